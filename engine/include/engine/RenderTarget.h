#pragma once

#include <engine/Image.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Texture.h>

namespace engine {

/// @brief Colour formats of a RenderTarget.
enum class ColorFormat {
    Srgb8,   ///< 8-bit sRGB-encoded colour: images for people
    Rgba32F, ///< linear 32-bit float: measurements (visibility, positions), no encoding
};

/// @brief Offscreen colour + depth (D24) target for headless rendering and readback.
class RenderTarget {
public:
    explicit RenderTarget(glm::ivec2 size, ColorFormat format = ColorFormat::Srgb8);

    void bind() const;
    /// @brief Reads the colour attachment back as 8-bit RGBA, rows top to bottom (Srgb8 targets).
    [[nodiscard]] Image readPixels() const;
    /// @brief Reads the colour attachment back as linear floats, 4 per pixel, rows top to bottom.
    [[nodiscard]] std::vector<float> readPixelsFloat() const;

    [[nodiscard]] glm::ivec2 size() const { return size_; }
    [[nodiscard]] ColorFormat format() const { return format_; }
    [[nodiscard]] const gl::Framebuffer& framebuffer() const { return framebuffer_; }

private:
    glm::ivec2 size_;
    ColorFormat format_;
    gl::Texture color_;
    gl::Texture depth_;
    gl::Framebuffer framebuffer_;
};

} // namespace engine
