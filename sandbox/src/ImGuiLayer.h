#pragma once

struct GLFWwindow;

namespace sandbox {

/// @brief Dear ImGui bound to a GLFW window and its OpenGL 4.5 context (the GLFW and OpenGL3 backends).
///
/// Create it after the window's context is current and destroy it before the window.
class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    /// @brief Starts a UI frame (after polling events, before any ImGui call).
    void beginFrame();
    /// @brief Draws the frame's UI into the bound framebuffer, as sRGB-encoded colours.
    void render();
};

} // namespace sandbox
