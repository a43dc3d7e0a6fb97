#include <engine/GlContext.h>

#include <epoxy/gl.h>

namespace engine {

namespace {
std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "";
}
} // namespace

std::string GlContext::renderer() const {
    return glString(GL_RENDERER);
}
std::string GlContext::version() const {
    return glString(GL_VERSION);
}

bool GlContext::isSoftwareRenderer() const {
    const std::string name = renderer();
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
           name.find("swrast") != std::string::npos;
}

} // namespace engine
