#include "GroundTruthOverlay.h"

#include <shadowbench/ShadowBench.h>

#include <cstdio>

namespace sandbox {

std::string GroundTruthView::summary() const {
    char line[256];
    std::snprintf(line, sizeof line,
                  "acne %.2f %% of %zu lit, leak %.2f %% of %zu shadowed, darkening %.4f, MAE %.4f",
                  100.0 * metrics.acneRate, metrics.lit, 100.0 * metrics.leakRate, metrics.shadowed,
                  metrics.darkening, metrics.meanAbsoluteError);
    return line;
}

GroundTruthView measureGroundTruth(const Session& session, const engine::Image& shaded) {
    shadowbench::BenchOptions options;
    options.size = shaded.size;
    const shadowbench::BenchScene scene(session.settings().scene, session.scene().scene(),
                                        session.scene().camera(), options);
    // Only the accuracy path of the bench runs, which needs no timing method.
    const shadowbench::ShadowBench bench(engine::TimingMethod::FinishAndSteadyClock, options);
    const shadowbench::Accuracy accuracy = bench.measure(scene, session.settings().a);

    GroundTruthView view;
    view.metrics = accuracy.metrics;
    view.settings = session.settings();
    view.size = shaded.size;
    view.overlay = shaded;
    for (std::size_t i = 0; i < accuracy.classes.size(); ++i) {
        glm::vec3 tint(-1.0f);
        const bool acne =
            accuracy.classes[i] == shadowbench::PixelClass::Lit && accuracy.visibility[i] < 0.5f;
        const bool leak =
            accuracy.classes[i] == shadowbench::PixelClass::Shadowed && accuracy.visibility[i] > 0.5f;
        if (acne) {
            tint = {255, 30, 30};
        } else if (leak) {
            tint = {40, 90, 255};
        } else if (accuracy.classes[i] == shadowbench::PixelClass::Band) {
            tint = {200, 190, 60};
        }
        if (tint.x >= 0.0f) {
            for (int c = 0; c < 3; ++c) {
                auto& channel = view.overlay.pixels[4 * i + static_cast<std::size_t>(c)];
                channel = static_cast<std::uint8_t>(0.35f * static_cast<float>(channel) + 0.65f * tint[c]);
            }
        }
    }
    return view;
}

} // namespace sandbox
