#pragma once

#include "SandboxScene.h"
#include "SandboxSettings.h"
#include "SceneCatalog.h"
#include "SplitRenderer.h"

#include <memory>
#include <optional>

namespace sandbox {

/// @brief The sandbox's state and the one path from settings to pixels, shared by the window and --headless:
/// the loaded scene, the settings, and the SplitRenderer that draws them.
///
/// Needs a current OpenGL 4.5 core context for its whole life.
class Session {
public:
    /// @brief Loads `settings.scene` at `settings.level`. Throws SandboxError for an unknown scene,
    /// content::ContentError for a bad file.
    Session(SceneCatalog catalog, SandboxSettings settings);

    [[nodiscard]] const SceneCatalog& catalog() const { return catalog_; }
    [[nodiscard]] const SandboxScene& scene() const { return *scene_; }
    /// @brief The scene, to change what the settings do not hold (SandboxScene::setLightType); loadScene()
    /// replaces it.
    [[nodiscard]] SandboxScene& scene() { return *scene_; }
    /// @brief The settings; edit them freely, render() applies them. Change scene and level through
    /// loadScene().
    [[nodiscard]] SandboxSettings& settings() { return settings_; }
    [[nodiscard]] const SandboxSettings& settings() const { return settings_; }

    /// @brief Loads another scene or level. On success the settings name it (and a different scene drops
    /// the previous scene's camera and light direction); on failure the current scene stays and the error
    /// (SandboxError or content::ContentError) propagates.
    void loadScene(const std::string& scene, int level);

    /// @brief Applies the settings to the scene and draws one frame into `target`.
    FrameReport render(const engine::FrameTarget& target);

    /// @brief Times both sides' passes with `method`, or stops timing.
    void setPassTiming(std::optional<engine::TimingMethod> method);
    [[nodiscard]] std::optional<engine::TimingMethod> passTiming() const { return timing_; }

private:
    SceneCatalog catalog_;
    SandboxSettings settings_;
    std::unique_ptr<SandboxScene> scene_;
    std::unique_ptr<SplitRenderer> renderer_;
    std::optional<engine::TimingMethod> timing_;
};

} // namespace sandbox
