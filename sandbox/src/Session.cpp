#include "Session.h"

namespace sandbox {

Session::Session(SceneCatalog catalog, SandboxSettings settings)
    : catalog_(std::move(catalog)), settings_(std::move(settings)),
      scene_(std::make_unique<SandboxScene>(catalog_.resolve(settings_.scene), settings_.level)),
      renderer_(std::make_unique<SplitRenderer>()) {}

void Session::loadScene(const std::string& scene, int level) {
    auto loaded = std::make_unique<SandboxScene>(catalog_.resolve(scene), level);
    if (scene != settings_.scene) {
        settings_.camera.reset();
        settings_.light.reset();
    }
    settings_.scene = scene;
    settings_.level = level;
    // The renderers free the old scene's GPU meshes at their next frame, once nothing references them.
    scene_ = std::move(loaded);
}

FrameReport Session::render(const engine::FrameTarget& target) {
    scene_->apply(settings_.light, settings_.camera);
    return renderer_->render(scene_->scene(), scene_->camera(), target, settings_.a,
                             settings_.compare ? std::optional(settings_.b) : std::nullopt, settings_.split);
}

void Session::setPassTiming(std::optional<engine::TimingMethod> method) {
    timing_ = method;
    renderer_->setPassTiming(method);
}

} // namespace sandbox
