#include <shadows/LightFrustum.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace shadows;

namespace {

Aabb box(glm::vec3 min, glm::vec3 max) {
    Aabb b;
    b.extend(min);
    b.extend(max);
    return b;
}

glm::vec3 toShadow(const LightProjection& p, const glm::vec3& world) {
    const glm::vec4 s = p.worldToShadow * glm::vec4(world, 1.0f);
    return glm::vec3(s) / s.w;
}

glm::mat4 cameraLookingAt(glm::vec3 eye, glm::vec3 target, float far = 100.0f) {
    return glm::perspective(0.8f, 4.0f / 3.0f, 0.1f, far) * glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

const glm::vec3 kSun = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));

} // namespace

TEST(LightFrustumTest, DirectionalMapCoversVisibleReceiversAndCastersBeyondTheView) {
    const std::vector<Aabb> boxes = {box({-5, -0.1f, -5}, {5, 0, 5}), // ground in view
                                     box({-1, 0, -1}, {1, 2, 1}),     // box in view
                                     box({3, 8, 2}, {4, 9, 3})};      // caster high above, outside the view
    const glm::mat4 camera = cameraLookingAt({0, 3, 8}, {0, 0, 0});
    const LightProjection p = fitDirectionalLight(kSun, camera, boxes, 1024, true);
    ASSERT_TRUE(p.valid);
    for (const Aabb& b : boxes) {
        for (const glm::vec3& corner : b.corners()) {
            const glm::vec3 s = toShadow(p, corner);
            EXPECT_GE(s.z, 0.0f); // nothing overlapping the map is clipped by the near plane
            EXPECT_LE(s.z, 1.0f);
        }
    }
    for (const glm::vec3& corner : boxes[1].corners()) {
        const glm::vec3 s = toShadow(p, corner);
        EXPECT_TRUE(s.x >= 0.0f && s.x <= 1.0f && s.y >= 0.0f && s.y <= 1.0f);
    }
}

TEST(LightFrustumTest, DirectionalMapIsClippedToTheCameraView) {
    // A huge ground plane: the map covers the visible part, not the whole plane.
    const std::vector<Aabb> boxes = {box({-1000, -0.1f, -1000}, {1000, 0, 1000})};
    const glm::mat4 camera = cameraLookingAt({0, 2, 4}, {0, 0, 0}, 20.0f);
    const LightProjection p = fitDirectionalLight(kSun, camera, boxes, 1024, true);
    ASSERT_TRUE(p.valid);
    EXPECT_LT(p.texelScale * 1024.0f, 60.0f);
}

TEST(LightFrustumTest, NothingVisibleMeansNoMap) {
    const std::vector<Aabb> boxes = {box({100, 0, 100}, {101, 1, 101})};
    EXPECT_FALSE(
        fitDirectionalLight(kSun, cameraLookingAt({0, 2, 4}, {0, 0, 0}, 20.0f), boxes, 512, true).valid);
    EXPECT_FALSE(fitDirectionalLight(kSun, cameraLookingAt({0, 2, 4}, {0, 0, 0}), {}, 512, true).valid);
}

TEST(LightFrustumTest, SnappedFrustumMovesInWholeTexels) {
    const std::vector<Aabb> boxes = {box({-5, -0.1f, -5}, {5, 0, 5}), box({-1, 0, -1}, {1, 2, 1})};
    const LightProjection a =
        fitDirectionalLight(kSun, cameraLookingAt({0, 3, 8}, {0, 0, 0}), boxes, 1024, true);
    const LightProjection b =
        fitDirectionalLight(kSun, cameraLookingAt({0.013f, 3, 8}, {0.013f, 0, 0}), boxes, 1024, true);
    ASSERT_TRUE(a.valid && b.valid);
    ASSERT_FLOAT_EQ(a.texelScale, b.texelScale); // extent quantised: unchanged by a small camera move
    // The same world point lands on the same sub-texel position in both maps: shadows do not shimmer.
    const glm::vec3 point(0.37f, 0.0f, -0.21f);
    const glm::vec2 ta = glm::vec2(toShadow(a, point)) * 1024.0f;
    const glm::vec2 tb = glm::vec2(toShadow(b, point)) * 1024.0f;
    EXPECT_NEAR(std::fmod(ta.x - tb.x + 1000.5f, 1.0f), 0.5f, 1e-2f);
    EXPECT_NEAR(std::fmod(ta.y - tb.y + 1000.5f, 1.0f), 0.5f, 1e-2f);
}

TEST(LightFrustumTest, SpotFrustumBoundsBoxesInFrontOfTheLight) {
    const glm::vec3 position(0, 6, 0);
    const std::vector<Aabb> boxes = {box({-3, -0.1f, -3}, {3, 0, 3}), box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}),
                                     box({-1, 10, -1}, {1, 11, 1})}; // behind the light: ignored
    const LightProjection p = fitSpotLight(position, {0, -1, 0}, 0.6f, 0.0f, boxes, 512);
    ASSERT_TRUE(p.valid);
    EXPECT_TRUE(p.perspective);
    for (const glm::vec3& corner : boxes[1].corners()) {
        const glm::vec3 s = toShadow(p, corner);
        EXPECT_GE(s.z, 0.0f);
        EXPECT_LE(s.z, 1.0f);
        EXPECT_TRUE(s.x >= 0.0f && s.x <= 1.0f && s.y >= 0.0f && s.y <= 1.0f);
    }
    // The light's axis maps to the centre of the map.
    const glm::vec3 centre = toShadow(p, {0, 0, 0});
    EXPECT_NEAR(centre.x, 0.5f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.5f, 1e-5f);
}

TEST(LightFrustumTest, LightStraightDownHasAStableBasis) {
    const std::vector<Aabb> boxes = {box({-1, 0, -1}, {1, 1, 1})};
    const LightProjection p =
        fitDirectionalLight({0, -1, 0}, cameraLookingAt({0, 3, 5}, {0, 0, 0}), boxes, 256, true);
    ASSERT_TRUE(p.valid);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            EXPECT_TRUE(std::isfinite(p.worldToShadow[c][r]));
        }
    }
}
