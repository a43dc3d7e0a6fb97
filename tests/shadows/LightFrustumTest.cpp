// CPU tests of the shadow map fits (LightFrustum): one directional map, spot maps, cascades and cube faces,
// and the cascade and cube-face selection of shaders/shadows/visibility.glsl (compiled as C++).
#include <shadows/LightFrustum.h>
#include <shadows/ShadowSettings.h>
#include <shadows/VisibilityMath.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace shadows;
namespace g = shadows::glsl;

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

TEST(LightFrustumTest, DirectionalMapCoversWhereShadowsCanFallNotTheWholeGroundInView) {
    // A model on a large ground plane (flat: it cannot shadow itself): the map covers the model's light-space
    // footprint, where its shadow and its self-shadowing fall, not the 40 m of ground in view.
    const std::vector<Aabb> boxes = {box({-20, 0, -20}, {20, 0, 20}),
                                     box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f})};
    const glm::mat4 camera = cameraLookingAt({0, 6, 12}, {0, 0, 0});
    const LightProjection p = fitDirectionalLight(kSun, camera, boxes, 1024, true);
    ASSERT_TRUE(p.valid);
    const Aabb footprint = boxes[1].transformed(p.view);
    const float footprintExtent =
        std::max(footprint.max.x - footprint.min.x, footprint.max.y - footprint.min.y);
    EXPECT_LE(p.texelScale * 1024.0f, footprintExtent * 1.2f); // 1/8-octave quantisation at most
    // The model and its shadow on the ground (its corners carried along the light onto y = 0) are mapped.
    for (const glm::vec3& corner : boxes[1].corners()) {
        const glm::vec3 onGround = corner + kSun * (-corner.y / kSun.y);
        for (const glm::vec3& point : {corner, onGround}) {
            const glm::vec3 s = toShadow(p, point);
            EXPECT_TRUE(s.x >= 0.0f && s.x <= 1.0f && s.y >= 0.0f && s.y <= 1.0f) << s.x << " " << s.y;
        }
    }
}

TEST(LightFrustumTest, DirectionalMapsLitBorderHoldsNothingThatCanBeShadowed) {
    // The map's outer band, where lookups are lit without reading it, is the margin beyond where shadows can
    // fall: several texels wide (8 less snapping), and no point of the model or of its shadow lies in it.
    const std::vector<Aabb> boxes = {box({-20, 0, -20}, {20, 0, 20}),
                                     box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f})};
    for (const bool snap : {false, true}) {
        const LightProjection p =
            fitDirectionalLight(kSun, cameraLookingAt({0, 6, 12}, {0, 0, 0}), boxes, 1024, snap);
        ASSERT_TRUE(p.valid);
        EXPECT_GE(p.litBorderTexels, snap ? 6.0f : 7.0f);
        const float inner = 0.5f - p.litBorderTexels / 1024.0f;
        for (const glm::vec3& corner : boxes[1].corners()) {
            const glm::vec3 onGround = corner + kSun * (-corner.y / kSun.y);
            for (const glm::vec3& point : {corner, onGround}) {
                const glm::vec3 s = toShadow(p, point);
                EXPECT_LE(std::max(std::abs(s.x - 0.5f), std::abs(s.y - 0.5f)), inner) << s.x << " " << s.y;
            }
        }
    }
    // Spot maps have no such band: their edges are the cone's, which shadows reach.
    const LightProjection spot = fitSpotLight({0, 5, 0}, {0, -1, 0}, 0.6f, 20.0f, boxes, 1024);
    ASSERT_TRUE(spot.valid);
    EXPECT_EQ(spot.litBorderTexels, 0.0f);
}

