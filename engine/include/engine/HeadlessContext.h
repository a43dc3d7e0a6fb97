#pragma once

#include <engine/GlContext.h>

namespace engine {

/// @brief OpenGL 4.5 core context on EGL's surfaceless platform (Mesa): no window, no display server.
///
/// Render into a Framebuffer (see RenderTarget). Throws ContextError with a remedy when EGL, the
/// surfaceless platform or a 4.5 core context is unavailable.
class HeadlessContext final : public GlContext {
public:
    explicit HeadlessContext(const ContextOptions& options = {});
    ~HeadlessContext() override;
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    void makeCurrent() override;
    void swapBuffers() override {}
    [[nodiscard]] glm::ivec2 framebufferSize() const override { return {0, 0}; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
};

} // namespace engine
