// Tap patterns and jitter texels: what the PCF kernels and their fits read (no GL).
#include <shadows/TapPattern.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

using namespace shadows;

TEST(TapPatternTest, RejectsBadParametersByName) {
    EXPECT_THROW(TapPattern::make(TapLayout::Grid, 9, 1.0f), std::invalid_argument);
    EXPECT_THROW(TapPattern::make(TapLayout::Poisson, 4, 1.0f), std::invalid_argument);
    EXPECT_THROW(TapPattern::make(TapLayout::Grid, 4, 0.0f), std::invalid_argument);
    EXPECT_THROW(TapPattern::make(TapLayout::Grid, 4, std::nanf("")), std::invalid_argument);
}

TEST(TapPatternTest, PoissonPatternIsDeterministicAndInsideTheRadius) {
    const TapPattern a = TapPattern::make(TapLayout::Poisson, 32, 2.5f);
    const TapPattern b = TapPattern::make(TapLayout::Poisson, 32, 2.5f);
    EXPECT_EQ(a.offsets, b.offsets);
    ASSERT_EQ(a.offsets.size(), 32u);
    for (const glm::vec2& o : a.offsets) {
        EXPECT_LE(glm::length(o), 2.5f + 1e-5f);
    }
}

TEST(JitterTexelsTest, EveryTapStaysInItsStratumAndTestTapsSpread) {
    const JitterTexels jitter = makeJitterTexels(32, 8);
    ASSERT_EQ(jitter.pairs, 16);
    ASSERT_EQ(jitter.texels.size(), 8u * 8u * 16u);
    glm::ivec2 grid;
    for (int tap = 0; tap < 32; ++tap) {
        const glm::ivec2 stratum = jitterStratum(tap, 32, grid);
        for (std::size_t pixel = 0; pixel < 64; ++pixel) {
            const glm::u16vec4 texel = jitter.texels[static_cast<std::size_t>(tap / 2) * 64 + pixel];
            const glm::vec2 point =
                glm::vec2(tap % 2 == 0 ? texel.x : texel.z, tap % 2 == 0 ? texel.y : texel.w) / 65535.0f;
            EXPECT_GE(point.x * static_cast<float>(grid.x), static_cast<float>(stratum.x) - 1e-3f);
            EXPECT_LE(point.x * static_cast<float>(grid.x), static_cast<float>(stratum.x + 1) + 1e-3f);
            EXPECT_GE(point.y * static_cast<float>(grid.y), static_cast<float>(stratum.y) - 1e-3f);
            EXPECT_LE(point.y * static_cast<float>(grid.y), static_cast<float>(stratum.y + 1) + 1e-3f);
        }
    }
    EXPECT_EQ(grid.x * grid.y, 32);
    // The first 8 (test) taps use 8 distinct strata reaching both halves of the box in x and y.
    std::set<std::pair<int, int>> cells;
    glm::ivec2 low(100);
    glm::ivec2 high(-1);
    for (int tap = 0; tap < 8; ++tap) {
        const glm::ivec2 s = jitterStratum(tap, 32, grid);
        cells.insert({s.x, s.y});
        low = glm::min(low, s);
        high = glm::max(high, s);
    }
    EXPECT_EQ(cells.size(), 8u);
    EXPECT_LT(low.x, grid.x / 2);
    EXPECT_GE(high.x, grid.x / 2);
    EXPECT_LT(low.y, grid.y / 2);
    EXPECT_GE(high.y, grid.y / 2);
}

TEST(TapPatternTest, LinksListTapsNearestFirstAndJoinGridNeighbours) {
    const TapPattern grid = TapPattern::make(TapLayout::Grid, 4, 1.5f); // one texel between taps
    ASSERT_EQ(grid.nearestFirst.size(), 16u);
    for (std::size_t k = 1; k < grid.nearestFirst.size(); ++k) {
        EXPECT_LE(glm::length(grid.offsets[static_cast<std::size_t>(grid.nearestFirst[k - 1])]),
                  glm::length(grid.offsets[static_cast<std::size_t>(grid.nearestFirst[k])]));
    }
    EXPECT_FLOAT_EQ(glm::length(grid.offsets[static_cast<std::size_t>(grid.nearestFirst[0])]),
                    std::sqrt(0.5f));
    EXPECT_FLOAT_EQ(grid.linkDistance, 1.5f); // diagonal neighbours (1.41) are joined, two apart (2) are not
    const TapPattern poisson = TapPattern::make(TapLayout::Poisson, 16, 1.5f);
    EXPECT_GT(poisson.linkDistance, 0.0f);
    EXPECT_LT(poisson.linkDistance, 3.0f);
}