TEST(LightFrustumTest, DirectionalMapDepthSpansOnlyWhatLiesOverTheMap) {
    // An 800 m ground spans hundreds of metres of light-space depth under a low sun; over the model's
    // footprint it spans a few. Filtered moments need that short range to tell a small caster from the
    // ground.
    const glm::vec3 lowSun = glm::normalize(glm::vec3(-0.4f, -0.35f, -0.3f));
    const std::vector<Aabb> boxes = {box({-400, 0, -400}, {400, 0, 400}), box({-1, 0, -1}, {1, 2, 1})};
    const LightProjection p =
        fitDirectionalLight(lowSun, cameraLookingAt({0, 3, 8}, {0, 0, 0}, 1000.0f), boxes, 1024, true);
    ASSERT_TRUE(p.valid);
    const float depthRange = 2.0f / std::abs(p.projection[2][2]);
    const Aabb groundInLight = boxes[0].transformed(p.view);
    EXPECT_GT(groundInLight.max.z - groundInLight.min.z, 500.0f);
    EXPECT_LT(depthRange, 20.0f);
    // Still, everything over the map lies within its depth range.
    for (int i = -40; i <= 40; ++i) {
        for (int k = -40; k <= 40; ++k) {
            for (const float y : {0.0f, 1.0f, 2.0f}) {
                const glm::vec3 point(0.1f * static_cast<float>(i), y, 0.1f * static_cast<float>(k));
                const bool onSomething =
                    y == 0.0f || (std::abs(point.x) <= 1.0f && std::abs(point.z) <= 1.0f);
                const glm::vec3 s = toShadow(p, point);
                if (onSomething && s.x >= 0.0f && s.x <= 1.0f && s.y >= 0.0f && s.y <= 1.0f) {
                    EXPECT_TRUE(s.z >= 0.0f && s.z <= 1.0f) << point.x << " " << point.y << " " << point.z;
                }
            }
        }
    }
}

