#include <engine/GlContext.h>

#include <epoxy/gl.h>

#include <malloc.h>

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

bool isSoftwareRendererName(std::string_view renderer) {
    return renderer.find("llvmpipe") != std::string_view::npos ||
           renderer.find("softpipe") != std::string_view::npos ||
           renderer.find("swrast") != std::string_view::npos;
}

bool raiseAllocatorThresholds() {
    // llvmpipe allocates per-draw vertex buffers and per-frame bin storage of a few MiB. glibc serves blocks
    // over its mmap threshold with fresh mappings and gives the top of the heap back beyond its trim
    // threshold, so each frame would fault the same pages in again. 32 MiB is the largest mmap threshold
    // glibc accepts on 64-bit; setting either value also stops glibc's dynamic adjustment.
    constexpr int kMmapThreshold = 32 << 20;
    constexpr int kTrimThreshold = 512 << 20;
    return mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 && mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
}

bool GlContext::isSoftwareRenderer() const {
    return isSoftwareRendererName(renderer());
}

void GlContext::applyAllocatorPolicy(const ContextOptions& options) {
    if (!options.tuneAllocatorForSoftwareRenderer || !isSoftwareRenderer()) {
        return;
    }
    allocatorTuned_ = raiseAllocatorThresholds();
}

} // namespace engine
