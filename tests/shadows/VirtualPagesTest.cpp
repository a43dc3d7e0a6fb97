// The virtual maps' CPU side: the level a receiver asks for (the shader's own function, compiled as C++), the
// pages its kernel reaches, the clipmap's geometry, the pool's LRU and the page table's fallbacks.
#include <shadows/ShadowSettings.h>
#include <shadows/VirtualPages.h>
#include <shadows/VisibilityMath.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace {

using shadows::ClipmapGeometry;
using shadows::PageKey;
using shadows::PagePool;

const float kUnbounded = shadows::glsl::GS_FOOTPRINT_UNBOUNDED;

int level(float unitFootprint, float pixelSize, int base = -40, int count = 64) {
    return shadows::glsl::gsVirtualLevel(unitFootprint, pixelSize, base, count);
}

TEST(VirtualLevel, CoarsestLevelWithATexelPerPixel) {
    // A texel one unit wide spanning 4 pixels: texels of 1/4 span exactly one, of 1/2 two.
    const int chosen = level(4.0f, 0.3f);
    EXPECT_EQ(chosen, -2);
    EXPECT_LE(std::ldexp(4.0f, chosen), 1.0f);
    EXPECT_GT(std::ldexp(4.0f, chosen + 1), 1.0f);
    // Just above a power of two needs the next finer level; just below does not.
    EXPECT_EQ(level(4.01f, 0.3f), -3);
    EXPECT_EQ(level(3.99f, 0.3f), -2);
}

TEST(VirtualLevel, SlopeAsksFinerThanDistanceUpToTheCap) {
    // A receiver at grazing light: its footprint asks 20 octaves below its pixel size, the cap allows 3.
    EXPECT_EQ(level(std::ldexp(1.0f, 20), 1.0f), -shadows::glsl::GS_VIRTUAL_SLOPE_OCTAVES);
    // Facing the light, the footprint and the pixel size agree.
    EXPECT_EQ(level(1.0f / 0.7f, 0.7f), -1);
}

TEST(VirtualLevel, UnknownFootprintFallsBackToPixelSize) {
    EXPECT_EQ(level(0.0f, 0.3f), -2);
    EXPECT_EQ(level(kUnbounded, 0.3f), -2);
    EXPECT_EQ(level(std::numeric_limits<float>::quiet_NaN(), 0.3f), -2);
    EXPECT_EQ(level(-1.0f, 0.3f), -2);
}

TEST(VirtualLevel, ClampedToTheRequestRange) {
    EXPECT_EQ(level(1e-30f, 1e30f, -10, 8), -3);
    EXPECT_EQ(level(1e20f, 1e-20f, -10, 8), -10);
    // No pixel size: the footprint alone; neither: the finest.
    EXPECT_EQ(level(4.0f, 0.0f), -2);
    EXPECT_EQ(level(4.0f, std::numeric_limits<float>::infinity()), -2);
    EXPECT_EQ(level(0.0f, 0.0f, -10, 8), -10);
}

TEST(VirtualPageSpan, CoversTheKernelsReach) {
    glm::ivec2 low;
    glm::ivec2 high;
    shadows::glsl::gsVirtualPageSpan(glm::vec2(130.0f, 64.0f), 4.0f, 128.0f, 128, low, high);
    EXPECT_EQ(low, glm::ivec2(0, 0));
    EXPECT_EQ(high, glm::ivec2(1, 0));
    shadows::glsl::gsVirtualPageSpan(glm::vec2(64.0f, 64.0f), 4.0f, 128.0f, 128, low, high);
    EXPECT_EQ(low, high);
    // Clamped to the window at both ends.
    shadows::glsl::gsVirtualPageSpan(glm::vec2(1.0f, 16383.0f), 4.0f, 128.0f, 128, low, high);
    EXPECT_EQ(low, glm::ivec2(0, 127));
    EXPECT_EQ(high, glm::ivec2(0, 127));
}

ClipmapGeometry geometry(glm::vec2 camera = glm::vec2(10.3f, -7.9f)) {
    ClipmapGeometry result;
    result.lightView = shadows::lightView(glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)));
    result.camera = camera;
    result.depth = {-50.0f, 50.0f};
    result.pageSize = 128;
    result.finestLevel = -8;
    return result;
}