TEST(LightFrustumTest, AGroundNothingCanShadowNeedsNoMap) {
    // A flat ground alone cannot be shadowed.
    const Aabb ground = box({-20, 0, -20}, {20, 0, 20});
    const glm::mat4 camera = cameraLookingAt({0, 6, 12}, {0, 0, 0});
    EXPECT_FALSE(fitDirectionalLight(kSun, camera, std::vector<Aabb>{ground}, 1024, true).valid);
    // A ground with relief (not flat) can shadow itself.
    EXPECT_TRUE(
        fitDirectionalLight(kSun, camera, std::vector<Aabb>{box({-20, 0, -20}, {20, 0.5f, 20})}, 1024, true)
            .valid);
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

// ---- Cascades and cube faces ----

namespace {

FitView camera(glm::vec3 eye, glm::vec3 target, float near = 0.3f, float far = 500.0f) {
    return {glm::lookAt(eye, target, glm::vec3(0, 1, 0)), glm::perspective(0.8f, 16.0f / 9.0f, near, far)};
}

const glm::vec3 kLowSun = glm::normalize(glm::vec3(-0.4f, -0.6f, -0.3f));

// A large ground with a few buildings along the view.
const std::vector<Aabb> kOutdoor = {box({-400, -0.1f, -400}, {400, 0, 400}), box({-2, 0, -12}, {2, 6, -8}),
                                    box({5, 0, -60}, {15, 20, -50}), box({-30, 0, -250}, {0, 40, -200})};

struct SplitCase {
    float near;
    float far;
    int count;
    float weight;
};

class CascadeSplitsTest : public testing::TestWithParam<SplitCase> {};

} // namespace

TEST_P(CascadeSplitsTest, AreMonotoneAndCoverNearToFarExactly) {
    const SplitCase c = GetParam();
    const std::vector<float> splits = cascadeSplits(c.near, c.far, c.count, c.weight);
    ASSERT_EQ(splits.size(), static_cast<std::size_t>(c.count) + 1);
    EXPECT_EQ(splits.front(), c.near);
    EXPECT_EQ(splits.back(), c.far);
    for (std::size_t i = 1; i < splits.size(); ++i) {
        EXPECT_GT(splits[i], splits[i - 1]) << "split " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, CascadeSplitsTest,
                         testing::Values(SplitCase{0.3f, 5000.0f, 4, 0.5f}, SplitCase{0.3f, 5000.0f, 4, 0.0f},
                                         SplitCase{0.3f, 5000.0f, 4, 1.0f}, SplitCase{0.1f, 100.0f, 2, 0.75f},
                                         SplitCase{1e-3f, 1e6f, 3, 0.5f}, SplitCase{10.0f, 10.5f, 4, 1.0f},
                                         SplitCase{0.5f, 8.0f, 1, 0.5f}));

TEST(CascadeSplitsTest, WeightBlendsUniformAndLogarithmicSchemes) {
    const std::vector<float> uniform = cascadeSplits(1.0f, 1000.0f, 3, 0.0f);
    const std::vector<float> logarithmic = cascadeSplits(1.0f, 1000.0f, 3, 1.0f);
    const std::vector<float> half = cascadeSplits(1.0f, 1000.0f, 3, 0.5f);
    EXPECT_NEAR(uniform[1], 1.0f + 999.0f / 3.0f, 1e-3f);
    EXPECT_NEAR(logarithmic[1], 10.0f, 1e-3f);
    EXPECT_NEAR(logarithmic[2], 100.0f, 1e-2f);
    EXPECT_NEAR(half[1], 0.5f * (uniform[1] + logarithmic[1]), 1e-3f);
}

TEST(CascadeSplitsTest, AutomaticCountAddsACascadePerDecadeBeyondAThousandToOne) {
    EXPECT_EQ(automaticCascadeCount({2.0f, 19.0f}), 1);   // a model on a table
    EXPECT_EQ(automaticCascadeCount({1.0f, 999.0f}), 1);  // a model on a ground plane
    EXPECT_EQ(automaticCascadeCount({0.3f, 600.0f}), 2);  // a street
    EXPECT_EQ(automaticCascadeCount({0.3f, 4000.0f}), 3); // a landscape
    EXPECT_EQ(automaticCascadeCount({1e-3f, 1e6f}), kMaxCascades);
    EXPECT_EQ(automaticCascadeCount({0.0f, 10.0f}), 1); // degenerate ranges get the one fitted map
    EXPECT_EQ(automaticCascadeCount({5.0f, 5.0f}), 1);
}

TEST(CascadeFitTest, SphereHoldsTheWholeSliceAndIgnoresCameraPose) {
    const FitView a = camera({0, 1.8f, 0}, {0, 1.5f, -10});
    const FitView b = camera({123.4f, 7.0f, -55.5f}, {-300, -20, 40}); // moved and turned
    for (const auto& [near, far] : {std::pair{0.3f, 4.0f}, {4.0f, 40.0f}, {40.0f, 500.0f}}) {
        const Sphere sa = frustumSliceSphere(a.projection, near, far);
        const Sphere sb = frustumSliceSphere(b.projection, near, far);
        EXPECT_EQ(sa.radius, sb.radius); // bit for bit: cascades keep their texel size while the camera turns
        const glm::mat4 clipToView = glm::inverse(a.projection);
        for (const float x : {-1.0f, 1.0f}) {
            for (const float y : {-1.0f, 1.0f}) {
                const glm::vec4 n = clipToView * glm::vec4(x, y, -1.0f, 1.0f);
                const glm::vec3 direction = glm::vec3(n) / n.w / (-n.z / n.w); // view-space point at depth 1
                for (const float depth : {near, far}) {
                    EXPECT_LE(glm::length(direction * depth - sa.centre), sa.radius * (1.0f + 1e-5f));
                }
            }
        }
    }
}

TEST(CascadeFitTest, SnappingKeepsTheTexelGridFixedInWorldSpaceUnderCameraTranslation) {
    const int resolution = 1024;
    for (const bool snap : {true, false}) {
        // Sub-texel and multi-texel steps of the camera, which also looks along a new line each time.
        int offGrid = 0;
        const LightProjection reference = fitCascade(kLowSun, camera({0, 1.8f, 0}, {0, 1.5f, -10}), 4.0f,
                                                     40.0f, kOutdoor, resolution, snap);
        ASSERT_TRUE(reference.valid);
        for (const float step : {0.0013f, 0.011f, 0.07f, 0.9f, 3.7f}) {
            const glm::vec3 eye(step, 1.8f, -0.5f * step);
            const LightProjection moved = fitCascade(kLowSun, camera(eye, eye + glm::vec3(0, -0.3f, -10)),
                                                     4.0f, 40.0f, kOutdoor, resolution, snap);
            ASSERT_TRUE(moved.valid);
            EXPECT_EQ(moved.texelScale, reference.texelScale);
            for (const glm::vec3 point : {glm::vec3(0.37f, 0.0f, -12.21f), glm::vec3(-3.3f, 2.0f, -20.0f)}) {
                const glm::vec3 a = toShadow(reference, point);
                const glm::vec3 b = toShadow(moved, point);
                const glm::vec2 texels = (glm::vec2(b) - glm::vec2(a)) * static_cast<float>(resolution);
                const glm::vec2 fraction = glm::abs(texels - glm::round(texels));
                const bool onGrid = fraction.x < 1e-2f && fraction.y < 1e-2f;
                offGrid += onGrid ? 0 : 1;
                if (snap) {
                    EXPECT_TRUE(onGrid) << "step " << step << ": moved by " << texels.x << ", " << texels.y;
                    EXPECT_NEAR(b.z, a.z, 1e-6f) << "step " << step; // same depths: same stored values
                }
            }
        }
        if (!snap) {
            EXPECT_GT(offGrid, 0); // without snapping the grid slides with the camera
        }
    }
}

TEST(CascadeFitTest, CastersTowardsTheLightAreInsideTheDepthRange) {
    // A tall tower outside the slice's sphere but between it and the sun still lands in the map.
    const FitView view = camera({0, 1.8f, 0}, {0, 1.5f, -10});
    const std::vector<Aabb> boxes = {kOutdoor[0], box({25, 0, -10}, {30, 200, -5})};
    const LightProjection p = fitCascade(kLowSun, view, 0.3f, 20.0f, boxes, 1024, true);
    ASSERT_TRUE(p.valid);
    // Every point of the tower over the map lies within its depth range (the part beside it need not).
    int overTheMap = 0;
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 100; ++j) {
            for (int k = 0; k <= 10; ++k) {
                const glm::vec3 point(25.0f + 0.5f * static_cast<float>(i), 2.0f * static_cast<float>(j),
                                      -10.0f + 0.5f * static_cast<float>(k));
                const glm::vec3 s = toShadow(p, point);
                if (s.x >= 0.0f && s.x <= 1.0f && s.y >= 0.0f && s.y <= 1.0f) {
                    ++overTheMap;
                    EXPECT_GE(s.z, 0.0f) << point.x << " " << point.y << " " << point.z;
                }
            }
        }
    }
    EXPECT_GT(overTheMap, 0);
}

