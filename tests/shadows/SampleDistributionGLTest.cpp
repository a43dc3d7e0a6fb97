// The sample-distribution fit on the GPU: its reduction against the CPU mirror on the same depth image, a
// single mesh spanning the view fitted to its visible samples, the casters drawn only where those samples
// read changing no image, and the fallback of a view with nothing in it.
#include "VisibleSamples.h"

#include "../engine/GLTestContext.h"
#include "../support/ComparisonSamplerLeftOnUnit.h"

#include <engine/EmbeddedShaderFile.h>
#include <engine/Engine.h>
#include <engine/Image.h>
#include <engine/Primitives.h>
#include <engine/RenderTarget.h>
#include <shadows/SampleDistribution.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>

std::span<const engine::EmbeddedShaderFile> gsShadowShaders();

using namespace shadows;

namespace {

const glm::vec3 kSunDirection = glm::normalize(glm::vec3(-0.5f, -0.25f, 0.8f)); // about 14 degrees up

/// Runs the reduction in the frame's pre-passes and keeps its result and the depth image it reduced.
class SampleProbe final : public engine::Module {
public:
    [[nodiscard]] std::string_view name() const override { return "sample-probe"; }
    void attach(engine::ModuleHost& host) override {
        host_ = &host;
        host.shaders().add(gsShadowShaders());
        // The depth pass's program includes the techniques the module lists; a plain depth needs none.
        host.shaders().add("shadows/techniques.glsl", "");
    }
    void detach() override { samples.reset(); }
    void renderPrePasses(const engine::FrameContext& frame) override {
        samples.emplace();
        bounds = samples->measure(*host_, frame, FitView{frame.view, frame.projection},
                                  lightView(kSunDirection), 0.9f, 0.1f);
        whole = bounds;
        if (bounds) {
            samples->measureCascadeSlices(*host_, *bounds);
        }
        depth = samples->readDepth();
        size = samples->size();
        view = frame.view;
        projection = frame.projection;
    }

    std::optional<VisibleSamples> samples;
    std::optional<VisibleSamples::Bounds> bounds;
    std::optional<VisibleSamples::Bounds> whole; // measure's result alone, before the cascades' slices
    std::vector<float> depth;
    glm::ivec2 size{0};
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};

private:
    engine::ModuleHost* host_ = nullptr;
};

/// One mesh: a 2 km ground with boxes on it, merged the way real assets arrive, so its bounding box spans
/// every view; a low sun and a camera 6 m up looking across it.
engine::Scene mergedApron(engine::EntityId& camera, glm::vec3 target = {0.0f, 0.0f, -60.0f}) {
    engine::MeshData merged = engine::primitives::plane(2000.0f, 8);
    for (const glm::vec3 at : {glm::vec3(-6.0f, 0.0f, -30.0f), glm::vec3(8.0f, 0.0f, -55.0f),
                               glm::vec3(-20.0f, 0.0f, -120.0f), glm::vec3(30.0f, 0.0f, -200.0f)}) {
        const engine::MeshData box = engine::primitives::cube(4.0f);
        const auto base = static_cast<std::uint32_t>(merged.positions.size());
        for (std::size_t i = 0; i < box.positions.size(); ++i) {
            merged.positions.push_back(box.positions[i] + at + glm::vec3(0.0f, 2.0f, 0.0f));
            merged.normals.push_back(box.normals[i]);
        }
        for (const std::uint32_t index : box.indices) {
            merged.indices.push_back(base + index);
        }
    }
    engine::Scene scene;
    const auto mesh = scene.create("apron");
    scene.entity(mesh).mesh = engine::MeshComponent{std::make_shared<engine::MeshData>(std::move(merged))};
    const auto sun = scene.create("sun");
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).transform = engine::Transform::lookAt(-kSunDirection, glm::vec3(0.0f));
    camera = scene.create("camera");
    engine::CameraComponent lens;
    lens.nearPlane = 0.5f;
    lens.farPlane = 1500.0f;
    scene.entity(camera).camera = lens;
    scene.entity(camera).transform = engine::Transform::lookAt({0.0f, 6.0f, 0.0f}, target);
    return scene;
}

