// The CPU side of the sample-distribution fit: the reduction's mirror on synthetic depth images, the cascade
// count's density rule, and the map fitted to a samples' box (no GL).
#include <shadows/LightFrustum.h>
#include <shadows/SampleDistribution.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <array>

#include <cmath>
#include <limits>
#include <vector>

using namespace shadows;

namespace {

const glm::mat4 kProjection = glm::perspective(0.8f, 4.0f / 3.0f, 1.0f, 1000.0f);

/// The window depth (0..1) a point at view depth `viewDepth` on the axis has under kProjection.
float windowDepth(float viewDepth) {
    const glm::vec4 clip = kProjection * glm::vec4(0.0f, 0.0f, -viewDepth, 1.0f);
    return 0.5f * clip.z / clip.w + 0.5f;
}

/// A box of samples in light space.
LightRect rect(glm::vec3 low, glm::vec3 high) {
    LightRect r;
    r.extend(low);
    r.extend(high);
    return r;
}

} // namespace

TEST(SampleDistributionTest, DepthRangeIsTheNearestAndFarthestSurface) {
    const glm::ivec2 size(4, 3);
    std::vector<float> depth(12, 1.0f); // cleared: no surface
    depth[1] = windowDepth(2.0f);
    depth[6] = windowDepth(50.0f);
    depth[11] = windowDepth(7.0f);
    const auto range = sampleDepthRange(depth, size, glm::inverse(kProjection));
    ASSERT_TRUE(range);
    // Off the axis the texel's view depth is the same plane's: -z does not change across the image.
    EXPECT_NEAR(range->x, 2.0f, 2e-3f);
    EXPECT_NEAR(range->y, 50.0f, 0.1f);
}

TEST(SampleDistributionTest, AnEmptyOrBrokenViewHasNoRange) {
    const glm::ivec2 size(3, 2);
    EXPECT_FALSE(sampleDepthRange(std::vector<float>(6, 1.0f), size, glm::inverse(kProjection)));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(sampleDepthRange(std::vector<float>(6, nan), size, glm::inverse(kProjection)));
    // A degenerate projection (all zeros) gives no finite depth.
    std::vector<float> depth(6, 0.5f);
    EXPECT_FALSE(sampleDepthRange(depth, size, glm::mat4(0.0f)));
    // NaN texels among good ones are skipped.
    depth[0] = nan;
    EXPECT_TRUE(sampleDepthRange(depth, size, glm::inverse(kProjection)));
}

TEST(SampleDistributionTest, SlicesFollowThePracticalSplitSchemeWithTheBlendBand) {
    const auto slices = sampleSliceDepths({1.0f, 1000.0f}, 1.0f, 0.1f);
    // The outer ends widened by a thousandth, for the reduction's rounding.
    EXPECT_FLOAT_EQ(slices[sampleSliceIndex(1, 0)].x, 0.999f);
    EXPECT_FLOAT_EQ(slices[sampleSliceIndex(1, 0)].y, 1001.0f);
    // Logarithmic: 4 cascades split at 10^(3/4) steps; each after the first starts a tenth of the previous
    // one's span early.
    const std::vector<float> splits = cascadeSplits(1.0f, 1000.0f, 4, 1.0f);
    for (int c = 0; c < 4; ++c) {
        const glm::vec2 slice = slices[static_cast<std::size_t>(sampleSliceIndex(4, c))];
        EXPECT_FLOAT_EQ(slice.y, splits[static_cast<std::size_t>(c) + 1] * (c == 3 ? 1.001f : 1.0f));
        const float expectedNear =
            c == 0 ? 0.999f : splits[c] - 0.1f * (splits[c] - splits[static_cast<std::size_t>(c) - 1]);
        EXPECT_FLOAT_EQ(slice.x, expectedNear);
    }
    EXPECT_EQ(sampleSliceIndex(4, 3), kSampleSlices - 1);
}