TEST(CascadeFitTest, ReceiversDecideWhichSlicesAreDrawn) {
    const FitView view = camera({0, 50, 0}, {0, 50, -10}); // looking at the sky over the ground
    const std::vector<Aabb> boxes = {box({-5, 45, -30}, {5, 55, -20})};
    EXPECT_TRUE(hasReceiversBetween(view, boxes, 10.0f, 25.0f));
    EXPECT_FALSE(hasReceiversBetween(view, boxes, 40.0f, 500.0f));
    EXPECT_FALSE(hasReceiversBetween(view, boxes, 0.3f, 15.0f));
    const std::optional<glm::vec2> range = visibleDepthRange(view, boxes);
    ASSERT_TRUE(range);
    EXPECT_LE(range->x, 20.0f);
    EXPECT_GE(range->y, 30.0f);
    EXPECT_LT(range->y, 30.0f * 1.1f); // widened by at most a 1/8 octave
    EXPECT_FALSE(visibleDepthRange(view, std::vector<Aabb>{box({-5, 45, 20}, {5, 55, 30})})); // behind
}

TEST(CubeFaceTest, SelectionPicksTheDominantAxisWithOneFaceForEveryDirection) {
    EXPECT_EQ(g::gsCubeFace({2, 1, -1}), 0);
    EXPECT_EQ(g::gsCubeFace({-2, 1, -1}), 1);
    EXPECT_EQ(g::gsCubeFace({0.1f, 3, -1}), 2);
    EXPECT_EQ(g::gsCubeFace({0.1f, -3, -1}), 3);
    EXPECT_EQ(g::gsCubeFace({0.1f, 0.2f, 1}), 4);
    EXPECT_EQ(g::gsCubeFace({0.1f, 0.2f, -1}), 5);
    EXPECT_EQ(g::gsCubeFace({1, 1, 1}), 0); // ties go to the earlier axis
    EXPECT_EQ(g::gsCubeFace({0, 0, 0}), 0); // even the degenerate direction has a face
    for (int face = 0; face < kCubeFaces; ++face) {
        EXPECT_EQ(g::gsCubeFace(cubeFaceAxis(face)), face);
    }
}