float extentOf(const LightRect& rect) {
    return std::max(rect.max.x - rect.min.x, rect.max.y - rect.min.y);
}

} // namespace

// Sizes that fill the reduction's groups of 128x128 texels partly, down to a group whose last invocations
// start beyond the image.
class GpuReduction : public ::testing::TestWithParam<glm::ivec2> {};

TEST_P(GpuReduction, EqualsItsCpuMirror) {
    glTestContext();
    const glm::ivec2 size = GetParam();
    engine::EntityId camera = engine::kNoEntity;
    const engine::Scene scene = mergedApron(camera);
    engine::Engine engine;
    // The sample pass's own D32F depth: the lighting pass's D24 one (ModuleHost::viewDepth) reads back a step
    // away from what the shader fetches, 0.1 m at this view's 900 m, which is the format's, not the
    // reduction's.
    engine.renderer().shareViewDepth = false;
    auto& probe = static_cast<SampleProbe&>(engine.addModule(std::make_unique<SampleProbe>()));
    engine::RenderTarget target(size);
    engine.renderFrame(scene, camera, target);
    ASSERT_TRUE(probe.bounds);
    const auto range = sampleDepthRange(probe.depth, probe.size, glm::inverse(probe.projection));
    ASSERT_TRUE(range);
    EXPECT_NEAR(probe.bounds->viewDepth.x, range->x, 1e-4f * range->x);
    EXPECT_NEAR(probe.bounds->viewDepth.y, range->y, 1e-4f * range->y);
    const auto slices = sampleSliceDepths(probe.bounds->viewDepth, 0.9f, 0.1f);
    const auto rects = sampleLightRects(probe.depth, probe.size, glm::inverse(probe.projection * probe.view),
                                        probe.view, lightView(kSunDirection), slices);
    std::size_t samples = 0;
    for (std::size_t s = 0; s < rects.size(); ++s) {
        const LightRect& gpu = probe.bounds->slices[s];
        const LightRect& cpu = rects[s];
        samples += cpu.samples;
        // A sample within float rounding of a split may fall on either side: counts agree to a few.
        EXPECT_NEAR(static_cast<double>(gpu.samples), static_cast<double>(cpu.samples),
                    1e-3 * static_cast<double>(cpu.samples) + 2.0)
            << s;
        ASSERT_EQ(gpu.empty(), cpu.empty()) << s;
        if (!cpu.empty()) {
            const float tolerance = 1e-3f * std::max(extentOf(cpu), 1.0f);
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_NEAR(gpu.min[axis], cpu.min[axis], tolerance) << s << " axis " << axis;
                EXPECT_NEAR(gpu.max[axis], cpu.max[axis], tolerance) << s << " axis " << axis;
            }
        }
    }
    // measure alone reduced the range and slice 0 in its one pass, the same as with the cascades' slices,
    // and left those empty.
    ASSERT_TRUE(probe.whole);
    EXPECT_FALSE(probe.whole->cascadeSlices);
    EXPECT_TRUE(probe.bounds->cascadeSlices);
    EXPECT_EQ(probe.whole->viewDepth, probe.bounds->viewDepth);
    EXPECT_EQ(probe.whole->slices[0].samples, probe.bounds->slices[0].samples);
    EXPECT_EQ(probe.whole->slices[0].min, probe.bounds->slices[0].min);
    EXPECT_EQ(probe.whole->slices[0].max, probe.bounds->slices[0].max);
    for (std::size_t s = 1; s < rects.size(); ++s) {
        EXPECT_TRUE(probe.whole->slices[s].empty()) << s;
        EXPECT_FALSE(probe.bounds->slices[s].empty() && !rects[s].empty()) << s;
    }
    std::cout << "[ measured ] reduction of " << probe.size.x << "x" << probe.size.y << ": view depths "
              << probe.bounds->viewDepth.x << ".." << probe.bounds->viewDepth.y << ", " << samples
              << " slice samples\n";
    // Most of the image is ground: every texel was reduced, none twice.
    EXPECT_GT(rects[0].samples, static_cast<std::uint32_t>(size.x * size.y) / 2);
    EXPECT_LE(probe.bounds->slices[0].samples, static_cast<std::uint32_t>(size.x * size.y));
}

