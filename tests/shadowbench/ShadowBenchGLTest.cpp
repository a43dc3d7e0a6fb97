// Every non-naive technique at its defaults against ray-traced ground truth, on each content scene under its
// own light and under a low sun (5° above the horizon), and on the scenes of every light type: the floor of
// the defaults (acne and leak 0.05 %, darkening 0.5 %), which every one meets there (the values,
// deterministic on llvmpipe, are printed as "[ measured ]"). docs/RESULTS.md, "Defaults", has the same on the
// real models.
#include "../engine/GLTestContext.h"

#include <shadowbench/ShadowBench.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <unistd.h>

using namespace shadowbench;
using shadows::ShadowTechnique;

namespace {

/// The floor of the defaults.
constexpr double kAcneFloor = 5e-4;
constexpr double kLeakFloor = 5e-4;
constexpr double kDarkeningFloor = 5e-3;

/// Rates over fewer pixels than this are not checked (a grazing view may see few shadowed receivers).
constexpr std::size_t kMinimumPixels = 1000;

/// Measures every non-naive technique at its defaults on `scene` and checks it against the floor. Leak is
/// checked only over enough shadowed pixels, unless `leakAlways`.
void expectDefaultsMeetTheFloor(const ShadowBench& bench, const BenchScene& scene, const std::string& view,
                                bool leakAlways) {
    for (const ShadowTechnique technique : shadows::allTechniques()) {
        if (shadows::traitsOf(technique).naive) {
            continue;
        }
        shadows::ShadowSettings settings;
        settings.technique = technique;
        const ShadowMetrics m = bench.measure(scene, settings).metrics;
        const std::string label = view + " " + std::string(shadows::toString(technique));
        std::cout << "[ measured ] " << label << ": acne " << m.acneRate << " of " << m.lit << ", leak "
                  << m.leakRate << " of " << m.shadowed << ", darkening " << m.darkening << "\n";
        EXPECT_GT(m.lit, kMinimumPixels) << label;
        EXPECT_LT(m.acneRate, kAcneFloor) << label;
        EXPECT_LT(m.darkening, kDarkeningFloor) << label;
        if (leakAlways) {
            EXPECT_GT(m.shadowed, kMinimumPixels) << label;
        }
        if (leakAlways || m.shadowed >= kMinimumPixels) {
            EXPECT_LT(m.leakRate, kLeakFloor) << label;
        }
    }
}

/// What the floor is measured at: the Defaults table's image size, accuracy only, images beside the test's.
BenchOptions floorOptions() {
    BenchOptions options;
    options.size = {320, 240};
    options.timing = false;
    options.imageFolder = std::filesystem::temp_directory_path() / ("gs_bench_" + std::to_string(::getpid()));
    return options;
}

class ShadowBenchGLTest : public testing::TestWithParam<const char*> {};

} // namespace

TEST_P(ShadowBenchGLTest, EveryTechniqueAtItsDefaultsMeetsTheFloor) {
    const ShadowBench bench(glTestContext(), floorOptions());
    const std::filesystem::path path =
        std::filesystem::path(CONTENT_DIR) / "scenes" / (std::string(GetParam()) + ".gltf");
    for (const std::optional<engine::LightAngles> light :
         {std::optional<engine::LightAngles>{},
          std::optional<engine::LightAngles>{engine::LightAngles{30.0f, 5.0f}}}) {
        const auto scene = bench.prepare(GetParam(), path, light);
        expectDefaultsMeetTheFloor(bench, *scene,
                                   std::string(GetParam()) + (light ? " " + light->label() : ""), false);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShadowBenchGLTest,
                         testing::Values("knob", "torus", "bowl", "thin-shell", "crease-cube",
                                         "grazing-plane", "spheres"),
                         [](const auto& test) {
                             std::string name = test.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

namespace {

/// `terrain` (6 m texels over a heightfield: relief and creases below a texel) under the lights of the
/// Defaults sweep where the techniques comparing along the receiver's plane kept acne and `vsm` leaked
/// (docs/SHADOWS.md, "Half a texel for relief", "Light-bleeding reduction 0.4").
class TerrainBenchGLTest : public testing::TestWithParam<engine::LightAngles> {};

} // namespace

TEST_P(TerrainBenchGLTest, EveryTechniqueAtItsDefaultsMeetsTheFloor) {
    const std::filesystem::path path = std::filesystem::path(CORPUS_DIR) / "terrain.glb";
    if (!std::filesystem::exists(path)) {
        GTEST_SKIP() << "the real-model corpus is absent (" << path.string()
                     << " missing): run bash tools/corpus.sh (needs assimp-utils and assimp-testmodels)";
    }
    const ShadowBench bench(glTestContext(), floorOptions());
    const auto scene = bench.prepare("terrain", path, GetParam());
    expectDefaultsMeetTheFloor(bench, *scene, "terrain " + GetParam().label(), false);
}

INSTANTIATE_TEST_SUITE_P(Lights, TerrainBenchGLTest,
                         testing::Values(engine::LightAngles{30.0f, 40.0f}, engine::LightAngles{30.0f, 5.0f},
                                         engine::LightAngles{30.0f, 1.0f},
                                         engine::LightAngles{210.0f, 40.0f}),
                         [](const auto& test) {
                             std::string name = test.param.label();
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(ShimmerGLTest, SnappedCascadesDoNotShimmerAndUnsnappedOnesDo) {
    const engine::HeadlessContext& context = glTestContext();
    BenchOptions options;
    options.size = {160, 120};
    options.timing = false;
    options.shimmerFrames = 4;
    const ShadowBench bench(context, options);
    const auto scene = bench.prepare("knob", std::filesystem::path(CONTENT_DIR) / "scenes" / "knob.gltf");
    shadows::ShadowSettings settings;
    settings.cascadeCount = 3;
    settings.resolution = 512;
    EXPECT_EQ(bench.measureShimmer(*scene, settings), 0.0);
    settings.texelSnapping = false;
    const double unsnapped = bench.measureShimmer(*scene, settings);
    std::cout << "[ measured ] knob, 3 unsnapped cascades: shimmer " << unsnapped << "\n";
    EXPECT_GT(unsnapped, 0.0);
}

namespace {

/// The room (two point lights) and the outdoor scene (a sun over 4 km: automatic cascades) under their own
/// lights.
class EveryLightBenchGLTest : public testing::TestWithParam<const char*> {};

} // namespace

TEST_P(EveryLightBenchGLTest, EveryTechniqueAtItsDefaultsMeetsTheFloor) {
    const engine::HeadlessContext& context = glTestContext();
    BenchOptions options;
    options.size = {320, 240};
    options.timing = false;
    const ShadowBench bench(context, options);
    const std::string name = GetParam();
    const auto scene = bench.prepare(name, std::filesystem::path(CONTENT_DIR) / "scenes" / (name + ".gltf"));
    expectDefaultsMeetTheFloor(bench, *scene, name, true);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryLightBenchGLTest, testing::Values("room", "outdoor"),
                         [](const auto& test) { return std::string(test.param); });
