#include "GroundTruthOverlay.h"

#include <shadowbench/ShadowBench.h>

#include <cstdio>

namespace sandbox {

namespace {

/// Tints the columns [left, right) of `overlay` where `accuracy` has acne, leaks or band pixels.
void tintErrors(engine::Image& overlay, const shadowbench::Accuracy& accuracy, int left, int right) {
    for (std::size_t i = 0; i < accuracy.classes.size(); ++i) {
        const int x = static_cast<int>(i % static_cast<std::size_t>(overlay.size.x));
        if (x < left || x >= right) {
            continue;
        }
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
                auto& channel = overlay.pixels[4 * i + static_cast<std::size_t>(c)];
                channel = static_cast<std::uint8_t>(0.35f * static_cast<float>(channel) + 0.65f * tint[c]);
            }
        }
    }
}

} // namespace

std::string GroundTruthView::summary(const shadowbench::ShadowMetrics& metrics) {
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
    const SandboxSettings& settings = session.settings();
    const shadowbench::Accuracy a = bench.measure(scene, settings.a);

    GroundTruthView view;
    view.a = a.metrics;
    view.settings = settings;
    view.size = shaded.size;
    view.overlay = shaded;
    if (!settings.compare) {
        tintErrors(view.overlay, a, 0, shaded.size.x);
        return view;
    }
    const shadowbench::Accuracy b = bench.measure(scene, settings.b);
    view.b = b.metrics;
    const int splitX = SplitRenderer::splitColumn(settings.split, shaded.size.x);
    tintErrors(view.overlay, a, 0, splitX);
    tintErrors(view.overlay, b, splitX, shaded.size.x);
    return view;
}

} // namespace sandbox
