#pragma once

#include <engine/GlContext.h>

#include <string>

struct GLFWwindow;

namespace engine {

/// @brief A GLFW window with an OpenGL 4.5 core context.
///
/// Throws ContextError when there is no display (suggesting headless mode) or no 4.5 core support.
class WindowContext final : public GlContext {
public:
    WindowContext(const std::string& title, glm::ivec2 size, const ContextOptions& options = {});
    ~WindowContext() override;
    WindowContext(const WindowContext&) = delete;
    WindowContext& operator=(const WindowContext&) = delete;

    void makeCurrent() override;
    void swapBuffers() override;
    [[nodiscard]] glm::ivec2 framebufferSize() const override;

    /// @brief Processes window events; returns false once the user asked to close the window.
    bool pollEvents();
    [[nodiscard]] GLFWwindow* window() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace engine
