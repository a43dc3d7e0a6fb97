#pragma once

#include <engine/Image.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Texture.h>

namespace engine {

/// @brief Offscreen colour (sRGB8_A8) + depth (D24) target for headless rendering and readback.
class RenderTarget {
public:
    explicit RenderTarget(glm::ivec2 size);

    void bind() const;
    /// @brief Reads the colour attachment back (sRGB-encoded bytes), rows top to bottom.
    [[nodiscard]] Image readPixels() const;

    [[nodiscard]] glm::ivec2 size() const { return size_; }
    [[nodiscard]] const gl::Framebuffer& framebuffer() const { return framebuffer_; }

private:
    glm::ivec2 size_;
    gl::Texture color_;
    gl::Texture depth_;
    gl::Framebuffer framebuffer_;
};

} // namespace engine
