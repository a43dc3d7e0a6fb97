#include <engine/Error.h>
#include <engine/GlDebug.h>
#include <engine/WindowContext.h>

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>

#include <cstdlib>

namespace engine {

namespace {
std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}
} // namespace

WindowContext::WindowContext(const std::string& title, glm::ivec2 size, const ContextOptions& options) {
    if (!glfwInit()) {
        const char* display = std::getenv("DISPLAY");
        throw ContextError("window: cannot open a display (" + lastGlfwError() + "; DISPLAY=" +
                           (display ? display : "unset") + "). Run with --headless, or start Xvfb.");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string error = lastGlfwError();
        glfwTerminate();
        throw ContextError("window: cannot create an OpenGL 4.5 core window (" + error + ")");
    }
    makeCurrent();
    if (options.debug) {
        GlDebug::install();
    }
    applyAllocatorPolicy(options);
}

WindowContext::~WindowContext() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void WindowContext::makeCurrent() {
    glfwMakeContextCurrent(window_);
}
void WindowContext::swapBuffers() {
    glfwSwapBuffers(window_);
}

glm::ivec2 WindowContext::framebufferSize() const {
    glm::ivec2 size{0};
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

bool WindowContext::pollEvents() {
    glfwPollEvents();
    return !glfwWindowShouldClose(window_);
}

} // namespace engine