TEST(ClipmapGeometry, WindowIsSnappedToPagesAroundTheCamera) {
    const ClipmapGeometry clipmap = geometry();
    for (int l = -8; l < 8; ++l) {
        const glm::ivec2 origin = clipmap.windowOrigin(l);
        const double page = ClipmapGeometry::texelSize(l) * 128.0;
        const glm::dvec2 camera = glm::dvec2(clipmap.camera) / page - glm::dvec2(origin);
        // The camera lies in the window's middle page.
        EXPECT_GE(camera.x, 64.0);
        EXPECT_LT(camera.x, 65.0);
        EXPECT_GE(camera.y, 64.0);
        EXPECT_LT(camera.y, 65.0);
    }
    // A camera moving within a page keeps the window.
    EXPECT_EQ(geometry({10.3f, -7.9f}).windowOrigin(0), geometry({10.4f, -7.95f}).windowOrigin(0));
}

TEST(ClipmapGeometry, PagesSitOnTheirLevelsTexelGrid) {
    const ClipmapGeometry clipmap = geometry();
    const int l = -3;
    const int border = 4;
    const glm::ivec2 page = clipmap.windowOrigin(l) + glm::ivec2(70, 61);
    // The world point at the page's lower corner, at mid depth.
    const glm::vec2 corner = glm::vec2(glm::dvec2(page) * ClipmapGeometry::texelSize(l) * 128.0);
    const glm::vec3 world = glm::vec3(glm::inverse(clipmap.lightView) * glm::vec4(corner, 0.0f, 1.0f));
    const glm::vec4 inPage = clipmap.pageProjection(l, page, border).worldToShadow * glm::vec4(world, 1.0f);
    const float tile = 128.0f + 2.0f * border;
    EXPECT_NEAR(inPage.x * tile, static_cast<float>(border), 1e-3f);
    EXPECT_NEAR(inPage.y * tile, static_cast<float>(border), 1e-3f);
    EXPECT_NEAR(inPage.z, 0.5f, 1e-6f);
    const glm::vec4 inLevel = clipmap.levelProjection(l).worldToShadow * glm::vec4(world, 1.0f);
    EXPECT_NEAR(inLevel.x * shadows::kVirtualResolution, 70.0f * 128.0f, 1e-2f);
    EXPECT_NEAR(inLevel.y * shadows::kVirtualResolution, 61.0f * 128.0f, 1e-2f);
    EXPECT_FLOAT_EQ(clipmap.levelProjection(l).texelScale, 0.125f);
}

TEST(DepthRangeFor, StaysWhileACasterMovesInsideIt) {
    const glm::mat4 view = shadows::lightView(glm::vec3(0.0f, -1.0f, 0.0f));
    shadows::Aabb ground{{-10, -1, -10}, {10, 0, 10}};
    shadows::Aabb box{{0, 0, 0}, {1, 2, 1}};
    const glm::vec2 before = shadows::depthRangeFor(view, std::vector{ground, box});
    box.min.x += 0.3f;
    box.max.x += 0.3f;
    EXPECT_EQ(shadows::depthRangeFor(view, std::vector{ground, box}), before);
    EXPECT_LE(before.x, -1.0f);
    EXPECT_GE(before.y, 2.0f);
    EXPECT_EQ(shadows::depthRangeFor(view, {}), glm::vec2(0.0f, 1.0f));
}

TEST(RequestLevelBase, FollowsTheScenesScale) {
    EXPECT_EQ(shadows::requestLevelBase(1.0f), -24);
    EXPECT_EQ(shadows::requestLevelBase(1e5f), 16 - 24);
    EXPECT_EQ(shadows::requestLevelBase(0.0f), -24);
    EXPECT_EQ(shadows::requestLevelBase(std::numeric_limits<float>::quiet_NaN()), -24);
}

TEST(ClipmapGeometry, FineLevelsFarFromTheOriginKeepAnIntegerWindow) {
    ClipmapGeometry clipmap = geometry({3e6f, -3e6f});
    const glm::ivec2 origin = clipmap.windowOrigin(-40);
    EXPECT_EQ(origin, glm::ivec2((1 << 28) - 64, -(1 << 28) - 64));
}