// The reduction gathers the depth image through texture unit 0: a sampler left bound there with comparison
// and linear filtering, as a fitted map's lookup leaves one, changes no bound.
TEST(GpuReductionSampler, IgnoresASamplerLeftOnItsUnit) {
    glTestContext();
    engine::EntityId camera = engine::kNoEntity;
    const engine::Scene scene = mergedApron(camera);
    const auto reduced = [&] {
        engine::Engine engine;
        engine.renderer().shareViewDepth = false;
        auto& probe = static_cast<SampleProbe&>(engine.addModule(std::make_unique<SampleProbe>()));
        engine::RenderTarget target({131, 67});
        engine.renderFrame(scene, camera, target);
        return probe.bounds;
    };
    const auto clean = reduced();
    std::optional<VisibleSamples::Bounds> left;
    {
        const testsupport::ComparisonSamplerLeftOnUnit sampler(0);
        left = reduced();
    }
    ASSERT_TRUE(clean && left);
    EXPECT_EQ(left->viewDepth, clean->viewDepth);
    EXPECT_EQ(left->slices[0].samples, clean->slices[0].samples);
    EXPECT_EQ(left->slices[0].min, clean->slices[0].min);
    EXPECT_EQ(left->slices[0].max, clean->slices[0].max);
}

INSTANTIATE_TEST_SUITE_P(SampleDistributionGLTest, GpuReduction,
                         ::testing::Values(glm::ivec2(320, 240), glm::ivec2(131, 67), glm::ivec2(9, 7)),
                         [](const ::testing::TestParamInfo<glm::ivec2>& param) {
                             return std::to_string(param.param.x) + "x" + std::to_string(param.param.y);
                         });

TEST(SampleDistributionGLTest, ASingleMeshSpanningTheViewIsFittedToItsVisibleSamples) {
    glTestContext();
    engine::EntityId camera = engine::kNoEntity;
    // Looking down at the ground 30 m ahead: no horizon in view, few tens of metres of ground.
    const engine::Scene scene = mergedApron(camera, {0.0f, 0.0f, -8.0f});
    ShadowSettings settings;
    settings.technique = ShadowTechnique::SlopeScaledBias;
    settings.cascadeCount = 1;
    settings.resolution = 1024;
    engine::Engine engine;
    auto& probe = static_cast<SampleProbe&>(engine.addModule(std::make_unique<SampleProbe>()));
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    engine::RenderTarget target({320, 240});
    engine.renderFrame(scene, camera, target);
    const auto samplesFit = module.lightProjection(0);
    ASSERT_TRUE(samplesFit && probe.bounds);
    settings.directionalFit = DirectionalFit::Bounds;
    module.setSettings(settings);
    engine.renderFrame(scene, camera, target);
    const auto boundsFit = module.lightProjection(0);
    ASSERT_TRUE(boundsFit);

    // The visible samples a caster can shadow, as the module cut them.
    std::vector<Aabb> boxes;
    Aabb meshBox;
    for (const glm::vec3& p : scene.entity(scene.find("apron").value()).mesh->mesh->positions) {
        meshBox.extend(p);
    }
    boxes.push_back(meshBox);
    const LightRect visible =
        clippedTo(probe.bounds->slices[0], shadowableRegion(kSunDirection, probe.projection * probe.view,
                                                            std::span<const Aabb>(boxes)));
    ASSERT_FALSE(visible.empty());
    const float slack = ShadowPlan::resolve(settings).kernelReachTexels + 1.0f;
    const float limit = extentOf(visible) * 1024.0f / (1024.0f - 2.0f * slack) * std::exp2(0.125f);
    const float fitted = samplesFit->texelScale * 1024.0f;
    std::cout << "[ measured ] one mesh spanning the view: samples " << extentOf(visible) << " m, fitted map "
              << fitted << " m, the bounds fit's " << boundsFit->texelScale * 1024.0f << " m\n";
    EXPECT_LE(fitted, limit * 1.0001f);
    EXPECT_GE(fitted, extentOf(visible));
    EXPECT_LT(fitted, 0.5f * boundsFit->texelScale * 1024.0f);
}

