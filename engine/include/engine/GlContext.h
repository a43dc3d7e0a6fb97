#pragma once

#include <glm/vec2.hpp>

#include <string>
#include <string_view>

namespace engine {

/// @brief True for the GL_RENDERER string of a CPU rasteriser (llvmpipe, softpipe, swrast).
[[nodiscard]] bool isSoftwareRendererName(std::string_view renderer);

/// @brief Raises glibc's mmap and trim thresholds for the whole process (mallopt; ContextOptions::
/// tuneAllocatorForSoftwareRenderer says why), as a context on a CPU rasteriser does at start-up. For
/// programs whose contexts are not ours (the OpenSceneGraph peer), so that both renderers run on the same
/// allocator. Returns whether both thresholds took.
bool raiseAllocatorThresholds();

/// @brief Options shared by every context kind.
struct ContextOptions {
    /// Request a KHR_debug context so GL errors surface as GlError/log lines. Default true.
    bool debug = true;
    /// On a CPU rasteriser, raise glibc's mmap and trim thresholds once at start-up (mallopt), so the
    /// driver's large per-draw and per-frame buffers are reused instead of being mapped and unmapped every
    /// frame (a third of a frame in page faults on a 121k-triangle model, docs/RESULTS.md). Process-wide; not
    /// applied on GPUs. Default true.
    bool tuneAllocatorForSoftwareRenderer = true;
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
    /// @brief Whether start-up changed the allocator's thresholds (ContextOptions).
    [[nodiscard]] bool allocatorTuned() const { return allocatorTuned_; }

protected:
    /// @brief Applies ContextOptions::tuneAllocatorForSoftwareRenderer; call with the context current.
    void applyAllocatorPolicy(const ContextOptions& options);

private:
    bool allocatorTuned_ = false;
};

} // namespace engine
