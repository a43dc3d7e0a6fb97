// shadowbench::summariseTimes: the figures every timed table prints.
#include <shadowbench/ShadowBench.h>

#include <gtest/gtest.h>

using shadowbench::summariseTimes;

TEST(PassTimingTest, SummariseTimesTakesTheMiddleOfAnOddCount) {
    const shadowbench::PassTiming timing = summariseTimes({5.0, 1.0, 3.0});
    EXPECT_EQ(timing.median, 3.0);
    EXPECT_EQ(timing.min, 1.0);
    EXPECT_EQ(timing.max, 5.0);
    EXPECT_EQ(timing.samples, 3);
}

TEST(PassTimingTest, SummariseTimesAveragesTheMiddleTwoOfAnEvenCount) {
    EXPECT_EQ(summariseTimes({10.0, 20.0}).median, 15.0);
    const shadowbench::PassTiming timing = summariseTimes({4.0, 1.0, 2.0, 8.0});
    EXPECT_EQ(timing.median, 3.0);
    EXPECT_EQ(timing.min, 1.0);
    EXPECT_EQ(timing.max, 8.0);
    EXPECT_EQ(timing.samples, 4);
}

TEST(PassTimingTest, SummariseTimesOfNothingIsZeroSamples) {
    const shadowbench::PassTiming timing = summariseTimes({});
    EXPECT_EQ(timing.samples, 0);
    EXPECT_EQ(timing.median, 0.0);
    EXPECT_EQ(summariseTimes({7.0}).median, 7.0);
    EXPECT_EQ(summariseTimes({7.0}).samples, 1);
}