PageKey key(int level, int x, int y = 0, int light = 0) {
    return {light, level, {x, y}};
}

TEST(PagePool, DrawsNewPagesOnceThenServesThemCached) {
    PagePool pool(4);
    const std::vector requests{key(0, 0), key(0, 1)};
    PagePool::FrameResult first = pool.request(requests, 1);
    EXPECT_EQ(first.render.size(), 2u);
    EXPECT_EQ(first.cached, 0);
    PagePool::FrameResult second = pool.request(requests, 2);
    EXPECT_TRUE(second.render.empty());
    EXPECT_EQ(second.cached, 2);
    EXPECT_EQ(pool.resident(), 2);
    EXPECT_NE(pool.tileOf(key(0, 0)), pool.tileOf(key(0, 1)));
}

TEST(PagePool, EvictsTheLeastRecentlyUsed) {
    PagePool pool(2);
    pool.request(std::vector{key(0, 0), key(0, 1)}, 1);
    pool.request(std::vector{key(0, 1)}, 2); // page 0 is now the older
    const int tileOfPage0 = pool.tileOf(key(0, 0));
    PagePool::FrameResult result = pool.request(std::vector{key(0, 2)}, 3);
    ASSERT_EQ(result.render.size(), 1u);
    EXPECT_EQ(result.render[0].first, tileOfPage0);
    EXPECT_EQ(pool.tileOf(key(0, 0)), -1);
    EXPECT_GE(pool.tileOf(key(0, 1)), 0);
}

TEST(PagePool, GrowingKeepsResidentPagesInTheirTiles) {
    PagePool pool(2);
    pool.request(std::vector{key(0, 0), key(0, 1)}, 1);
    const int tile0 = pool.tileOf(key(0, 0));
    const int tile1 = pool.tileOf(key(0, 1));
    pool.grow(4);
    pool.grow(3); // never shrinks
    EXPECT_EQ(pool.tiles(), 4);
    EXPECT_EQ(pool.tileOf(key(0, 0)), tile0);
    EXPECT_EQ(pool.tileOf(key(0, 1)), tile1);
    // The new tiles take new pages before anything is evicted.
    PagePool::FrameResult result = pool.request(std::vector{key(0, 2), key(0, 3)}, 2);
    EXPECT_EQ(result.render.size(), 2u);
    EXPECT_EQ(result.refused, 0);
    EXPECT_EQ(pool.resident(), 4);
    EXPECT_EQ(pool.tileOf(key(0, 0)), tile0);
}

TEST(PagePool, NeverEvictsAPageAskedForLaterInTheFrame) {
    PagePool pool(2);
    pool.request(std::vector{key(0, 0)}, 1);
    pool.request(std::vector{key(0, 1)}, 2); // page 0 is the older
    // A new page first, then page 0 again: the new one takes page 1's tile, not the older page 0's.
    PagePool::FrameResult result = pool.request(std::vector{key(0, 2), key(0, 0)}, 3);
    EXPECT_EQ(result.render.size(), 1u);
    EXPECT_EQ(result.cached, 1);
    EXPECT_GE(pool.tileOf(key(0, 0)), 0);
    EXPECT_EQ(pool.tileOf(key(0, 1)), -1);
}

TEST(PagePool, RefusesWhatTheFramesOwnPagesFill) {
    PagePool pool(1);
    PagePool::FrameResult result = pool.request(std::vector{key(1, 0), key(0, 0)}, 1);
    EXPECT_EQ(result.render.size(), 1u);
    EXPECT_EQ(result.refused, 1);
    EXPECT_GE(pool.tileOf(key(1, 0)), 0); // the first (coarse) request stays
}

