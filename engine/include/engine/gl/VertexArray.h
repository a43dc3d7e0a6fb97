#pragma once

#include <engine/gl/Buffer.h>
#include <engine/gl/GlObject.h>

namespace engine::gl {

/// @brief Vertex array object configured with DSA calls.
class VertexArray {
public:
    VertexArray();

    /// @brief Binds `buffer` to binding point `binding` with the given stride.
    void setVertexBuffer(GLuint binding, const Buffer& buffer, GLsizei stride, GLintptr offset = 0);
    /// @brief Declares float attribute `location` with `components` floats at `offset` of `binding`.
    void setFloatAttribute(GLuint location, GLuint binding, GLint components, GLuint offset);
    void setIndexBuffer(const Buffer& buffer);
    void bind() const;

    [[nodiscard]] GLuint id() const { return object_.id(); }

private:
    GlObject<detail::deleteVertexArray> object_;
};

} // namespace engine::gl