TEST(CubeFaceTest, SelectionIsContinuousAcrossEdgesBecauseBothFacesHoldThePoint) {
    // Directions straddling every edge and corner of the cube: whichever face each side selects, its widened
    // map holds the point with the margin to spare, so a kernel there reads that face's own texels.
    const int resolution = 512;
    const float margin = 5.5f;
    const glm::vec3 light(1.0f, 2.0f, 3.0f);
    const std::vector<Aabb> boxes = {box(light - glm::vec3(20.0f), light + glm::vec3(20.0f))};
    const glm::mat4 everywhere = glm::ortho(-1e3f, 1e3f, -1e3f, 1e3f, -1e3f, 1e3f);
    std::vector<LightProjection> faces;
    for (int face = 0; face < kCubeFaces; ++face) {
        faces.push_back(fitPointLightFace(light, face, 0.0f, everywhere, boxes, resolution, margin));
        ASSERT_TRUE(faces.back().valid);
        ASSERT_TRUE(faces.back().perspective);
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float inside = (margin - 0.5f) / static_cast<float>(resolution); // margin left for the kernel
    int crossings = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 d(unit(random), unit(random), unit(random));
        // Push half the samples onto an edge (two equal magnitudes) and a few onto a corner.
        if (i % 2 == 0) {
            d.y = std::copysign(std::abs(d.x), d.y);
        }
        if (i % 10 == 0) {
            d.z = std::copysign(std::abs(d.x), d.z);
        }
        for (const float nudge : {-1e-4f, 1e-4f}) {
            const glm::vec3 direction = glm::normalize(d + glm::vec3(nudge, 0.0f, 0.0f));
            const int face = g::gsCubeFace(direction);
            crossings += face != g::gsCubeFace(glm::normalize(d - glm::vec3(nudge, 0.0f, 0.0f)));
            const glm::vec3 s = toShadow(faces[static_cast<std::size_t>(face)], light + 7.0f * direction);
            ASSERT_TRUE(s.x >= inside && s.x <= 1.0f - inside && s.y >= inside && s.y <= 1.0f - inside)
                << "direction " << direction.x << ", " << direction.y << ", " << direction.z << " on face "
                << face << " at " << s.x << ", " << s.y;
            ASSERT_TRUE(s.z > 0.0f && s.z < 1.0f);
        }
    }
    EXPECT_GT(crossings, 1000); // the samples did straddle edges
}

