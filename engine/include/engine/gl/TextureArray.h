#pragma once

#include <engine/gl/GlObject.h>

#include <glm/vec2.hpp>

namespace engine::gl {

/// @brief Immutable-storage 2D array texture (glTextureStorage3D on GL_TEXTURE_2D_ARRAY): layers of one size
/// and format that a shader selects per fragment (a sampler array may only be indexed uniformly).
class TextureArray {
public:
    /// @brief Allocates `layers` layers of `levels` mip levels of `internalFormat` at `size`.
    TextureArray(GLenum internalFormat, glm::ivec2 size, GLsizei layers, GLsizei levels = 1);

    [[nodiscard]] GLuint id() const { return object_.id(); }
    [[nodiscard]] glm::ivec2 size() const { return size_; }
    [[nodiscard]] GLsizei layers() const { return layers_; }
    [[nodiscard]] GLenum internalFormat() const { return format_; }

private:
    GlObject<detail::deleteTexture> object_;
    glm::ivec2 size_{0};
    GLsizei layers_ = 0;
    GLenum format_ = 0;
};

} // namespace engine::gl
