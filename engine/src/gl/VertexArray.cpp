#include <engine/gl/VertexArray.h>

namespace engine::gl {

static GLuint createVertexArray() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return name;
}

VertexArray::VertexArray() : object_(createVertexArray()) {}

void VertexArray::setVertexBuffer(GLuint binding, const Buffer& buffer, GLsizei stride, GLintptr offset) {
    glVertexArrayVertexBuffer(object_.id(), binding, buffer.id(), offset, stride);
}

void VertexArray::setFloatAttribute(GLuint location, GLuint binding, GLint components, GLuint offset) {
    glEnableVertexArrayAttrib(object_.id(), location);
    glVertexArrayAttribFormat(object_.id(), location, components, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(object_.id(), location, binding);
}

void VertexArray::setIndexBuffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(object_.id(), buffer.id());
}

void VertexArray::bind() const {
    glBindVertexArray(object_.id());
}

} // namespace engine::gl