TEST(PagePool, InvalidatesOnlyPagesUnderTheRect) {
    ClipmapGeometry clipmap = geometry({0.0f, 0.0f});
    PagePool pool(8);
    // Level 0: pages of 128 world units.
    pool.request(std::vector{key(0, 0), key(0, 1), key(0, 5), key(0, 0, 0, 1)}, 1);
    const int dropped = pool.invalidate(0, clipmap, {130.5f, 10.0f, 131.0f, 11.0f}, 2);
    EXPECT_EQ(dropped, 1);
    EXPECT_EQ(pool.tileOf(key(0, 1)), -1);
    EXPECT_GE(pool.tileOf(key(0, 0)), 0);
    EXPECT_GE(pool.tileOf(key(0, 5)), 0);
    // Within the border of page 0 too (2 texels of 1 unit past its edge at 128).
    EXPECT_EQ(pool.invalidate(0, clipmap, {129.5f, 10.0f, 129.6f, 11.0f}, 2), 1);
    // Another light's pages are not touched, until its own light changes.
    EXPECT_GE(pool.tileOf(key(0, 0, 0, 1)), 0);
    EXPECT_EQ(pool.invalidateLight(1), 1);
    EXPECT_EQ(pool.resident(), 1);
}

/// Lights reading up to `coarsest` levels each; no centre (a perspective map's requests, ranked by the pages
/// each group frees) unless given, no previous frame.
std::vector<shadows::CoarseningLight>
lights(std::vector<int> coarsest, glm::dvec2 centre = glm::dvec2(std::numeric_limits<double>::quiet_NaN())) {
    std::vector<shadows::CoarseningLight> result;
    for (const int level : coarsest) {
        shadows::CoarseningLight light;
        light.coarsestLevel = level;
        light.centre = centre;
        result.push_back(light);
    }
    return result;
}

/// Level-0 requests of light 0 covering `side`² pages from the origin.
shadows::PageRequests block(int side) {
    shadows::PageRequests pages;
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            pages.insert({0, 0, y, x});
        }
    }
    return pages;
}

TEST(CoarsenToFit, FillsThePoolAsFullAsTheRequestsAllow) {
    // 64 pages into 50: five groups of four give way (15 pages fewer), not the whole level (16 left).
    std::vector requests{block(8)};
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({15}), 50), 15);
    EXPECT_EQ(requests[0].size(), 49u);
    const auto coarser = std::count_if(requests[0].begin(), requests[0].end(),
                                       [](const auto& page) { return std::get<0>(page) == 1; });
    EXPECT_EQ(coarser, 5);
}

TEST(CoarsenToFit, APageWhoseParentIsAskedForGivesWayFirst) {
    // A full group of four (frees 3 of 4) and a lone page whose parent is requested (frees 1 of 1): one
    // page over, the lone page merges, and the group keeps its detail.
    std::vector requests{shadows::PageRequests{
        {0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 1, 0}, {0, 0, 1, 1}, {0, 0, 4, 4}, {1, 0, 2, 2}}};
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({15}), 5), 1);
    EXPECT_EQ(requests[0],
              (shadows::PageRequests{{0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 1, 0}, {0, 0, 1, 1}, {1, 0, 2, 2}}));
}

TEST(CoarsenToFit, TheLightAskingForTheMostGivesWay) {
    std::vector requests{block(2), block(4)};
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({15, 15}), 17), 3);
    EXPECT_EQ(requests[0], block(2));
    EXPECT_EQ(requests[1].size(), 13u);
}

TEST(CoarsenToFit, LonePagesMoveTheirLevelUpWhole) {
    // No group of level 0 frees a page, so the level moves up; on level 1 pairs merge.
    std::vector requests{shadows::PageRequests{{0, 0, 0, 0}, {0, 0, 0, 2}, {0, 0, 0, 4}, {0, 0, 0, 6}}};
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({15}), 2), 2);
    EXPECT_EQ(requests[0], (shadows::PageRequests{{2, 0, 0, 0}, {2, 0, 0, 1}}));
}

TEST(CoarsenToFit, AClipmapGivesWayFarthestFromTheCameraFirst) {
    // The camera over level-0 page (2, 2): the group farthest from it, under parent (3, 3), merges.
    std::vector requests{block(8)};
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({15}, {2.0, 2.0}), 61), 3);
    EXPECT_TRUE(requests[0].contains({1, 0, 3, 3}));
    EXPECT_FALSE(requests[0].contains({0, 0, 7, 7}));
    EXPECT_TRUE(requests[0].contains({0, 0, 0, 0}));
}

