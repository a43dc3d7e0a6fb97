// The cost model's reference pass (FetchProbe): the maps and counts it accepts, without a GL context.
#include <shadowbench/FetchProbe.h>

#include <engine/Error.h>

#include <gtest/gtest.h>

namespace {

using shadowbench::FetchKind;
using shadowbench::FetchProbe;
using shadowbench::ProbeMap;

TEST(FetchProbe, TakesEveryMapTheCostModelMeasures) {
    EXPECT_NO_THROW(FetchProbe(FetchKind::Compare, 1, glm::mat4(1.0f)));
    for (const ProbeMap& map : FetchProbe::kOtherMaps) {
        EXPECT_NO_THROW(FetchProbe(FetchKind::Compare, 1, glm::mat4(1.0f), map)) << map.size;
        EXPECT_NO_THROW(FetchProbe(FetchKind::Filtered, 16, glm::mat4(1.0f), map)) << map.size;
    }
}

TEST(FetchProbe, RefusesMapsAndCountsItCannotMake) {
    EXPECT_THROW(FetchProbe(FetchKind::Compare, 1, glm::mat4(1.0f), {0, shadows::DepthFormat::D24}),
                 engine::Error);
    EXPECT_THROW(FetchProbe(FetchKind::Compare, 1, glm::mat4(1.0f), {32768, shadows::DepthFormat::D24}),
                 engine::Error);
    EXPECT_THROW(
        FetchProbe(FetchKind::Compare, 1, glm::mat4(1.0f), {512, static_cast<shadows::DepthFormat>(7)}),
        engine::Error);
    EXPECT_THROW(FetchProbe(FetchKind::Compare, 3, glm::mat4(1.0f)), engine::Error);
    FetchProbe probe(FetchKind::Filtered, 1, glm::mat4(1.0f));
    EXPECT_THROW(probe.setFetches(0), engine::Error);
    EXPECT_NO_THROW(probe.setFetches(8));
}

} // namespace
