#pragma once

#include <glm/vec2.hpp>

#include <string>

namespace engine {

/// @brief Options shared by every context kind.
struct ContextOptions {
    /// Request a KHR_debug context so GL errors surface as GlError/log lines. Default true.
    bool debug = true;
};

/// @brief An OpenGL 4.5 core context; current on the creating thread after construction.
class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void makeCurrent() = 0;
    /// @brief Presents the default framebuffer (no-op for headless contexts).
    virtual void swapBuffers() = 0;
    /// @brief Size of the default framebuffer in pixels ({0,0} when there is none).
    [[nodiscard]] virtual glm::ivec2 framebufferSize() const = 0;

    /// @brief GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    [[nodiscard]] std::string renderer() const;
    /// @brief GL_VERSION string.
    [[nodiscard]] std::string version() const;
    /// @brief True for CPU rasterisers (llvmpipe, softpipe, swrast), whose timer queries time submission
    /// only.
    [[nodiscard]] bool isSoftwareRenderer() const;
};

} // namespace engine
