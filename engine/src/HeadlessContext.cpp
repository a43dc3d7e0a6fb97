#include <engine/Error.h>
#include <engine/GlDebug.h>
#include <engine/HeadlessContext.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <string>

namespace engine {

namespace {
std::string eglErrorText() {
    char text[32];
    std::snprintf(text, sizeof text, "EGL error 0x%04X", eglGetError());
    return text;
}
constexpr const char* kRemedy =
    " (on Debian install libegl-mesa0 and libgl1-mesa-dri; Mesa's llvmpipe needs no GPU)";
} // namespace

HeadlessContext::HeadlessContext(const ContextOptions& options) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        throw ContextError(
            std::string("headless context: EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)") +
            kRemedy);
    }
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) {
        throw ContextError(
            "headless context: no EGL display for the surfaceless platform: " + eglErrorText() + kRemedy);
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        throw ContextError("headless context: eglInitialize failed: " + eglErrorText() + kRemedy);
    }
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        throw ContextError("headless context: EGL cannot bind desktop OpenGL: " + eglErrorText());
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG,
                                 options.debug ? EGL_TRUE : EGL_FALSE,
                                 EGL_NONE};
    // EGL_KHR_no_config_context: a surfaceless context needs no framebuffer configuration.
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        const std::string error = eglErrorText();
        eglTerminate(display);
        throw ContextError("headless context: the driver refused an OpenGL 4.5 core context: " + error +
                           kRemedy);
    }
    context_ = context;
    makeCurrent();
    if (options.debug) {
        GlDebug::install();
    }
    applyAllocatorPolicy(options);
}

HeadlessContext::~HeadlessContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

void HeadlessContext::makeCurrent() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
        throw ContextError("headless context: eglMakeCurrent failed: " + eglErrorText());
    }
}

} // namespace engine
