#include "SplitRenderer.h"

#include <algorithm>
#include <cmath>

namespace sandbox {

struct SplitRenderer::Side {
    Side()
        : shadows(static_cast<shadows::ShadowModule&>(
              engine.addModule(std::make_unique<shadows::ShadowModule>()))),
          scissor(static_cast<ScissorModule&>(engine.addModule(std::make_unique<ScissorModule>()))) {}

    SideStats render(const engine::Scene& scene, engine::EntityId camera, const engine::FrameTarget& target,
                     const shadows::ShadowSettings& settings, int left, int right) {
        shadows.setSettings(settings);
        scissor.setRectangle({left, 0}, {right - left, target.size.y});
        SideStats stats;
        stats.frame = engine.renderFrame(scene, camera, target);
        stats.shadows = shadows.stats();
        return stats;
    }

    engine::Engine engine;
    shadows::ShadowModule& shadows;
    ScissorModule& scissor;
};

SplitRenderer::SplitRenderer() : a_(std::make_unique<Side>()), b_(std::make_unique<Side>()) {}

SplitRenderer::~SplitRenderer() = default;

FrameReport SplitRenderer::render(const engine::Scene& scene, engine::EntityId camera,
                                  const engine::FrameTarget& target, const shadows::ShadowSettings& a,
                                  const std::optional<shadows::ShadowSettings>& b, float split) {
    const int width = target.size.x;
    if (!b) {
        return {a_->render(scene, camera, target, a, 0, width), std::nullopt};
    }
    const int splitX = splitColumn(split, width);
    FrameReport report;
    report.a = a_->render(scene, camera, target, a, 0, splitX);
    report.b = b_->render(scene, camera, target, *b, splitX, width);
    return report;
}

int SplitRenderer::splitColumn(float split, int width) {
    return std::clamp(static_cast<int>(std::lround(static_cast<double>(split) * width)), 0, width);
}

void SplitRenderer::setPassTiming(std::optional<engine::TimingMethod> method) {
    a_->engine.setPassTiming(method);
    b_->engine.setPassTiming(method);
}

} // namespace sandbox
