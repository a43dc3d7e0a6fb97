// The virtual maps' CPU side: the level a receiver asks for (the shader's own function, compiled as C++), the
// pages its kernel reaches, the clipmap's geometry, the pool's LRU and the page table's fallbacks.
#include <shadows/ShadowSettings.h>
#include <shadows/VirtualPages.h>
#include <shadows/VisibilityMath.h>

#include <gtest/gtest.h>

#include <cmath>
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