TEST(CubeFaceTest, FacesWithoutVisibleReceiversAreNotDrawn) {
    const glm::vec3 light(0, 3, 0);
    const std::vector<Aabb> boxes = {box({-10, -0.1f, -10}, {10, 0, 10})}; // floor only
    const glm::mat4 view = glm::perspective(0.8f, 1.0f, 0.1f, 100.0f) *
                           glm::lookAt(glm::vec3(0, 8, 8), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    EXPECT_FALSE(fitPointLightFace(light, 2, 0.0f, view, boxes, 256, 2.0f).valid); // +Y: nothing above
    EXPECT_TRUE(fitPointLightFace(light, 3, 0.0f, view, boxes, 256, 2.0f).valid);  // -Y: the floor
    EXPECT_FALSE(
        fitPointLightFace(light, 3, 2.0f, view, boxes, 256, 2.0f).valid); // the floor is beyond range
}

TEST(CubeFaceTest, WideningHoldsTheMarginInTexels) {
    for (const int resolution : {256, 2048}) {
        const float fov = cubeFaceFieldOfView(resolution, 4.0f);
        // The 90° face ends at tan = 1: that is `margin` texels inside the map's edge.
        const float texelsOutside =
            0.5f * static_cast<float>(resolution) * (1.0f - 1.0f / std::tan(0.5f * fov));
        EXPECT_NEAR(texelsOutside, 4.0f, 1e-2f);
    }
    EXPECT_NEAR(cubeFaceFieldOfView(512, 0.0f), glm::radians(90.0f), 1e-6f);
}

TEST(CascadeSelectionTest, IndexFollowsTheSplitsAndTheBlendRisesAcrossTheBand) {
    const glm::vec4 far(4.0f, 20.0f, 100.0f, 500.0f);
    EXPECT_EQ(g::gsCascadeIndex(0.5f, far, 4), 0);
    EXPECT_EQ(g::gsCascadeIndex(4.0f, far, 4), 1);
    EXPECT_EQ(g::gsCascadeIndex(99.0f, far, 4), 2);
    EXPECT_EQ(g::gsCascadeIndex(1e9f, far, 4), 3);
    EXPECT_EQ(g::gsCascadeIndex(50.0f, far, 2), 1);
    EXPECT_EQ(g::gsCascadeIndex(50.0f, far, 1), 0);
    int previous = 0;
    for (float depth = 0.1f; depth < 1000.0f; depth *= 1.01f) {
        const int index = g::gsCascadeIndex(depth, far, 4);
        EXPECT_GE(index, previous);
        previous = index;
    }
    EXPECT_EQ(g::gsCascadeBlendWeight(10.0f, 4.0f, 20.0f, 0.1f), 0.0f);
    EXPECT_NEAR(g::gsCascadeBlendWeight(19.2f, 4.0f, 20.0f, 0.1f), 0.5f, 1e-5f);
    EXPECT_EQ(g::gsCascadeBlendWeight(20.0f, 4.0f, 20.0f, 0.1f), 1.0f);
    EXPECT_EQ(g::gsCascadeBlendWeight(19.9f, 4.0f, 20.0f, 0.0f), 0.0f);  // no band: no blend, no 0/0
    EXPECT_EQ(g::gsCascadeBlendWeight(19.9f, 20.0f, 20.0f, 0.1f), 0.0f); // empty span
}

TEST(CascadeSettingsTest, BadCascadeSettingsAreRefusedNamingTheField) {
    const auto problems = [](auto change) {
        ShadowSettings settings;
        change(settings);
        std::string all;
        for (const std::string& problem : settings.validate()) {
            all += problem + "\n";
        }
        return all;
    };
    EXPECT_NE(problems([](ShadowSettings& s) { s.cascadeCount = 5; }).find("cascadeCount"),
              std::string::npos);
    EXPECT_NE(problems([](ShadowSettings& s) { s.cascadeCount = -1; }).find("cascadeCount"),
              std::string::npos);
    EXPECT_NE(problems([](ShadowSettings& s) {
                  s.cascadeCount = 3;
                  s.cascadeSplitWeight = std::numeric_limits<float>::quiet_NaN();
              }).find("cascadeSplitWeight"),
              std::string::npos);
    EXPECT_NE(problems([](ShadowSettings& s) {
                  s.cascadeCount = 3;
                  s.cascadeBlend = std::numeric_limits<float>::infinity();
              }).find("cascadeBlend"),
              std::string::npos);
    EXPECT_EQ(problems([](ShadowSettings& s) { s.cascadeCount = 4; }), "");
    EXPECT_EQ(problems([](ShadowSettings& s) { s.cascadeCount = 0; }), ""); // automatic
}