TEST(SampleDistributionTest, LightRectsHoldEachSliceSamples) {
    const glm::ivec2 size(2, 1);
    const std::vector<float> depth{windowDepth(2.0f), windowDepth(400.0f)};
    const glm::mat4 clipToWorld = glm::inverse(kProjection); // view = world
    const auto range = sampleDepthRange(depth, size, glm::inverse(kProjection));
    ASSERT_TRUE(range);
    const auto slices = sampleSliceDepths(*range, 0.9f, 0.1f);
    const auto rects = sampleLightRects(depth, size, clipToWorld, glm::mat4(1.0f), glm::mat4(1.0f), slices);
    EXPECT_EQ(rects[sampleSliceIndex(1, 0)].samples, 2u);
    EXPECT_EQ(rects[sampleSliceIndex(2, 0)].samples, 1u);
    EXPECT_EQ(rects[sampleSliceIndex(2, 1)].samples, 1u);
    // Light space = view space here: the near sample's z is -2.
    EXPECT_NEAR(rects[sampleSliceIndex(2, 0)].max.z, -2.0f, 1e-3f);
    EXPECT_NEAR(rects[sampleSliceIndex(2, 1)].min.z, -400.0f, 1.0f);
}

TEST(SampleDistributionTest, CascadeCountIsTheFewestWithATexelPerPixel) {
    // A 480-pixel-high image: a pixel at view depth d is d * 2 tan(0.4) / 480 wide (~0.0035 d).
    const float pixelPerDepth = 2.0f * std::tan(0.4f) / 480.0f;
    std::array<LightRect, kSampleSlices> rects{};
    std::array<glm::vec2, kSampleSlices> depths = sampleSliceDepths({10.0f, 1000.0f}, 0.9f, 0.1f);
    // One map over 1000 m of 2048 texels: 0.49 m texels, 14 pixels wide at 10 m: too coarse. Two: the near
    // slice 20 m across holds 1 cm texels, finer than its 3.5 cm pixels; the far one is seen from far enough.
    rects[sampleSliceIndex(1, 0)] = rect({0, 0, 0}, {1000.0f, 1000.0f, 1.0f});
    rects[sampleSliceIndex(2, 0)] = rect({0, 0, 0}, {20.0f, 20.0f, 1.0f});
    const float farNear = depths[sampleSliceIndex(2, 1)].x;
    const float farExtent = 0.9f * 2048.0f * pixelPerDepth * farNear;
    rects[sampleSliceIndex(2, 1)] = rect({0, 0, 0}, {farExtent, farExtent, 1.0f});
    EXPECT_GT(sliceTexelsPerPixel(rects[0], depths[0].x, 2048, kProjection, 480), 1.0f);
    EXPECT_EQ(densityCascadeCount(rects, depths, 2048, kProjection, 480), 2);
    // A slice too coarse at every count: four.
    rects[sampleSliceIndex(2, 1)] = rect({0, 0, 0}, {4.0f * farExtent, farExtent, 1.0f});
    for (int cascade = 0; cascade < 3; ++cascade) {
        rects[static_cast<std::size_t>(sampleSliceIndex(3, cascade))] =
            rect({0, 0, 0}, {1000.0f, 1.0f, 1.0f});
    }
    EXPECT_EQ(densityCascadeCount(rects, depths, 2048, kProjection, 480), 4);
    // A small model: one map is enough.
    rects[sampleSliceIndex(1, 0)] = rect({0, 0, 0}, {5.0f, 5.0f, 1.0f});
    EXPECT_EQ(densityCascadeCount(rects, depths, 2048, kProjection, 480), 1);
}

TEST(SampleDistributionTest, ClippingToTheShadowableRegionKeepsDepthAndDropsDisjointRects) {
    Aabb region;
    region.extend({0.0f, 0.0f, 0.0f});
    region.extend({10.0f, 10.0f, 0.0f});
    const LightRect clipped = clippedTo(rect({-5.0f, 2.0f, -30.0f}, {20.0f, 4.0f, 3.0f}), region);
    EXPECT_EQ(clipped.min, glm::vec3(0.0f, 2.0f, -30.0f));
    EXPECT_EQ(clipped.max, glm::vec3(10.0f, 4.0f, 3.0f));
    EXPECT_TRUE(clippedTo(rect({11.0f, 0.0f, 0.0f}, {12.0f, 1.0f, 1.0f}), region).empty());
    EXPECT_TRUE(clippedTo(rect({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}), Aabb{}).empty());
}

