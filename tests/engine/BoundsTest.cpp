// Aabb and intersectsClipVolume: a box is culled only when it lies wholly outside one clip plane.
#include <engine/Bounds.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <limits>

namespace {

engine::Aabb box(glm::vec3 min, glm::vec3 max) {
    engine::Aabb b;
    b.extend(min);
    b.extend(max);
    return b;
}

// A camera at the origin looking down -Z, 90° field of view, near 1, far 100.
const glm::mat4 kViewProjection = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 100.0f);

TEST(BoundsTest, ExtendAndTransform) {
    engine::Aabb b;
    EXPECT_TRUE(b.empty());
    b.extend(glm::vec3(1, 2, 3));
    b.extend(box({-1, 0, 0}, {0, 5, 1}));
    b.extend(engine::Aabb{}); // an empty box adds nothing
    EXPECT_EQ(b.min, glm::vec3(-1, 0, 0));
    EXPECT_EQ(b.max, glm::vec3(1, 5, 3));
    const engine::Aabb moved = b.transformed(glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)));
    EXPECT_EQ(moved.min, glm::vec3(9, 0, 0));
    EXPECT_TRUE(engine::Aabb{}.transformed(glm::mat4(1.0f)).empty());
}

TEST(BoundsTest, BoxesInsideOrStraddlingAreKept) {
    EXPECT_TRUE(engine::intersectsClipVolume(box({-1, -1, -11}, {1, 1, -9}), kViewProjection));
    EXPECT_TRUE(engine::intersectsClipVolume(box({-100, -1, -11}, {100, 1, -9}), kViewProjection));
    // Straddles the near plane and the camera itself.
    EXPECT_TRUE(engine::intersectsClipVolume(box({-1, -1, -2}, {1, 1, 2}), kViewProjection));
    // Huge box around everything.
    EXPECT_TRUE(engine::intersectsClipVolume(box(glm::vec3(-1e6f), glm::vec3(1e6f)), kViewProjection));
}

TEST(BoundsTest, BoxesOutsideOnePlaneAreCulled) {
    EXPECT_FALSE(engine::intersectsClipVolume(box({-1, -1, 1}, {1, 1, 5}), kViewProjection)); // behind
    EXPECT_FALSE(
        engine::intersectsClipVolume(box({-1, -1, -300}, {1, 1, -200}), kViewProjection)); // beyond far
    EXPECT_FALSE(engine::intersectsClipVolume(box({20, -1, -11}, {30, 1, -9}), kViewProjection));   // right
    EXPECT_FALSE(engine::intersectsClipVolume(box({-1, -30, -11}, {1, -20, -9}), kViewProjection)); // below
    EXPECT_FALSE(engine::intersectsClipVolume(engine::Aabb{}, kViewProjection));
}

TEST(BoundsTest, NonFiniteBoxesAreNeverCulled) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    engine::Aabb b = box({20, -1, -11}, {30, 1, -9});
    b.max.x = nan;
    EXPECT_TRUE(engine::intersectsClipVolume(b, kViewProjection));
}

} // namespace
