// engine::gl::Buffer: storage, initial data and updates read back from the GL.
#include "../GLTestContext.h"

#include <engine/gl/Buffer.h>

#include <gtest/gtest.h>

#include <array>

TEST(BufferGLTest, HoldsItsInitialDataAndUpdates) {
    glTestContext();
    const std::array<int, 4> values{1, 2, 3, 4};
    engine::gl::Buffer buffer =
        engine::gl::Buffer::fromSpan(std::span<const int>(values), GL_DYNAMIC_STORAGE_BIT);
    ASSERT_NE(buffer.id(), 0u);
    EXPECT_EQ(buffer.size(), sizeof values);
    const int seven = 7;
    buffer.update(2 * sizeof(int), sizeof seven, &seven);
    std::array<int, 4> back{};
    glGetNamedBufferSubData(buffer.id(), 0, sizeof back, back.data());
    EXPECT_EQ(back, (std::array<int, 4>{1, 2, 7, 4}));
}

TEST(BufferGLTest, MovingHandsTheObjectOver) {
    glTestContext();
    engine::gl::Buffer first(16, nullptr);
    const GLuint id = first.id();
    engine::gl::Buffer second = std::move(first);
    EXPECT_EQ(second.id(), id);
    EXPECT_EQ(first.id(), 0u); // the moved-from handle is empty, so it deletes nothing
    EXPECT_TRUE(glIsBuffer(id));
}