TEST(CoarsenToFit, StopsAtEachLightsCoarsestLevel) {
    std::vector requests{block(4)};
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({0}), 1), 0);
    EXPECT_EQ(requests[0], block(4));
    // One level up at most: 16 pages become 4, over the capacity of 1 (the pool then refuses the rest).
    EXPECT_EQ(shadows::coarsenToFit(requests, lights({1}), 1), 12);
    EXPECT_EQ(requests[0].size(), 4u);
}

TEST(BuildPageTable, PointsEveryPageAtTheFinestResidentOverIt) {
    ClipmapGeometry clipmap = geometry({0.0f, 0.0f});
    clipmap.finestLevel = 0;
    const int side = clipmap.pagesPerSide();
    PagePool pool(4);
    // Level 2's page 0 covers level 0's pages 0-3 on each axis; level 0's page (1, 1) is resident itself.
    pool.request(std::vector{key(2, 0), key(0, 1, 1)}, 1);
    const std::vector<std::uint32_t> table = shadows::buildPageTable(pool, 0, clipmap);
    ASSERT_EQ(table.size(), static_cast<std::size_t>(side * side * shadows::kClipmapLevels));
    const auto entry = [&](int index, glm::ivec2 page) {
        const glm::ivec2 local = page - clipmap.windowOrigin(index);
        return table[static_cast<std::size_t>(index * side * side + local.y * side + local.x)];
    };
    const std::uint32_t coarse = shadows::pageTableEntry(2, pool.tileOf(key(2, 0)));
    const std::uint32_t fine = shadows::pageTableEntry(0, pool.tileOf(key(0, 1, 1)));
    EXPECT_EQ(entry(0, {1, 1}), fine);
    EXPECT_EQ(entry(0, {3, 2}), coarse);
    EXPECT_EQ(entry(1, {1, 0}), coarse);
    EXPECT_EQ(entry(2, {0, 0}), coarse);
    EXPECT_EQ(entry(0, {4, 0}), 0u);  // beyond level 2's page: nothing
    EXPECT_EQ(entry(0, {-1, 0}), 0u); // negative pages have their own parents (-1 >> 1 = -1)
    EXPECT_EQ((coarse >> 24) & 63u, 2u);
    EXPECT_EQ(coarse & shadows::kPageTileMask, static_cast<std::uint32_t>(pool.tileOf(key(2, 0))));
}

TEST(VirtualFaceLevel, CoarsestMipWithATexelPerPixel) {
    // Level-0 texels spanning a quarter pixel each way: level 2's span one.
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({4.0f, 0.0f}, {0.0f, 4.0f}, 4.0f, 1.0f, 8), 2);
    // Aiming at 2 pixels a texel allows one level coarser.
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({4.0f, 0.0f}, {0.0f, 4.0f}, 4.0f, 2.0f, 8), 3);
    // Magnified (a level-0 texel spans 3 pixels): the finest level, no finer.
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({1.0f / 3, 0.0f}, {0.0f, 1.0f / 3}, 1.0f / 3, 1.0f, 8), 0);
    // Far away: clamped to the coarsest level.
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({1e6f, 0.0f}, {0.0f, 1e6f}, 1e6f, 1.0f, 8), 7);
    // Grazing: the slope asks at most GS_VIRTUAL_SLOPE_OCTAVES below the pixel's own size.
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({64.0f, 0.0f}, {0.0f, 1e-4f}, 64.0f, 1.0f, 8),
              6 - shadows::glsl::GS_VIRTUAL_SLOPE_OCTAVES);
    // No derivative (a pixel facing away): by its size alone; an unbounded footprint with a target above one
    // pixel stays unbounded.
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({0.0f, 0.0f}, {0.0f, 0.0f}, 8.0f, 1.0f, 8), 3);
    EXPECT_EQ(shadows::glsl::gsVirtualFaceLevel({0.0f, 0.0f}, {0.0f, 0.0f}, 8.0f, 4.0f, 8), 5);
}

shadows::PerspectiveGeometry spotMap() {
    shadows::PerspectiveGeometry result;
    const glm::mat4 view = glm::lookAt(glm::vec3(1.0f, 5.0f, 2.0f), glm::vec3(0.0f), glm::vec3(0, 0, -1));
    result.face = shadows::virtualPerspective(view, 1.2f, {0.7f, 9.0f});
    result.pageSize = 128;
    return result;
}

