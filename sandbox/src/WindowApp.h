#pragma once

#include "CommandLine.h"
#include "SceneCatalog.h"

#include <engine/Image.h>

#include <glm/vec2.hpp>

namespace sandbox {

class Session;

/// @brief The interactive sandbox: a GLFW window showing the split-screen view with Dear ImGui controls.
///
/// The view is rendered exactly as --headless renders it (Session into an sRGB RenderTarget) and copied to
/// the window unchanged; screenshots read that copy back from the window before the UI is drawn over it, so
/// a screenshot equals the headless image of the same settings.
class WindowApp {
public:
    WindowApp(CommandLine line, SceneCatalog catalog);

    /// @brief Runs until the window closes or --frames frames were shown (writing --screenshot after the
    /// last). Returns the exit status; throws engine::ContextError when no window can be opened.
    int run();

private:
    enum class Drag { None, Orbit, Pan, Divider };

    /// Mouse: drag the divider, orbit, pan and zoom (when the UI does not want the mouse).
    void handleMouse(Session& session);
    /// Divider line and side labels over the view.
    static void drawDivider(const Session& session);
    /// Reads the window's back buffer (rows top to bottom).
    static engine::Image readWindow(glm::ivec2 size);

    CommandLine line_;
    SceneCatalog catalog_;
    Drag drag_ = Drag::None;
};

} // namespace sandbox
