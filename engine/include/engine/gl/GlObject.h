#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace engine::gl {

/// @brief Move-only owner of one GL object name; `Deleter` releases it.
///
/// Counts the names of its kind it holds (live()), so long runs can check that GL objects do not
/// accumulate (liveObjectCounts(), `gs-sandbox --soak`). GL is driven from one thread, hence plain counters.
template <void (*Deleter)(GLuint)>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint name) : name_(name) { live_ += name != 0; }
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

    /// @brief Objects of this kind created through a GlObject and not yet deleted, process-wide.
    [[nodiscard]] static long live() { return live_; }

private:
    void reset() {
        if (name_ != 0) {
            Deleter(name_);
            name_ = 0;
            --live_;
        }
    }
    GLuint name_ = 0;
    inline static long live_ = 0;
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
inline void deleteQuery(GLuint n) {
    glDeleteQueries(1, &n);
}
} // namespace detail

/// @brief GL objects alive through GlObject, by kind (every object the engine and its modules create is held
/// by one).
struct LiveObjectCounts {
    long buffers = 0;
    long textures = 0;
    long framebuffers = 0;
    long vertexArrays = 0;
    long programs = 0;
    long shaders = 0;
    long samplers = 0;
    long queries = 0;

    [[nodiscard]] long total() const {
        return buffers + textures + framebuffers + vertexArrays + programs + shaders + samplers + queries;
    }
    bool operator==(const LiveObjectCounts&) const = default;
};

inline LiveObjectCounts liveObjectCounts() {
    return {GlObject<detail::deleteBuffer>::live(),      GlObject<detail::deleteTexture>::live(),
            GlObject<detail::deleteFramebuffer>::live(), GlObject<detail::deleteVertexArray>::live(),
            GlObject<detail::deleteProgram>::live(),     GlObject<detail::deleteShader>::live(),
            GlObject<detail::deleteSampler>::live(),     GlObject<detail::deleteQuery>::live()};
}

} // namespace engine::gl