TEST(PerspectiveGeometry, LevelsGoDownToOnePage) {
    shadows::PerspectiveGeometry map = spotMap();
    EXPECT_EQ(map.levels(), 8); // 128 pages a side at level 0
    map.pageSize = 32;
    EXPECT_EQ(map.levels(), 10);
    map.pageSize = 512;
    EXPECT_EQ(map.levels(), 6);
}

TEST(PerspectiveGeometry, PagesAreCropsOfTheWholeMap) {
    const shadows::PerspectiveGeometry map = spotMap();
    ASSERT_TRUE(map.face.valid);
    const int border = 5;
    const float tile = 128.0f + 2.0f * border;
    const glm::vec3 world(0.31f, 0.2f, -0.17f);
    const glm::vec4 clip = map.face.worldToShadow * glm::vec4(world, 1.0f);
    const glm::vec3 coord = glm::vec3(clip) / clip.w;
    for (int level = 0; level < map.levels(); ++level) {
        // The page under the point on this level, and where in it (in level texels) the point lies.
        const float resolution = std::ldexp(static_cast<float>(shadows::kVirtualResolution), -level);
        const glm::vec2 window = glm::vec2(coord) * resolution;
        const glm::ivec2 page = glm::ivec2(glm::floor(window / 128.0f));
        const shadows::LightProjection projection = map.pageProjection(level, page, border);
        const glm::vec4 inClip = projection.worldToShadow * glm::vec4(world, 1.0f);
        const glm::vec3 inPage = glm::vec3(inClip) / inClip.w;
        const glm::vec2 expected = window - glm::vec2(page) * 128.0f + static_cast<float>(border);
        EXPECT_NEAR(inPage.x * tile, expected.x, 2e-3f) << "level " << level;
        EXPECT_NEAR(inPage.y * tile, expected.y, 2e-3f) << "level " << level;
        // Every level stores the same depth, and a texel 2^level level-0 texels wide.
        EXPECT_NEAR(inPage.z, coord.z, 1e-6f);
        EXPECT_FLOAT_EQ(projection.texelScale, map.face.texelScale * std::ldexp(1.0f, level));
        EXPECT_EQ(projection.depthRange, map.face.depthRange);
        // The page's rectangle holds the point, its border included.
        const glm::vec4 rect = map.pageRect(level, page, border);
        EXPECT_LE(rect.x, coord.x);
        EXPECT_GE(rect.z, coord.x);
    }
}

TEST(VirtualPerspective, DepthRangeSnapsOutwardToQuarterOctaves) {
    const glm::mat4 view(1.0f);
    const shadows::LightProjection a = shadows::virtualPerspective(view, 1.0f, {0.7f, 9.0f});
    const shadows::LightProjection b = shadows::virtualPerspective(view, 1.0f, {0.69f, 9.1f});
    ASSERT_TRUE(a.valid);
    EXPECT_EQ(a.depthRange, b.depthRange) << "a caster moving a little keeps the pages";
    EXPECT_LE(a.depthRange.x, 0.7f);
    EXPECT_GE(a.depthRange.y, 9.0f);
    EXPECT_GT(a.depthRange.x, 0.7f / 1.19f);
    EXPECT_LT(a.depthRange.y, 9.0f * 1.19f);
    EXPECT_TRUE(a.perspective);
    EXPECT_FLOAT_EQ(a.texelScale, 2.0f * std::tan(0.5f) / shadows::kVirtualResolution);
    // Nothing to map: invalid, never a NaN matrix.
    EXPECT_FALSE(shadows::virtualPerspective(view, 1.0f, {0.0f, 9.0f}).valid);
    EXPECT_FALSE(shadows::virtualPerspective(view, 1.0f, {2.0f, 1.0f}).valid);
    EXPECT_FALSE(
        shadows::virtualPerspective(view, 1.0f, {1.0f, std::numeric_limits<float>::infinity()}).valid);
    EXPECT_FALSE(
        shadows::virtualPerspective(view, std::numeric_limits<float>::quiet_NaN(), {1.0f, 2.0f}).valid);
}