TEST(SampleDistributionTest, TheMapHoldsTheSamplesAndTheirMarginAndNoMore) {
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, -0.4f, -0.8f));
    const LightRect samples = rect({-12.0f, 3.0f, -40.0f}, {18.0f, 9.0f, -5.0f});
    const float margin = 3.0f;
    const LightProjection map = fitToSamples(direction, samples, {}, 1024, margin, true);
    ASSERT_TRUE(map.valid);
    // No larger than the samples, the margin and a texel of slack, rounded up to the next 1/8 octave.
    const float extent = 30.0f * 1024.0f / (1024.0f - 2.0f * (margin + 1.0f));
    EXPECT_LE(map.texelScale * 1024.0f, extent * std::exp2(0.125f) * 1.0001f);
    EXPECT_GE(map.texelScale * 1024.0f, extent);
    // Every corner of the samples' box lies inside the map, away from its lit border, and within its depth.
    const glm::mat4 toLightSpace = glm::inverse(lightView(direction));
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 light((corner & 1) != 0 ? samples.max.x : samples.min.x,
                              (corner & 2) != 0 ? samples.max.y : samples.min.y,
                              (corner & 4) != 0 ? samples.max.z : samples.min.z);
        const glm::vec4 world = toLightSpace * glm::vec4(light, 1.0f);
        const glm::vec4 s = map.worldToShadow * world;
        // The lit border starts two texels beyond the samples, and the margin holds their kernels.
        const float border = std::max(map.litBorderTexels + 2.0f, margin) / 1024.0f - 1e-6f;
        EXPECT_GE(s.x, border) << corner;
        EXPECT_LE(s.x, 1.0f - border) << corner;
        EXPECT_GE(s.y, border) << corner;
        EXPECT_LE(s.y, 1.0f - border) << corner;
        EXPECT_GT(s.z, 0.0f) << corner;
        EXPECT_LT(s.z, 1.0f) << corner;
    }
}

TEST(SampleDistributionTest, CastersAreDrawnWhereTheSamplesReadAndNoFurther) {
    // Samples four times wider than deep in light space: the square map spans the width, and the casters
    // need drawing only over the samples, their kernels' reach (the margin and a texel) and the receivers'
    // two texels of offset.
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, -0.4f, -0.8f));
    const LightRect samples = rect({-20.0f, 3.0f, -40.0f}, {20.0f, 13.0f, -5.0f});
    const float margin = 3.0f;
    for (const bool snap : {false, true}) {
        const LightProjection map = fitToSamples(direction, samples, {}, 1024, margin, snap);
        ASSERT_TRUE(map.valid);
        const glm::vec4 region = map.drawnRegion;
        const glm::mat4 toWorld = glm::inverse(lightView(direction));
        const glm::vec4 low =
            map.worldToShadow * toWorld * glm::vec4(samples.min.x, samples.min.y, -20.0f, 1.0f);
        const glm::vec4 high =
            map.worldToShadow * toWorld * glm::vec4(samples.max.x, samples.max.y, -20.0f, 1.0f);
        const float reach = (margin + 1.0f + 2.0f) / 1024.0f;
        const float tolerance = 1e-5f;
        EXPECT_NEAR(region.x, std::max(low.x - reach, 0.0f), tolerance) << snap;
        EXPECT_NEAR(region.y, std::max(low.y - reach, 0.0f), tolerance) << snap;
        EXPECT_NEAR(region.z, std::min(high.x + reach, 1.0f), tolerance) << snap;
        EXPECT_NEAR(region.w, std::min(high.y + reach, 1.0f), tolerance) << snap;
        // Across the narrow side a quarter of the map and its reach; across the wide one all of it, the
        // snapped extent's slack beyond the samples left out.
        EXPECT_LT(region.w - region.y, 0.26f + 2.0f * reach) << snap;
        EXPECT_GE(region.x, 0.0f) << snap;
        EXPECT_LE(region.z, 1.0f) << snap;
    }
    // Visible samples beyond those a caster can shadow: the region holds their lookups too, so each reads
    // what it would in the whole map; the map itself is fitted to the shadowable ones alone.
    const LightRect visible = rect({-20.0f, -5.0f, -40.0f}, {20.0f, 13.0f, -5.0f});
    const LightProjection held = fitToSamples(direction, samples, {}, 1024, margin, false);
    const LightProjection all = fitToSamples(direction, samples, {}, 1024, margin, false, {}, &visible);
    EXPECT_EQ(all.worldToShadow, held.worldToShadow);
    EXPECT_LT(all.drawnRegion.y, held.drawnRegion.y);
    EXPECT_EQ(all.drawnRegion.w, held.drawnRegion.w);
    const glm::vec4 below = all.worldToShadow * glm::inverse(lightView(direction)) *
                            glm::vec4(visible.min.x, visible.min.y, -20.0f, 1.0f);
    EXPECT_NEAR(all.drawnRegion.y, std::max(below.y - (margin + 3.0f) / 1024.0f, 0.0f), 1e-5f);
    // A visible box that is not a number draws the map whole.
    LightRect broken = visible;
    broken.max.y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(fitToSamples(direction, samples, {}, 1024, margin, false, {}, &broken).drawnRegion,
              glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
    // Where the map is no wider than the samples and their reach, it is drawn whole.
    const LightProjection square =
        fitToSamples(direction, rect({0.0f, 0.0f, -40.0f}, {30.0f, 30.0f, -5.0f}), {}, 1024, margin, false);
    EXPECT_NEAR(square.drawnRegion.x, 0.0f, 1e-6f);
    EXPECT_NEAR(square.drawnRegion.z, 1.0f, 1e-6f);
    EXPECT_NEAR(square.drawnRegion.y, 0.0f, 1e-6f);
    EXPECT_NEAR(square.drawnRegion.w, 1.0f, 1e-6f);
}

