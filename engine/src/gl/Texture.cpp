#include <engine/gl/Texture.h>

namespace engine::gl {

static GLuint createTexture() {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &name);
    return name;
}

Texture::Texture(GLenum internalFormat, glm::ivec2 size, GLsizei levels)
    : object_(createTexture()), size_(size), format_(internalFormat) {
    glTextureStorage2D(object_.id(), levels, internalFormat, size.x, size.y);
    setFilter(GL_NEAREST, GL_NEAREST);
    glTextureParameteri(object_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(object_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
    glTextureParameteri(object_.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(object_.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::bind(GLuint unit) const {
    glBindTextureUnit(unit, object_.id());
}

} // namespace engine::gl
