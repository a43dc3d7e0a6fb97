// engine::gl::liveObjectCounts: each wrapper kind counts the names it holds, moves hand them over uncounted,
// and the timer's queries are deleted with it.
#include "../GLTestContext.h"

#include <engine/PassTimer.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/Texture.h>

#include <gtest/gtest.h>

#include <optional>

TEST(LiveObjectCountGLTest, CountsCreationsAndDeletionsByKind) {
    glTestContext();
    const engine::gl::LiveObjectCounts before = engine::gl::liveObjectCounts();
    {
        engine::gl::Buffer buffer(16, nullptr);
        const engine::gl::Texture texture(GL_RGBA8, {4, 4});
        const engine::gl::LiveObjectCounts during = engine::gl::liveObjectCounts();
        EXPECT_EQ(during.buffers, before.buffers + 1);
        EXPECT_EQ(during.textures, before.textures + 1);
        EXPECT_EQ(during.total(), before.total() + 2);
        const engine::gl::Buffer moved = std::move(buffer);
        EXPECT_EQ(engine::gl::liveObjectCounts(), during);
    }
    EXPECT_EQ(engine::gl::liveObjectCounts(), before);
}

TEST(LiveObjectCountGLTest, TimerQueriesAreDeletedWithTheTimer) {
    glTestContext();
    const long before = engine::gl::liveObjectCounts().queries;
    std::optional<engine::PassTimer> timer(std::in_place, engine::TimingMethod::TimerQuery);
    timer->begin();
    EXPECT_GE(timer->end(), 0.0);
    EXPECT_EQ(engine::gl::liveObjectCounts().queries, before + 2);
    timer.reset();
    EXPECT_EQ(engine::gl::liveObjectCounts().queries, before);
}