TEST(SampleDistributionTest, SnappedFitIgnoresSubTexelMotionOfTheSamples) {
    // The samples move by a fraction of a texel (a camera creeping forward): quantised extent, snapped origin
    // and stepped depth keep the map's texel grid; only whole texels move it.
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, -0.4f, -0.8f));
    const LightProjection a =
        fitToSamples(direction, rect({0.0f, 0.0f, -40.0f}, {30.0f, 20.0f, -5.0f}), {}, 1024, 2.0f, true);
    const float texel = a.texelScale;
    const LightProjection b = fitToSamples(
        direction, rect({0.2f * texel, 0.1f * texel, -40.0f}, {30.0f + 0.2f * texel, 20.0f, -5.0f}), {}, 1024,
        2.0f, true);
    EXPECT_EQ(a.texelScale, b.texelScale);
    // The origin differs by whole texels (possibly none).
    const glm::vec4 origin = glm::inverse(a.worldToShadow) * glm::vec4(0.0f, 0.0f, 0.5f, 1.0f);
    const glm::vec4 moved = b.worldToShadow * origin;
    const float shift = (moved.x / moved.w) * 1024.0f;
    EXPECT_NEAR(shift, std::round(shift), 1e-2f);
}

TEST(SampleDistributionTest, AnEarlierSquareIsKeptWhileItHoldsTheSamplesWithTheirMargin) {
    // A camera moving along: the samples shift, and the square drawn before stays where it is while they and
    // their margin (the kernels' reach) lie within it, so the map it holds stays valid.
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, -0.4f, -0.8f));
    const float margin = 2.0f;
    const auto shifted = [](float dx, float width) {
        return rect({dx, 0.0f, -40.0f}, {dx + width, 20.0f, -5.0f});
    };
    const LightProjection first = fitToSamples(direction, shifted(0.0f, 30.0f), {}, 1024, margin, true);
    ASSERT_TRUE(first.valid);
    const float texel = first.texelScale;
    EXPECT_EQ(first.square.z, texel * 1024.0f);
    // How far the samples may move right with their margin still inside the square.
    const float room = first.square.x + 0.5f * first.square.z - 30.0f - margin * texel;
    ASSERT_GT(room, texel);
    const std::array<LightProjection, 1> kept{first};
    const LightProjection inside = fitToSamples(direction, shifted(room - 0.25f * texel, 30.0f), {}, 1024,
                                                margin, true, {}, nullptr, kept);
    EXPECT_EQ(inside.square, first.square);
    EXPECT_EQ(inside.worldToShadow, first.worldToShadow);
    // The same samples fitted afresh centre a square of their own.
    EXPECT_NE(fitToSamples(direction, shifted(room - 0.25f * texel, 30.0f), {}, 1024, margin, true).square,
              first.square);
    // A quarter texel further, the margin would cross the edge: a square of their own.
    const LightProjection beyond = fitToSamples(direction, shifted(room + 0.25f * texel, 30.0f), {}, 1024,
                                                margin, true, {}, nullptr, kept);
    EXPECT_NE(glm::vec2(beyond.square), glm::vec2(first.square));
    EXPECT_EQ(beyond.square.z, first.square.z);
    // Samples that need another size, or a map of another resolution, keep nothing either.
    const LightProjection wider =
        fitToSamples(direction, shifted(1.0f, 36.0f), {}, 1024, margin, true, {}, nullptr, kept);
    EXPECT_NE(wider.square.z, first.square.z);
    const LightProjection finer =
        fitToSamples(direction, shifted(texel, 30.0f), {}, 2048, margin, true, {}, nullptr, kept);
    EXPECT_NE(finer.texelScale, first.texelScale);
    EXPECT_NE(glm::vec2(finer.square), glm::vec2(first.square));
}

