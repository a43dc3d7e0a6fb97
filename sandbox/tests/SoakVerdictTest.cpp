// The soak run's verdict: flat after warm-up passes; RSS beyond the tolerance, any change in the live GL
// objects or any GL error fails, each named.
#include "SoakRun.h"

#include <gtest/gtest.h>

namespace {

sandbox::SoakSample sample(int cycle, double rssMiB, long buffers) {
    sandbox::SoakSample s;
    s.cycle = cycle;
    s.rssMiB = rssMiB;
    s.glObjects.buffers = buffers;
    s.glObjects.textures = 10;
    return s;
}

TEST(SoakVerdictTest, FlatAfterWarmUpPasses) {
    const auto verdict =
        sandbox::judgeSoak({sample(1, 100.0, 4), sample(2, 103.0, 4), sample(3, 99.0, 4)}, 0, 0.08);
    EXPECT_TRUE(verdict.passed());
    EXPECT_DOUBLE_EQ(verdict.rssGrowthMiB, 3.0);
    EXPECT_EQ(verdict.glObjectGrowth, 0);
}

TEST(SoakVerdictTest, RssBeyondTheToleranceFails) {
    const auto verdict =
        sandbox::judgeSoak({sample(1, 100.0, 4), sample(2, 104.0, 4), sample(3, 108.5, 4)}, 0, 0.08);
    ASSERT_EQ(verdict.failures.size(), 1u);
    EXPECT_NE(verdict.failures[0].find("RSS grew 8.5 MiB after warm-up (tolerance 8.0 MiB)"),
              std::string::npos)
        << verdict.failures[0];
}

TEST(SoakVerdictTest, TheToleranceIsAFractionOfTheBaseline) {
    // 8.5 MiB over 100 MiB fails at 8 %; the same growth over 200 MiB passes, with a 16 MiB allowance.
    const auto verdict = sandbox::judgeSoak({sample(2, 200.0, 4), sample(3, 208.5, 4)}, 0, 0.08);
    EXPECT_TRUE(verdict.passed());
    EXPECT_DOUBLE_EQ(verdict.rssToleranceMiB, 16.0);
    EXPECT_DOUBLE_EQ(verdict.rssGrowthMiB, 8.5);
}

TEST(SoakVerdictTest, AnyChangeInLiveGlObjectsFails) {
    const auto grown = sandbox::judgeSoak({sample(1, 100.0, 4), sample(2, 100.0, 5)}, 0, 0.08);
    ASSERT_EQ(grown.failures.size(), 1u);
    EXPECT_EQ(grown.glObjectGrowth, 1);
    EXPECT_NE(grown.failures[0].find("after cycle 2"), std::string::npos) << grown.failures[0];

    // Same total, different kinds: a buffer freed and a texture leaked still fails.
    sandbox::SoakSample swapped = sample(2, 100.0, 3);
    swapped.glObjects.textures = 11;
    const auto verdict = sandbox::judgeSoak({sample(1, 100.0, 4), swapped}, 0, 0.08);
    EXPECT_EQ(verdict.glObjectGrowth, 0);
    EXPECT_FALSE(verdict.passed());
}

TEST(SoakVerdictTest, GlErrorsFail) {
    const auto verdict = sandbox::judgeSoak({sample(1, 100.0, 4), sample(2, 100.0, 4)}, 3, 0.08);
    ASSERT_EQ(verdict.failures.size(), 1u);
    EXPECT_EQ(verdict.failures[0], "3 GL error(s)");
}

} // namespace
