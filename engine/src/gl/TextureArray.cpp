#include <engine/gl/TextureArray.h>

namespace engine::gl {

static GLuint createTextureArray() {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &name);
    return name;
}

TextureArray::TextureArray(GLenum internalFormat, glm::ivec2 size, GLsizei layers, GLsizei levels)
    : object_(createTextureArray()), size_(size), layers_(layers), format_(internalFormat) {
    glTextureStorage3D(object_.id(), levels, internalFormat, size.x, size.y, layers);
    glTextureParameteri(object_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(object_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(object_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(object_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

} // namespace engine::gl