TEST(SampleDistributionTest, NoSamplesOrNonFiniteOnesGiveNoMap) {
    const glm::vec3 direction(0.0f, -1.0f, 0.0f);
    EXPECT_FALSE(fitToSamples(direction, LightRect{}, {}, 1024, 2.0f, true).valid);
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(fitToSamples(direction, rect({0, 0, 0}, {inf, 1.0f, 1.0f}), {}, 1024, 2.0f, true).valid);
    LightRect nan = rect({0, 0, 0}, {1.0f, 1.0f, 1.0f});
    nan.max.x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(fitToSamples(direction, nan, {}, 1024, 2.0f, true).valid);
    // A single sample: a tiny but valid map.
    EXPECT_TRUE(fitToSamples(direction, rect({1, 2, 3}, {1, 2, 3}), {}, 1024, 2.0f, true).valid);
}

TEST(SampleDistributionTest, ASoftMarginHoldsTheLightsWidestPenumbraUpToAnEighthOfTheMap) {
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, -0.4f, -0.8f));
    // Samples 2 m across and 10 m deep in light space, no caster above them: the widest penumbra is cast from
    // their top onto their bottom.
    const LightRect samples = rect({0.0f, 0.0f, -10.0f}, {2.0f, 2.0f, 0.0f});
    const float hard = 3.0f;
    const LightProjection narrow = fitToSamples(direction, samples, {}, 1024, hard + 64.0f, false);
    // No widening asked for: the same map as the margin in texels.
    const LightProjection same = fitToSamples(direction, samples, {}, 1024, hard, false, {64.0f, 0.0f});
    EXPECT_EQ(same.texelScale, narrow.texelScale);
    EXPECT_EQ(same.softReachTexels, 64.0f);
    // A penumbra of 0.01 m per metre behind its blocker: 0.1 m, about 60 texels of 2 m over 1024 - no wider
    // than the margin's floor of 64.
    EXPECT_EQ(fitToSamples(direction, samples, {}, 1024, hard, false, {64.0f, 0.01f}).softReachTexels, 64.0f);
    // 0.03 m per metre: 0.3 m, wider than 64 texels; the map's reach holds it in world units.
    const LightProjection wide = fitToSamples(direction, samples, {}, 1024, hard, false, {64.0f, 0.03f});
    ASSERT_TRUE(wide.valid);
    EXPECT_GT(wide.softReachTexels, 64.0f);
    EXPECT_GE(wide.softReachTexels * wide.texelScale, 0.3f);
    EXPECT_LE(wide.softReachTexels * wide.texelScale, 0.3f * 1.25f); // counted in the narrower map's texels
    // The map holds the samples and that margin: its side is the samples', two margins and the slack.
    EXPECT_NEAR(wide.texelScale * 1024.0f,
                2.0f + 2.0f * (hard + wide.softReachTexels + 1.0f) * wide.texelScale, 1e-3f);
    // A penumbra wider than an eighth of the map stops there; a non-finite size widens nothing.
    EXPECT_EQ(fitToSamples(direction, samples, {}, 1024, hard, false, {64.0f, 10.0f}).softReachTexels,
              128.0f);
    EXPECT_EQ(fitToSamples(direction, samples, {}, 1024, hard, false,
                           {64.0f, std::numeric_limits<float>::infinity()})
                  .softReachTexels,
              64.0f);
    EXPECT_EQ(fitToSamples(direction, samples, {}, 1024, hard, false,
                           {64.0f, std::numeric_limits<float>::quiet_NaN()})
                  .softReachTexels,
              64.0f);
}