TEST(BuildPageTable, FacePagesFallBackToTheirMipAncestors) {
    const shadows::PerspectiveGeometry map = spotMap();
    PagePool pool(4);
    // Face 2 of light 0: level 3's page (1, 0) covers level 0's pages x 8-15, y 0-7; level 0's (9, 2) is
    // resident itself. Face 1's page (0, 0) of level 7 is another face's.
    const PageKey coarse{0, 3, {1, 0}, 2};
    const PageKey fine{0, 0, {9, 2}, 2};
    pool.request(std::vector{coarse, fine, PageKey{0, 7, {0, 0}, 1}}, 1);
    const std::vector<std::uint32_t> table = shadows::buildPageTable(pool, 0, 2, map);
    std::vector<std::size_t> offsets{0};
    for (int level = 0; level < map.levels(); ++level) {
        const auto side = static_cast<std::size_t>(128 >> level);
        offsets.push_back(offsets.back() + side * side);
    }
    ASSERT_EQ(table.size(), offsets.back());
    const auto entry = [&](int level, glm::ivec2 page) {
        return table[offsets[static_cast<std::size_t>(level)] +
                     static_cast<std::size_t>(page.y * (128 >> level) + page.x)];
    };
    const std::uint32_t coarseEntry = shadows::pageTableEntry(3, pool.tileOf(coarse));
    EXPECT_EQ(entry(0, {9, 2}), shadows::pageTableEntry(0, pool.tileOf(fine)));
    EXPECT_EQ(entry(0, {15, 7}), coarseEntry);
    EXPECT_EQ(entry(2, {2, 1}), coarseEntry);
    EXPECT_EQ(entry(3, {1, 0}), coarseEntry);
    EXPECT_EQ(entry(0, {7, 0}), 0u) << "level 3's page 0 is not resident";
    EXPECT_EQ(entry(7, {0, 0}), 0u) << "face 1's page is not face 2's";
}

TEST(VirtualOverheadBytes, RequestsAndMipChainsOfTables) {
    // 128 pages a side: 64 levels of 128² request bits, and chains of 128² + 64² + ... + 1 words.
    const std::size_t requests = 128u * 128u * 64u / 8u;
    std::size_t chain = 0;
    for (std::size_t side = 128; side >= 1; side /= 2) {
        chain += side * side * 4;
    }
    EXPECT_EQ(shadows::virtualOverheadBytes(128, 0), requests);
    EXPECT_EQ(shadows::virtualOverheadBytes(128, 6), requests + 6 * chain);
    EXPECT_GT(shadows::virtualOverheadBytes(32, 1), shadows::virtualOverheadBytes(128, 1));
}

TEST(VirtualSettings, RefuseBadPagesAndBudgets) {
    shadows::ShadowSettings settings;
    settings.mapAllocation = shadows::MapAllocation::Virtual;
    EXPECT_TRUE(settings.validate().empty());
    const auto names = [](const std::vector<std::string>& problems, std::string_view field) {
        return problems.size() == 1 && problems[0].find(field) != std::string::npos;
    };
    shadows::ShadowSettings bad = settings;
    bad.virtualPageSize = 100;
    EXPECT_TRUE(names(bad.validate(), "virtualPageSize"));
    bad = settings;
    bad.virtualBudgetMiB = 0;
    EXPECT_TRUE(names(bad.validate(), "virtualBudgetMiB"));
    bad.virtualBudgetMiB = -5;
    EXPECT_TRUE(names(bad.validate(), "virtualBudgetMiB"));
    // One MiB holds no 512² page of 32-bit moments and depth.
    bad = settings;
    bad.technique = shadows::ShadowTechnique::Evsm;
    bad.virtualPageSize = 512;
    bad.virtualBudgetMiB = 1;
    EXPECT_TRUE(names(bad.validate(), "virtualBudgetMiB"));
    bad.virtualBudgetMiB = 8;
    EXPECT_TRUE(bad.validate().empty()) << bad.validate().front();
    // Like every field, the page settings are checked whether or not they apply.
    bad = settings;
    bad.mapAllocation = shadows::MapAllocation::Fitted;
    bad.virtualPageSize = 100;
    EXPECT_TRUE(names(bad.validate(), "virtualPageSize"));
}

} // namespace