namespace {

struct DrawnRegionCase {
    std::string name;
    ShadowTechnique technique;
    glm::vec3 target;     // where the camera looks
    int cascadeCount = 1; // 0: automatic
    int momentBlurRadius = 0;
};

void PrintTo(const DrawnRegionCase& c, std::ostream* out) {
    *out << c.name;
}

struct RegionFrame {
    engine::Image image;
    std::vector<LightProjection> maps;
    ShadowStats stats;
};

/// The apron under its sun through the camera; with `frozenAt`, the maps fitted to that view as a frozen fit,
/// which draws them whole.
RegionFrame renderApron(const DrawnRegionCase& c, std::optional<FitView> frozenAt) {
    engine::EntityId camera = engine::kNoEntity;
    const engine::Scene scene = mergedApron(camera, c.target);
    ShadowSettings settings;
    settings.technique = c.technique;
    settings.cascadeCount = c.cascadeCount;
    settings.momentBlurRadius = c.momentBlurRadius;
    settings.resolution = 1024;
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    module.setFitView(frozenAt);
    engine::RenderTarget target({320, 240});
    engine.renderFrame(scene, camera, target);
    return {target.readPixels(), module.lightProjections(0), module.stats()};
}

float regionArea(const LightProjection& map) {
    return (map.drawnRegion.z - map.drawnRegion.x) * (map.drawnRegion.w - map.drawnRegion.y);
}

class DrawnRegion : public ::testing::TestWithParam<DrawnRegionCase> {};

} // namespace

// Casters drawn only within the reach of the visible samples' lookups (LightProjection::drawnRegion) give the
// image of the same maps drawn whole, each technique's kernel, blur and penumbra reach included.
TEST_P(DrawnRegion, ChangesNoImage) {
    glTestContext();
    const DrawnRegionCase& c = GetParam();
    FitView cameraView;
    {
        engine::EntityId camera = engine::kNoEntity;
        const engine::Scene scene = mergedApron(camera, c.target);
        engine::Engine engine;
        auto& probe = static_cast<SampleProbe&>(engine.addModule(std::make_unique<SampleProbe>()));
        engine::RenderTarget target({320, 240});
        engine.renderFrame(scene, camera, target);
        cameraView = FitView{probe.view, probe.projection};
    }
    const RegionFrame scissored = renderApron(c, std::nullopt);
    const RegionFrame whole = renderApron(c, cameraView);
    ASSERT_FALSE(scissored.maps.empty());
    ASSERT_EQ(scissored.maps.size(), whole.maps.size());
    // The comparison means something only where casters were left out of some map, and the image shows
    // shadow.
    float smallest = 1.0f;
    for (std::size_t map = 0; map < whole.maps.size(); ++map) {
        EXPECT_EQ(regionArea(whole.maps[map]), 1.0f) << c.name << " map " << map;
        EXPECT_EQ(scissored.maps[map].worldToShadow, whole.maps[map].worldToShadow)
            << c.name << " map " << map;
        smallest = std::min(smallest, regionArea(scissored.maps[map]));
    }
    std::cout << "[ measured ] " << c.name << ": " << scissored.maps.size()
              << " maps, the smallest drawn over " << smallest * 100.0f << " % of its texels\n";
    EXPECT_LT(smallest, 0.9f) << c.name;
    // The stats count the texels drawn: every one of the whole maps', fewer of the others'.
    const auto side = static_cast<std::size_t>(whole.stats.mapResolution);
    EXPECT_EQ(whole.stats.casterTexels, side * side * whole.maps.size()) << c.name;
    EXPECT_LT(scissored.stats.casterTexels, whole.stats.casterTexels) << c.name;
    EXPECT_GT(scissored.stats.casterTexels, 0u) << c.name;
    ASSERT_EQ(scissored.image.size, whole.image.size);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < scissored.image.pixels.size(); ++i) {
        differing += scissored.image.pixels[i] != whole.image.pixels[i];
    }
    EXPECT_EQ(differing, 0u) << c.name;
    const auto [darkest, brightest] =
        std::minmax_element(scissored.image.pixels.begin(), scissored.image.pixels.end());
    EXPECT_GT(*brightest - *darkest, 64) << c.name;
}

