#pragma once

#include <engine/gl/GlObject.h>

#include <cstddef>
#include <span>

namespace engine::gl {

/// @brief Immutable-storage GL buffer (glNamedBufferStorage); dynamic buffers can be updated with update().
class Buffer {
public:
    Buffer() = default;
    /// @brief Creates storage of `bytes` bytes, optionally initialised from `data`.
    Buffer(std::size_t bytes, const void* data, GLbitfield flags = 0);

    template <typename T>
    static Buffer fromSpan(std::span<const T> items, GLbitfield flags = 0) {
        return Buffer(items.size_bytes(), items.data(), flags);
    }

    /// @brief Overwrites `bytes` at `offset`; requires GL_DYNAMIC_STORAGE_BIT at creation.
    void update(std::size_t offset, std::size_t bytes, const void* data);

    [[nodiscard]] GLuint id() const { return object_.id(); }
    [[nodiscard]] std::size_t size() const { return size_; }

private:
    GlObject<detail::deleteBuffer> object_;
    std::size_t size_ = 0;
};

} // namespace engine::gl
