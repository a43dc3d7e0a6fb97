#pragma once

#include <engine/gl/GlObject.h>

#include <glm/vec2.hpp>

namespace engine::gl {

/// @brief Immutable-storage 2D texture (glTextureStorage2D).
class Texture {
public:
    Texture() = default;
    /// @brief Allocates `levels` mip levels of `internalFormat` at `size`.
    Texture(GLenum internalFormat, glm::ivec2 size, GLsizei levels = 1);

    /// @brief Sets min/mag filter and clamp-to-edge wrapping.
    void setFilter(GLenum minFilter, GLenum magFilter);
    void bind(GLuint unit) const;

    [[nodiscard]] GLuint id() const { return object_.id(); }
    [[nodiscard]] glm::ivec2 size() const { return size_; }
    [[nodiscard]] GLenum internalFormat() const { return format_; }

private:
    GlObject<detail::deleteTexture> object_;
    glm::ivec2 size_{0};
    GLenum format_ = 0;
};

} // namespace engine::gl