// Looking down 8 m ahead: one map; towards the horizon: the automatic cascades. The techniques: one
// comparison (slope-scaled, normal-offset and its receiver offset), PCF's kernel, GSM's and receiver-plane's
// gradients, EVSM's moments, unblurred (the default) and blurred over 3 texels, PCSS's search and msm-soft's
// moment mips (the soft reach).
INSTANTIATE_TEST_SUITE_P(
    , DrawnRegion,
    ::testing::Values(
        DrawnRegionCase{"near_slope_scaled", ShadowTechnique::SlopeScaledBias, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_normal_offset", ShadowTechnique::NormalOffset, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_pcf", ShadowTechnique::Pcf, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_gsm", ShadowTechnique::Gsm, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_receiver_plane", ShadowTechnique::ReceiverPlaneBias, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_evsm", ShadowTechnique::Evsm, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_evsm_blurred", ShadowTechnique::Evsm, {0.0f, 0.0f, -8.0f}, 1, 3},
        DrawnRegionCase{"near_pcss", ShadowTechnique::Pcss, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{"near_msm_soft", ShadowTechnique::MsmSoft, {0.0f, 0.0f, -8.0f}},
        DrawnRegionCase{
            "horizon_cascades_slope_scaled", ShadowTechnique::SlopeScaledBias, {0.0f, 0.0f, -60.0f}, 0},
        DrawnRegionCase{"horizon_cascades_pcf", ShadowTechnique::Pcf, {0.0f, 0.0f, -60.0f}, 0}),
    [](const auto& caseInfo) { return caseInfo.param.name; });

TEST(SampleDistributionGLTest, AViewWithNothingInItFallsBackToBoundsSayingSoOnce) {
    glTestContext();
    engine::EntityId camera = engine::kNoEntity;
    engine::Scene scene = mergedApron(camera, {0.0f, 50.0f, 0.1f}); // straight up at the sky
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>()));
    engine::RenderTarget target({160, 120});
    testing::internal::CaptureStderr();
    engine.renderFrame(scene, camera, target);
    engine.renderFrame(scene, camera, target);
    const std::string said = testing::internal::GetCapturedStderr();
    const std::string warning = "the view shows no surface to fit the directional maps to";
    ASSERT_NE(said.find(warning), std::string::npos) << said;
    EXPECT_EQ(said.find(warning), said.rfind(warning)) << "said more than once: " << said;
    EXPECT_TRUE(module.lightProjections(0).empty()); // the bounds fit sees no receiver either
    // Turned back to the ground, the samples fit takes over again.
    scene.entity(camera).transform = engine::Transform::lookAt({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, -60.0f});
    engine.renderFrame(scene, camera, target);
    EXPECT_FALSE(module.lightProjections(0).empty());
}
