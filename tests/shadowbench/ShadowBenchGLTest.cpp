// Corrected techniques against ray-traced ground truth on the knob and the torus. Thresholds: values measured
// on llvmpipe (printed as "[ measured ]"; output is deterministic) with margin.
#include "../engine/GLTestContext.h"

#include <shadowbench/ShadowBench.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <unistd.h>

using namespace shadowbench;
using shadows::ShadowTechnique;

namespace {

struct Limit {
    double acne;
    double leak;
};

struct SceneCase {
    const char* scene;
    std::size_t minimumShadowed; // truly shadowed interior pixels the view must contain
    std::map<ShadowTechnique, Limit> limits;
};

const SceneCase kScenes[] = {
    {"knob",
     1000,
     {{ShadowTechnique::SlopeScaledBias, {0.001, 0.005}},
      {ShadowTechnique::Gsm, {0.001, 0.005}},
      {ShadowTechnique::PcfGsmPointGradient, {0.003, 0.005}},
      {ShadowTechnique::PcfGsmAverageGradient, {0.004, 0.005}},
      {ShadowTechnique::PcfGsmQuadratic, {0.004, 0.005}},
      {ShadowTechnique::ReceiverPlaneBias, {0.002, 0.005}},
      {ShadowTechnique::NormalOffset, {0.002, 0.005}}}},
    {"torus",
     300,
     {{ShadowTechnique::SlopeScaledBias, {0.001, 0.005}},
      {ShadowTechnique::Gsm, {0.001, 0.005}},
      {ShadowTechnique::PcfGsmPointGradient, {0.001, 0.005}},
      {ShadowTechnique::PcfGsmAverageGradient, {0.001, 0.005}},
      {ShadowTechnique::PcfGsmQuadratic, {0.001, 0.005}},
      {ShadowTechnique::ReceiverPlaneBias, {0.001, 0.005}},
      {ShadowTechnique::NormalOffset, {0.001, 0.005}}}},
};

class ShadowBenchGLTest : public testing::TestWithParam<SceneCase> {};

} // namespace

TEST_P(ShadowBenchGLTest, CorrectedTechniquesStayUnderMeasuredAcneAndLeak) {
    const engine::HeadlessContext& context = glTestContext();
    BenchOptions options;
    options.size = {320, 240};
    options.frames = 1;
    options.imageFolder = std::filesystem::temp_directory_path() / ("gs_bench_" + std::to_string(::getpid()));
    const ShadowBench bench(context, options);
    const auto scene = bench.prepare(GetParam().scene, std::filesystem::path(CONTENT_DIR) / "scenes" /
                                                           (std::string(GetParam().scene) + ".gltf"));
    for (const auto& [technique, limit] : GetParam().limits) {
        BenchConfig config;
        config.label = std::string(shadows::toString(technique));
        config.settings.technique = technique;
        config.settings.resolution = 1024;
        const BenchResult result = bench.run(*scene, config);
        std::cout << "[ measured ] " << GetParam().scene << " " << config.label << ": acne "
                  << result.metrics.acneRate << " of " << result.metrics.lit << ", leak "
                  << result.metrics.leakRate << " of " << result.metrics.shadowed << ", MAE "
                  << result.metrics.meanAbsoluteError << "\n";
        EXPECT_GT(result.metrics.lit, 10000u);
        EXPECT_GT(result.metrics.shadowed, GetParam().minimumShadowed);
        EXPECT_LE(result.metrics.acneRate, limit.acne) << config.label;
        EXPECT_LE(result.metrics.leakRate, limit.leak) << config.label;
    }
    std::filesystem::remove_all(options.imageFolder);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShadowBenchGLTest, testing::ValuesIn(kScenes),
                         [](const auto& test) { return std::string(test.param.scene); });
