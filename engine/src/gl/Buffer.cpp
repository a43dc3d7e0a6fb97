#include <engine/gl/Buffer.h>

namespace engine::gl {

static GLuint createBuffer() {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    return name;
}

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags)
    : object_(createBuffer()), size_(bytes) {
    // Zero-sized storage is an error in GL; keep one byte so empty meshes stay valid objects.
    glNamedBufferStorage(object_.id(), static_cast<GLsizeiptr>(bytes == 0 ? 1 : bytes),
                         bytes ? data : nullptr, flags);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    glNamedBufferSubData(object_.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

} // namespace engine::gl
