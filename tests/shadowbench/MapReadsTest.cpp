// The cost model's count of map reads per lookup, per technique (mapReadsPerLookup).
#include <shadowbench/ShadowBench.h>

#include <gtest/gtest.h>

namespace {

shadows::ShadowSettings with(shadows::ShadowTechnique technique) {
    shadows::ShadowSettings settings;
    settings.technique = technique;
    return settings;
}

TEST(MapReadsPerLookup, CountsEveryTapOfTheKernel) {
    EXPECT_EQ(shadowbench::mapReadsPerLookup(with(shadows::ShadowTechnique::SlopeScaledBias)), 1);
    shadows::ShadowSettings pcf = with(shadows::ShadowTechnique::Pcf);
    EXPECT_EQ(shadowbench::mapReadsPerLookup(pcf), static_cast<int>(pcf.tapPattern().offsets.size()));
    shadows::ShadowSettings jittered = with(shadows::ShadowTechnique::JitteredPcf);
    EXPECT_EQ(shadowbench::mapReadsPerLookup(jittered), jittered.jitterTaps);
    // pcss: the blocker search and the filter, the most its early outs leave.
    EXPECT_EQ(shadowbench::mapReadsPerLookup(with(shadows::ShadowTechnique::Pcss)), 40);
    EXPECT_EQ(shadowbench::mapReadsPerLookup(with(shadows::ShadowTechnique::PcssScreenPlane)), 40);
    // msm-soft: the search region's moments and the penumbra's, one fetch each whatever the width.
    EXPECT_EQ(shadowbench::mapReadsPerLookup(with(shadows::ShadowTechnique::MsmSoft)), 2);
}

} // namespace
