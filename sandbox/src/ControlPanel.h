#pragma once

#include <utility>

#include "Session.h"

#include <shadows/ShadowSettings.h>

#include <engine/PassTimer.h>

#include <filesystem>
#include <string>

namespace sandbox {

/// @brief The sandbox's Dear ImGui panels: scene, light, camera, both sides' shadow settings (controls drawn
/// from ParameterTable), settings files, screenshots, and the per-pass timing overlay.
class ControlPanel {
public:
    /// @param settingsPath initial path of the settings save/load field
    /// @param screenshotPath initial path of the screenshot field
    /// @param timing the method the "time passes" switch turns on (engine::PassTimer::methodFor the context)
    /// @param renderer GL_RENDERER, shown beside the timings
    ControlPanel(std::filesystem::path settingsPath, std::filesystem::path screenshotPath,
                 engine::TimingMethod timing, std::string renderer);

    /// @brief Draws the panels editing `session`. Returns true when a screenshot was asked for.
    bool draw(Session& session);

    /// @brief The timings overlay with both sides' smoothed pass times and the timing method.
    void drawTimings(const Session& session, const FrameReport& last);

    [[nodiscard]] std::filesystem::path screenshotPath() const { return screenshotPath_; }
    /// @brief Shows `message` under the panel (red when `error`).
    void setStatus(std::string message, bool error);
    /// @brief True once after the "Ground truth" button was pressed.
    bool takeGroundTruthRequest() { return std::exchange(groundTruthRequested_, false); }

private:
    void drawScene(Session& session);
    void drawLightAndCamera(Session& session);
    void drawView(Session& session);
    void drawSide(const char* id, shadows::ShadowSettings& settings);
    void drawFiles(Session& session);

    std::string settingsPath_;
    std::string screenshotPath_;
    std::string scenePath_;
    engine::TimingMethod timing_;
    std::string renderer_;
    std::string status_;
    bool statusIsError_ = false;
    bool groundTruthRequested_ = false;
    /// Exponential moving averages of the pass times (shadow, lighting) of sides A and B, milliseconds.
    double smoothed_[2][2] = {{-1.0, -1.0}, {-1.0, -1.0}};
};

} // namespace sandbox
