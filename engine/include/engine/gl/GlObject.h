#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace engine::gl {

/// @brief Move-only owner of one GL object name; `Deleter` releases it.
template <void (*Deleter)(GLuint)>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint name) : name_(name) {}
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    ~GlObject() { reset(); }

    [[nodiscard]] GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

private:
    void reset() {
        if (name_ != 0) {
            Deleter(name_);
            name_ = 0;
        }
    }
    GLuint name_ = 0;
};

namespace detail {
inline void deleteBuffer(GLuint n) {
    glDeleteBuffers(1, &n);
}
inline void deleteTexture(GLuint n) {
    glDeleteTextures(1, &n);
}
inline void deleteFramebuffer(GLuint n) {
    glDeleteFramebuffers(1, &n);
}
inline void deleteVertexArray(GLuint n) {
    glDeleteVertexArrays(1, &n);
}
inline void deleteProgram(GLuint n) {
    glDeleteProgram(n);
}
inline void deleteShader(GLuint n) {
    glDeleteShader(n);
}
inline void deleteSampler(GLuint n) {
    glDeleteSamplers(1, &n);
}
} // namespace detail

} // namespace engine::gl