TEST(SampleDistributionTest, ViewResolutionIsTheSmallestPowerOfTwoWhoseTexelsTheViewResolves) {
    // A 90° vertical field of view over 480 rows: a pixel spans 2 d / 480 at view depth d, 1/24 at d = 10, so
    // a slice 10 wide starting there is 240 pixels across.
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 4.0f / 3.0f, 0.1f, 100.0f);
    std::array<LightRect, kSampleSlices> rects{};
    std::array<glm::vec2, kSampleSlices> depths{};
    const auto single = static_cast<std::size_t>(sampleSliceIndex(1, 0));
    rects[single] = rect({0.0f, 0.0f, -5.0f}, {10.0f, 4.0f, 0.0f});
    depths[single] = {10.0f, 40.0f};
    // Half a pixel a texel: 480 texels and two margins of 3 + 1 texels, so 512; a quarter: 968, so 1024.
    EXPECT_EQ(viewResolution(rects, depths, 1, 2048, 3.0f, 0.5f, projection, 480), 512);
    EXPECT_EQ(viewResolution(rects, depths, 1, 2048, 3.0f, 0.25f, projection, 480), 1024);
    // Never above the setting's resolution; 0 (or a non-finite size) asks for the resolution itself.
    EXPECT_EQ(viewResolution(rects, depths, 1, 256, 3.0f, 0.25f, projection, 480), 256);
    EXPECT_EQ(viewResolution(rects, depths, 1, 2048, 3.0f, 0.0f, projection, 480), 2048);
    EXPECT_EQ(viewResolution(rects, depths, 1, 2048, 3.0f, std::numeric_limits<float>::quiet_NaN(),
                             projection, 480),
              2048);
    // A slice at the camera (a pixel of no size) cannot be resolved: the resolution.
    depths[single].x = 0.0f;
    EXPECT_EQ(viewResolution(rects, depths, 1, 2048, 3.0f, 0.5f, projection, 480), 2048);
    // A tiny view still takes 64 texels (the margins fit); cascades take the side their finest needs, empty
    // ones none.
    depths[single].x = 10.0f;
    EXPECT_EQ(viewResolution(rects, depths, 1, 2048, 3.0f, 0.5f, projection, 24), 64);
    const auto nearCascade = static_cast<std::size_t>(sampleSliceIndex(2, 0));
    const auto farCascade = static_cast<std::size_t>(sampleSliceIndex(2, 1));
    rects[nearCascade] = rect({0.0f, 0.0f, -5.0f}, {2.5f, 1.0f, 0.0f}); // 60 px across at d = 10: 128
    depths[nearCascade] = {10.0f, 20.0f};
    depths[farCascade] = {20.0f, 40.0f}; // empty
    EXPECT_EQ(viewResolution(rects, depths, 2, 2048, 3.0f, 0.5f, projection, 480), 128);
    rects[farCascade] = rect({0.0f, 0.0f, -5.0f}, {40.0f, 8.0f, 0.0f}); // 480 px across at d = 20: 1024
    EXPECT_EQ(viewResolution(rects, depths, 2, 2048, 3.0f, 0.5f, projection, 480), 1024);
}
