#include <shadowbench/ShadowBench.h>

#include <shadows/ShadowModule.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace shadowbench {

double ShadowBench::measureShimmer(const BenchScene& scene, const shadows::ShadowSettings& settings) const {
    engine::Engine engine;
    shadows::ShadowSettings visibilityOnly = settings;
    visibilityOnly.debugView = shadows::ShadowDebugView::Visibility;
    auto& module = static_cast<shadows::ShadowModule&>(
        engine.addModule(std::make_unique<shadows::ShadowModule>(visibilityOnly)));
    engine::RenderTarget target(options_.size, engine::ColorFormat::Rgba32F);
    const engine::Entity& camera = scene.scene_.entity(scene.camera_);
    const shadows::FitView start{glm::inverse(scene.scene_.worldMatrix(scene.camera_)),
                                 camera.camera->projectionMatrix(static_cast<float>(options_.size.x) /
                                                                 static_cast<float>(options_.size.y))};
    // An oblique direction, so the step has a component along both of the map's axes whatever the light.
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 0.37f, 0.61f));
    float step = 0.0f;
    std::vector<float> previous;
    std::size_t changes = 0;
    std::size_t compared = 0;
    for (int frame = 0; frame <= options_.shimmerFrames; ++frame) {
        shadows::FitView moved = start;
        moved.view = glm::translate(start.view, -direction * (step * static_cast<float>(frame)));
        module.setFitView(moved);
        engine.renderFrame(scene.scene_, scene.camera_, target);
        if (frame == 0) {
            const auto projection = module.lightProjection(scene.light_.index);
            if (!projection) {
                return 0.0; // no map, nothing to shimmer
            }
            // A third of a texel: a perspective map's texel at the camera's distance from the light.
            const glm::vec3 eye(scene.scene_.worldMatrix(scene.camera_)[3]);
            const float distance = projection->perspective ? glm::length(eye - scene.light_.position) : 1.0f;
            step = projection->texelScale * distance / 3.0f;
        }
        std::vector<float> pixels = target.readPixelsFloat();
        if (!previous.empty()) {
            for (std::size_t i = 0; i < scene.surfaces_.size(); ++i) {
                if (scene.surfaces_[i] == Surface::Receiver) {
                    changes += std::abs(pixels[4 * i] - previous[4 * i]) > 0.5f;
                    ++compared;
                }
            }
        }
        previous = std::move(pixels);
    }
    return compared ? static_cast<double>(changes) / static_cast<double>(compared) : 0.0;
}

} // namespace shadowbench
