#include <engine/Error.h>
#include <engine/GlDebug.h>

#include <epoxy/gl.h>

#include <iostream>
#include <mutex>
#include <utility>

namespace engine {

namespace {
std::mutex errorsMutex;
std::vector<std::string> recordedErrors;

void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum severity, GLsizei length,
                               const GLchar* message, const void* /*user*/) {
    const std::string text(message, length > 0 ? static_cast<std::size_t>(length)
                                               : std::char_traits<char>::length(message));
    if (type == GL_DEBUG_TYPE_ERROR) {
        std::lock_guard lock(errorsMutex);
        recordedErrors.push_back(text);
    } else if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM) {
        std::cerr << "[gl] " << text << '\n';
    }
}
} // namespace

void GlDebug::install() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) {
        return;
    }
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
}

std::vector<std::string> GlDebug::takeErrors() {
    std::lock_guard lock(errorsMutex);
    return std::exchange(recordedErrors, {});
}

void GlDebug::check(const std::string& where) {
    const std::vector<std::string> errors = takeErrors();
    if (errors.empty()) {
        return;
    }
    std::string message = where + ": OpenGL reported " + std::to_string(errors.size()) + " error(s):";
    for (const std::string& error : errors) {
        message += "\n  " + error;
    }
    throw GlError(message);
}

} // namespace engine
