// The shadow module inside the engine: every technique x light type x depth format compiles and renders the
// knob; resources and variants exist only for what the scene uses; the module also loads as a plugin.
#include "../engine/GLTestContext.h"
#include "../support/TestScenes.h"

#include <content/GltfLoader.h>
#include <engine/AddressSanitizer.h>
#include <engine/Engine.h>
#include <engine/Primitives.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/resource.h>

using namespace shadows;

namespace {

/// A box on a plane and a camera above them, looking down at the box (no light).
engine::Scene boxOnPlaneSeenFromAbove(engine::EntityId& camera) {
    engine::Scene scene = testsupport::boxOnPlane(10.0f, 1.0f);
    camera = scene.create("camera");
    scene.entity(camera).camera = engine::CameraComponent{};
    scene.entity(camera).transform = engine::Transform::lookAt({0, 5, 6}, {0, 0, 0});
    return scene;
}

/// The same under a sun.
engine::Scene boxOnPlaneUnderASun() {
    engine::EntityId camera = engine::kNoEntity;
    engine::Scene scene = boxOnPlaneSeenFromAbove(camera);
    const auto sun = scene.create("sun");
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).transform = engine::Transform::lookAt({-2, 5, 1}, {0, 0, 0});
    return scene;
}

content::LoadedScene knob(engine::LightType lightType) {
    content::SceneLoadOptions options;
    options.subdivisionLevel = 2; // enough curvature, fewer triangles for the 100+ renders below
    content::LoadedScene loaded =
        content::GltfLoader::load(std::filesystem::path(CONTENT_DIR) / "scenes" / "knob.gltf", options);
    if (lightType == engine::LightType::Spot) {
        loaded.scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
            if (e.light) {
                engine::Entity& light = loaded.scene.entity(id);
                light.light->type = engine::LightType::Spot;
                light.light->intensity = 40.0f;
                light.light->outerConeAngle = 0.5f;
                light.light->innerConeAngle = 0.4f;
                light.transform = engine::Transform::lookAt({3.0f, 4.0f, 2.0f}, {0.0f, 0.5f, 0.0f});
            }
        });
    }
    return loaded;
}

/// Renders and returns the shadow visibility of light 0 per pixel (debug view), checking it is finite in
/// [0,1].
std::vector<float> visibility(engine::Engine& engine, ShadowModule& module, const engine::Scene& scene,
                              ShadowSettings settings) {
    settings.debugView = ShadowDebugView::Visibility;
    module.setSettings(settings);
    engine::RenderTarget target({96, 72}, engine::ColorFormat::Rgba32F);
    engine.renderFrame(scene, *scene.firstCamera(), target);
    const std::vector<float> rgba = target.readPixelsFloat();
    std::vector<float> values;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        values.push_back(rgba[i]);
    }
    return values;
}

struct VariantCase {
    std::string name;
    ShadowSettings settings;
};

std::vector<VariantCase> everyTechniqueLightAndFormat() {
    std::vector<VariantCase> cases;
    for (const ShadowTechnique technique : allTechniques()) {
        for (const DepthFormat format : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
            ShadowSettings settings;
            settings.technique = technique;
            settings.depthFormat = format;
            settings.resolution = 256;
            std::string name(toString(technique));
            name += "_";
            name += toString(format);
            std::replace(name.begin(), name.end(), '-', '_');
            cases.push_back({name, settings});
        }
    }
    // Options that change the shader variant.
    auto with = [&](const std::string& name, auto change) {
        ShadowSettings settings;
        settings.resolution = 256;
        change(settings);
        cases.push_back({name, settings});
    };
    for (const GradientSource source : {GradientSource::StoredDerivatives, GradientSource::CentralDifferences,
                                        GradientSource::ScreenSpace}) {
        with(std::string("gsm_gradient_") + std::string(toString(source)), [&](ShadowSettings& s) {
            s.technique = ShadowTechnique::Gsm;
            s.gradientSource = source;
        });
        with(std::string("point_gradient_") + std::string(toString(source)), [&](ShadowSettings& s) {
            s.technique = ShadowTechnique::PcfGsmPointGradient;
            s.gradientSource = source;
        });
    }
    with("average_circular8",
         [](ShadowSettings& s) { s.averageGradientForm = AverageGradientForm::Circular8; });
    with("average_circular8_vec4",
         [](ShadowSettings& s) { s.averageGradientForm = AverageGradientForm::Circular8Vec4; });
    with("average_poisson64_rotated", [](ShadowSettings& s) {
        s.pcfLayout = TapLayout::Poisson;
        s.pcfTaps = 64;
        s.pcfRadius = 3.0f;
        s.pcfRotate = true;
    });
    with("quadratic_grid8", [](ShadowSettings& s) {
        s.technique = ShadowTechnique::PcfGsmQuadratic;
        s.pcfTaps = 8;
        s.pcfRadius = 3.5f;
    });
    with("pcf_poisson_rotated", [](ShadowSettings& s) {
        s.technique = ShadowTechnique::Pcf;
        s.pcfLayout = TapLayout::Poisson;
        s.pcfTaps = 32;
        s.pcfRotate = true;
    });
    with("receiver_plane_per_tap", [](ShadowSettings& s) {
        s.technique = ShadowTechnique::ReceiverPlaneBias;
        s.receiverPlaneKernel = ReceiverPlaneKernel::PerTap;
        s.receiverPlaneClamp = false;
    });
    with("hard_floor_back_faces", [](ShadowSettings& s) {
        s.technique = ShadowTechnique::HardCompare;
        s.floorReceiverDepth = true;
        s.casterFaces = CasterFaces::Back;
    });
    return cases;
}

class ShadowVariantGLTest : public testing::TestWithParam<VariantCase> {};

} // namespace

TEST_P(ShadowVariantGLTest, RendersKnobWithDirectionalAndSpotLights) {
    glTestContext();
    for (const engine::LightType lightType : {engine::LightType::Directional, engine::LightType::Spot}) {
        const content::LoadedScene loaded = knob(lightType);
        engine::Engine engine;
        auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>()));
        const std::vector<float> values = visibility(engine, module, loaded.scene, GetParam().settings);
        EXPECT_EQ(module.stats().shadowMaps, 1);
        std::size_t shadowed = 0;
        for (const float v : values) {
            ASSERT_TRUE(std::isfinite(v));
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
            shadowed += v < 0.5f;
        }
        // The knob's own shadow on the ground is always in view.
        EXPECT_GT(shadowed, values.size() / 50)
            << (lightType == engine::LightType::Spot ? "spot" : "directional");
        // Normal shading of the same variant compiles and draws too.
        ShadowSettings shaded = GetParam().settings;
        module.setSettings(shaded);
        engine::RenderTarget target({96, 72});
        EXPECT_NO_THROW(engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target));
    }
}

INSTANTIATE_TEST_SUITE_P(Variants, ShadowVariantGLTest, testing::ValuesIn(everyTechniqueLightAndFormat()),
                         [](const auto& test) { return test.param.name; });

TEST(ShadowModuleGLTest, DebugViewsCompileAndDiffer) {
    glTestContext();
    const content::LoadedScene loaded = knob(engine::LightType::Directional);
    engine::Engine engine;
    ShadowSettings settings;
    settings.resolution = 256;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    std::vector<std::vector<std::uint8_t>> images;
    for (const ShadowDebugView view :
         {ShadowDebugView::None, ShadowDebugView::TexelCheckerboard, ShadowDebugView::GradientMagnitude,
          ShadowDebugView::Bias, ShadowDebugView::Visibility, ShadowDebugView::ShadowMap}) {
        settings.debugView = view;
        settings.technique = view == ShadowDebugView::Bias ? ShadowTechnique::ReceiverPlaneBias
                                                           : ShadowTechnique::PcfGsmAverageGradient;
        settings.gradientSource = GradientSource::ScreenSpace;
        module.setSettings(settings);
        engine::RenderTarget target({64, 48});
        engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
        images.push_back(target.readPixels().pixels);
    }
    for (std::size_t a = 0; a < images.size(); ++a) {
        for (std::size_t b = a + 1; b < images.size(); ++b) {
            EXPECT_NE(images[a], images[b]) << "debug views " << a << " and " << b << " look the same";
        }
    }
}

TEST(ShadowModuleGLTest, ADirectionalMapTakesTheSideItsViewNeeds) {
    glTestContext();
    engine::Scene scene = boxOnPlaneUnderASun();
    const engine::EntityId camera = *scene.firstCamera();
    engine::Engine engine;
    ShadowSettings settings;
    settings.cascadeCount = 1;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    const auto sideAt = [&](glm::ivec2 size) {
        engine::RenderTarget target(size);
        engine.renderFrame(scene, camera, target);
        return module.stats().mapResolution;
    };
    // Texels of at most a quarter of a pixel where the view is nearest: a small view asks for a small map, a
    // larger one for more, never beyond `resolution`, and the memory follows.
    const int small = sideAt({64, 48});
    const std::size_t smallBytes = module.stats().bytes;
    const int large = sideAt({640, 480});
    std::cout << "[ measured ] box on a plane: map " << small << "² at 64x48, " << large << "² at 640x480\n";
    EXPECT_LT(small, large);
    EXPECT_LE(large, settings.resolution);
    EXPECT_EQ(smallBytes, static_cast<std::size_t>(small) * static_cast<std::size_t>(small) * 4u); // D24
    EXPECT_EQ(small & (small - 1), 0) << "a power of two";
    // 0 keeps `resolution`, as does a frame whose array also holds a spot light's map.
    settings.fittedTexelPixels = 0.0f;
    module.setSettings(settings);
    EXPECT_EQ(sideAt({64, 48}), settings.resolution);
    settings.fittedTexelPixels = ShadowSettings{}.fittedTexelPixels;
    module.setSettings(settings);
    const auto spot = scene.create("spot");
    scene.entity(spot).light = engine::LightComponent{};
    scene.entity(spot).light->type = engine::LightType::Spot;
    scene.entity(spot).transform = engine::Transform::lookAt({2, 5, 1}, {0, 0, 0});
    EXPECT_EQ(sideAt({64, 48}), settings.resolution);
}

/// A still scene, and one change to what its maps are drawn from.
struct MapInputChange {
    const char* name;
    void (*apply)(engine::Scene& scene, glm::ivec2& size);
};

class KeptMapsGLTest : public ::testing::TestWithParam<MapInputChange> {};

/// What `engine` renders of `scene` at `size` (RGBA floats; the visibility debug view where its module shows
/// it).
std::vector<float> visibilityImage(engine::Engine& engine, const engine::Scene& scene, glm::ivec2 size) {
    engine::RenderTarget target(size, engine::ColorFormat::Rgba32F);
    engine.renderFrame(scene, *scene.firstCamera(), target);
    return target.readPixelsFloat();
}

/// What a module with `settings` that redraws its maps every frame renders of `scene` at `size`.
std::vector<float> redrawnImage(const engine::Scene& scene, glm::ivec2 size, ShadowSettings settings) {
    settings.reuseUnchangedMaps = false;
    engine::Engine reference;
    reference.addModule(std::make_unique<ShadowModule>(settings));
    return visibilityImage(reference, scene, size);
}

TEST_P(KeptMapsGLTest, AStillViewKeepsItsMapsUntilWhatTheyAreDrawnFromChanges) {
    glTestContext();
    engine::Scene scene = boxOnPlaneUnderASun();
    glm::ivec2 size{96, 72};
    ShadowSettings settings;
    settings.debugView = ShadowDebugView::Visibility;
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    // Every frame drawing its maps: what each frame must look like.
    const auto redrawn = [&] { return redrawnImage(scene, size, settings); };

    visibilityImage(engine, scene, size);
    EXPECT_FALSE(module.stats().reusedMaps) << "the first frame draws its maps";
    EXPECT_EQ(visibilityImage(engine, scene, size), redrawn());
    EXPECT_TRUE(module.stats().reusedMaps) << "the same frame again keeps them";

    GetParam().apply(scene, size);
    const std::vector<float> changed = visibilityImage(engine, scene, size);
    EXPECT_FALSE(module.stats().reusedMaps) << GetParam().name;
    EXPECT_EQ(changed, redrawn()) << GetParam().name;
    EXPECT_EQ(visibilityImage(engine, scene, size), changed);
    EXPECT_TRUE(module.stats().reusedMaps) << "still again after " << GetParam().name;
}

INSTANTIATE_TEST_SUITE_P(
    EveryInput, KeptMapsGLTest,
    ::testing::Values(
        MapInputChange{"CameraMoves",
                       [](engine::Scene& scene, glm::ivec2&) {
                           scene.entity(*scene.firstCamera()).transform =
                               engine::Transform::lookAt({1, 4, 6}, {0, 0, 0});
                       }},
        MapInputChange{"CasterMoves",
                       [](engine::Scene& scene, glm::ivec2&) {
                           scene.entity(*scene.find("box")).transform.translation.x += 1.0f;
                       }},
        MapInputChange{"MeshReplaced",
                       [](engine::Scene& scene, glm::ivec2&) {
                           scene.entity(*scene.find("box")).mesh = engine::MeshComponent{
                               std::make_shared<engine::MeshData>(engine::primitives::cube(2.0f))};
                       }},
        MapInputChange{
            "SunTurns",
            [](engine::Scene& scene, glm::ivec2&) {
                scene.entity(*scene.find("sun")).transform = engine::Transform::lookAt({2, 5, -1}, {0, 0, 0});
            }},
        MapInputChange{"SunGrowsSofter",
                       [](engine::Scene& scene, glm::ivec2&) {
                           scene.entity(*scene.find("sun")).light->angularDiameter *= 4.0f;
                       }},
        MapInputChange{"SunStopsCasting",
                       [](engine::Scene& scene, glm::ivec2&) {
                           scene.entity(*scene.find("sun")).light->castsShadows = false;
                       }},
        MapInputChange{"ViewResized",
                       [](engine::Scene&, glm::ivec2& size) {
                           size = {64, 48};
                       }}),
    [](const ::testing::TestParamInfo<MapInputChange>& change) { return std::string(change.param.name); });

/// What a walk of the camera did with the maps: frames that kept them, and frames that left a kept placement.
struct Walk {
    int kept = 0;
    int drawnAfterKept = 0;
};

/// Walks the camera of `scene` `steps` times by `step` with the default settings, each frame's visibility
/// within one pixel in a thousand of a module that redraws its maps every frame.
Walk walkComparedWithRedrawing(engine::Scene& scene, glm::ivec2 size, glm::vec3 step, int steps) {
    ShadowSettings settings;
    settings.debugView = ShadowDebugView::Visibility;
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    const auto redrawn = [&] { return redrawnImage(scene, size, settings); };
    const auto differing = [](const std::vector<float>& a, const std::vector<float>& b) {
        std::size_t count = 0;
        for (std::size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4) {
            count += std::abs(a[i] - b[i]) > 0.5f / 255.0f ? 1 : 0;
        }
        return count;
    };
    const engine::EntityId camera = *scene.firstCamera();
    visibilityImage(engine, scene, size);
    Walk walk;
    bool keptLast = false;
    for (int frame = 1; frame <= steps; ++frame) {
        scene.entity(camera).transform.translation += step;
        const std::vector<float> image = visibilityImage(engine, scene, size);
        const ShadowStats stats = module.stats();
        EXPECT_FALSE(stats.reusedMaps) << frame;
        if (stats.keptMaps) {
            ++walk.kept;
            EXPECT_EQ(stats.casters.drawCalls, 0u) << frame;
        } else {
            walk.drawnAfterKept += keptLast ? 1 : 0;
        }
        keptLast = stats.keptMaps;
        EXPECT_LE(differing(image, redrawn()), static_cast<std::size_t>(size.x * size.y) / 1000) << frame;
    }
    return walk;
}

// A moving view keeps whole maps where they were placed while that holds its samples at the same texel size:
// the fit lands on the same texel grid, so each frame shows what one that redraws its maps does (but where
// the depth range's steps differ); a view that leaves the placement draws them again.
TEST(ShadowModuleGLTest, AMovingViewKeepsItsMapsWhileTheirPlacementsHoldItsSamples) {
    glTestContext();
    engine::Scene scene = boxOnPlaneUnderASun();
    const Walk walk = walkComparedWithRedrawing(scene, {96, 72}, {0.05f, 0.0f, 0.0f}, 40);
    std::cout << "[ measured ] 40 steps of 5 cm: " << walk.kept << " kept the maps, " << walk.drawnAfterKept
              << " left a kept placement\n";
    EXPECT_GE(walk.kept, 20) << "most small steps stay within the placement";
    EXPECT_GE(walk.drawnAfterKept, 1) << "the walk leaves a placement";

    ShadowSettings settings;
    settings.debugView = ShadowDebugView::Visibility;
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    const glm::ivec2 size{96, 72};
    visibilityImage(engine, scene, size);
    const engine::EntityId camera = *scene.firstCamera();
    scene.entity(camera).transform.translation += glm::vec3(0.02f, 0.0f, 0.0f);
    visibilityImage(engine, scene, size);
    EXPECT_TRUE(module.stats().keptMaps);
    // A still frame after a kept one keeps everything, as after a drawn one.
    visibilityImage(engine, scene, size);
    EXPECT_TRUE(module.stats().reusedMaps);
    scene.entity(camera).transform = engine::Transform::lookAt({1, 4, 6}, {0, 0, 0});
    visibilityImage(engine, scene, size);
    EXPECT_FALSE(module.stats().keptMaps) << "a view beyond the placement";
    // Without reuse, every frame draws its maps, however little the view moves.
    settings.reuseUnchangedMaps = false;
    module.setSettings(settings);
    visibilityImage(engine, scene, size);
    scene.entity(camera).transform.translation += glm::vec3(0.02f, 0.0f, 0.0f);
    visibilityImage(engine, scene, size);
    EXPECT_FALSE(module.stats().keptMaps) << "reuseUnchangedMaps off";
}

class MovingViewGLTest : public ::testing::TestWithParam<const char*> {};

// Every kind of map a moving view may keep: a sun's cascades (outdoor), a spot light's map (spheres), point
// lights' cube faces (room). Each frame of a walk matches a module that redraws every frame.
TEST_P(MovingViewGLTest, KeptMapsMatchRedrawnOnes) {
    glTestContext();
    content::SceneLoadOptions options;
    options.subdivisionLevel = 1;
    content::LoadedScene loaded = content::GltfLoader::load(
        std::filesystem::path(CONTENT_DIR) / "scenes" / (std::string(GetParam()) + ".gltf"), options);
    const engine::EntityId camera = *loaded.scene.firstCamera();
    const glm::vec3 forward = -glm::vec3(loaded.scene.worldMatrix(camera)[2]);
    const Walk walk = walkComparedWithRedrawing(loaded.scene, {96, 72}, 0.02f * glm::normalize(forward), 12);
    std::cout << "[ measured ] " << GetParam() << ": 12 steps of 2 cm, " << walk.kept << " kept the maps\n";
    EXPECT_GE(walk.kept, 1) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(EveryMapKind, MovingViewGLTest, ::testing::Values("outdoor", "spheres", "room"),
                         [](const ::testing::TestParamInfo<const char*>& scene) {
                             return std::string(scene.param);
                         });

// Walking along a row of casters, the view reads more of the map each step: a map drawn again where it lay is
// drawn a margin beyond what the view reads, so the next steps keep it (none does without the margin). The
// samples span the map's width, so every few steps they leave the placement.
TEST(ShadowModuleGLTest, AMovingViewThatReadsMoreOfAMapDrawsAMarginBeyondIt) {
    glTestContext();
    engine::Scene scene = testsupport::boxOnPlane(400.0f, 1.0f);
    std::vector<testsupport::Block> row;
    for (int i = 1; i < 40; ++i) {
        const float z = -4.0f * static_cast<float>(i);
        row.push_back({{-3.0f, 0.0f, z}, {-2.0f, 1.5f, z + 1.0f}});
        row.push_back({{2.0f, 0.0f, z - 2.0f}, {3.0f, 1.0f, z - 1.0f}});
    }
    testsupport::addBlocks(scene, row);
    const auto sun = scene.create("sun");
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).transform = engine::Transform::lookAt({-2, 3, 1}, {0, 0, 0});
    const auto camera = scene.create("camera");
    scene.entity(camera).camera = engine::CameraComponent{};
    scene.entity(camera).transform = engine::Transform::lookAt({0, 2, 4}, {0, 0.5f, -20});
    const Walk walk = walkComparedWithRedrawing(scene, {96, 72}, {0.0f, 0.0f, -0.05f}, 30);
    std::cout << "[ measured ] 30 steps of 5 cm along the row: " << walk.kept << " kept the maps\n";
    EXPECT_GE(walk.kept, 6);
}

TEST(ShadowModuleGLTest,
     MapsAreRedrawnAfterASettingsChangeAndEveryFrameWithoutReuseVirtualOnesKeptAfterAnIdleUpdate) {
    glTestContext();
    engine::Scene scene = boxOnPlaneUnderASun();
    ShadowSettings settings;
    settings.debugView = ShadowDebugView::Visibility;
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    visibilityImage(engine, scene, {64, 48});
    visibilityImage(engine, scene, {64, 48});
    EXPECT_TRUE(module.stats().reusedMaps);
    settings.resolution = 1024;
    module.setSettings(settings);
    visibilityImage(engine, scene, {64, 48});
    EXPECT_FALSE(module.stats().reusedMaps) << "a settings change";
    settings.reuseUnchangedMaps = false;
    module.setSettings(settings);
    for (int frame = 0; frame < 3; ++frame) {
        visibilityImage(engine, scene, {64, 48});
        EXPECT_FALSE(module.stats().reusedMaps) << "frame " << frame << " with reuseUnchangedMaps off";
    }
    // Virtual maps: the first frame draws pages, the second updates them and draws none, the third keeps
    // them, with the image and page counters of an update.
    settings.mapAllocation = MapAllocation::Virtual;
    module.setSettings(settings);
    visibilityImage(engine, scene, {64, 48});
    EXPECT_GT(module.stats().pages.rendered, 0);
    const std::vector<float> updated = visibilityImage(engine, scene, {64, 48});
    EXPECT_FALSE(module.stats().reusedMaps) << "virtual maps without reuse";
    EXPECT_EQ(module.stats().pages.rendered, 0);
    settings.reuseUnchangedMaps = true;
    module.setSettings(settings);
    visibilityImage(engine, scene, {64, 48});
    visibilityImage(engine, scene, {64, 48});
    EXPECT_FALSE(module.stats().reusedMaps) << "virtual maps keep pages only after an update that drew none";
    EXPECT_EQ(visibilityImage(engine, scene, {64, 48}), updated);
    EXPECT_TRUE(module.stats().reusedMaps) << "virtual maps' third still frame";
    EXPECT_EQ(module.stats().pages.rendered, 0);
}

class PartTimingGLTest : public ::testing::TestWithParam<MapAllocation> {};

// The pre-pass's parts lie within the pass the engine times around them; a frame that keeps its maps spends
// nothing in either, and with part timing off neither is measured.
TEST_P(PartTimingGLTest, SplitsThePrePassIntoTheFitAndTheMaps) {
    glTestContext();
    engine::Scene scene = boxOnPlaneUnderASun();
    ShadowSettings settings;
    settings.mapAllocation = GetParam();
    engine::Engine engine;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    engine::RenderTarget target({64, 48});
    engine.renderFrame(scene, *scene.firstCamera(), target);
    EXPECT_LT(module.stats().fitMilliseconds, 0.0) << "part timing is off by default";
    EXPECT_LT(module.stats().mapsMilliseconds, 0.0);

    const engine::TimingMethod method = engine::PassTimer::methodFor(glTestContext());
    engine.setPassTiming(method);
    module.setPartTiming(method);
    scene.entity(*scene.find("box")).transform.translation.x += 0.5f; // the maps are drawn anew
    const engine::FrameStats drawn = engine.renderFrame(scene, *scene.firstCamera(), target);
    const ShadowStats parts = module.stats();
    ASSERT_FALSE(parts.reusedMaps);
    EXPECT_GE(parts.fitMilliseconds, 0.0);
    EXPECT_GE(parts.mapsMilliseconds, 0.0);
    EXPECT_LE(parts.fitMilliseconds + parts.mapsMilliseconds, drawn.prePassMilliseconds);

    engine.renderFrame(scene, *scene.firstCamera(), target);
    engine.renderFrame(scene, *scene.firstCamera(), target); // virtual maps keep theirs after an idle update
    ASSERT_TRUE(module.stats().reusedMaps);
    EXPECT_EQ(module.stats().fitMilliseconds, 0.0);
    EXPECT_EQ(module.stats().mapsMilliseconds, 0.0);

    module.setPartTiming(std::nullopt);
    EXPECT_LT(module.stats().fitMilliseconds, 0.0);
    engine.renderFrame(scene, *scene.firstCamera(), target);
    EXPECT_LT(module.stats().mapsMilliseconds, 0.0);
}

INSTANTIATE_TEST_SUITE_P(ShadowModuleGLTest, PartTimingGLTest,
                         ::testing::Values(MapAllocation::Fitted, MapAllocation::Virtual),
                         [](const ::testing::TestParamInfo<MapAllocation>& allocation) {
                             return allocation.param == MapAllocation::Fitted ? "Fitted" : "Virtual";
                         });

TEST(ShadowModuleGLTest, ResourcesOnlyForShadowCastingLights) {
    glTestContext();
    engine::EntityId camera = engine::kNoEntity;
    engine::Scene scene = boxOnPlaneSeenFromAbove(camera);

    engine::Engine engine;
    ShadowSettings settings;
    settings.resolution = 128;
    settings.fittedTexelPixels = 0.0f; // maps of `resolution`, however little the 32x32 view needs
    settings.depthFormat = DepthFormat::D16;
    settings.technique = ShadowTechnique::HardCompare;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    engine::RenderTarget target({32, 32});

    // No lights: no maps, no shadow variant, no depth program.
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().shadowMaps, 0);
    EXPECT_EQ(module.stats().bytes, 0u);
    EXPECT_EQ(engine.programs().compileCount(), 1u);

    // A light that does not cast shadows changes nothing of the module's (the engine's variant for one light
    // is compiled: the light count is part of the variant).
    const auto lamp = scene.create("lamp");
    scene.entity(lamp).light = engine::LightComponent{};
    scene.entity(lamp).light->castsShadows = false;
    scene.entity(lamp).transform = engine::Transform::lookAt({2, 5, 1}, {0, 0, 0});
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().shadowMaps, 0);
    EXPECT_EQ(engine.programs().compileCount(), 2u);

    // Two casting lights: two D16 maps, one shadowed lighting variant plus the depth program, and the
    // lighting pass's depth pre-pass, which the sample pass takes (ModuleHost::viewDepth).
    for (const char* name : {"sun", "moon"}) {
        const auto light = scene.create(name);
        scene.entity(light).light = engine::LightComponent{};
        scene.entity(light).transform =
            engine::Transform::lookAt({-2, 5, std::string(name) == "sun" ? 1.0f : -1.0f}, {0, 0, 0});
    }
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().shadowMaps, 2);
    EXPECT_EQ(module.stats().bytes, 2u * 128u * 128u * 2u);
    EXPECT_EQ(engine.programs().compileCount(), 5u);
    EXPECT_EQ(module.lightProjection(0), std::nullopt); // the lamp casts no shadow
    EXPECT_TRUE(module.lightProjection(1).has_value());

    // One stops casting: its map is released.
    scene.entity(*scene.find("moon")).light->castsShadows = false;
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().shadowMaps, 1);

    // Stored gradients allocate their RG32F target only when a technique reads them; settings apply lazily.
    settings.technique = ShadowTechnique::Gsm;
    settings.gradientSource = GradientSource::StoredDerivatives;
    module.setSettings(settings);
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().bytes, 128u * 128u * (2u + 8u));
    settings.gradientSource = GradientSource::CentralDifferences;
    module.setSettings(settings);
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().bytes, 128u * 128u * 2u);
}

// Every light the renderer takes may be a point light casting from all its faces: 48 map slots. With 24, the
// lights past the fourth cast no shadow.
TEST(ShadowModuleGLTest, EveryLightMayBeAPointLight) {
    glTestContext();
    engine::EntityId camera = engine::kNoEntity;
    engine::Scene scene = boxOnPlaneSeenFromAbove(camera);
    for (int light = 0; light < engine::ForwardRenderer::kMaxLights; ++light) {
        const auto lamp = scene.create("lamp " + std::to_string(light));
        engine::LightComponent point;
        point.type = engine::LightType::Point;
        point.intensity = 2.0f;
        scene.entity(lamp).light = point;
        const float angle = 0.785f * static_cast<float>(light);
        scene.entity(lamp).transform.translation = {1.5f * std::cos(angle), 1.0f, 1.5f * std::sin(angle)};
    }
    engine::Engine engine;
    ShadowSettings settings;
    settings.resolution = 64;
    settings.depthFormat = DepthFormat::D16;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    engine::RenderTarget target({32, 32});
    engine.renderFrame(scene, camera, target);
    EXPECT_GT(module.stats().shadowMaps, 24);
    EXPECT_EQ(module.stats().bytes, static_cast<std::size_t>(module.stats().shadowMaps) * 64u * 64u * 2u);
    for (int light = 0; light < engine::ForwardRenderer::kMaxLights; ++light) {
        EXPECT_TRUE(module.lightProjection(light).has_value()) << "light " << light;
    }
}

// Whole maps over fittedBudgetMiB take the largest side that fits, as if asked for: two point lights' 12 EVSM
// faces at 512² would take 60 MiB; in 16 MiB they are drawn at 256², the image that resolution 256 gives.
TEST(ShadowModuleGLTest, MapsOverTheFittedBudgetTakeTheSideThatFitsAndSaySo) {
    glTestContext();
    engine::EntityId camera = engine::kNoEntity;
    engine::Scene scene = boxOnPlaneSeenFromAbove(camera);
    for (int light = 0; light < 2; ++light) {
        const auto lamp = scene.create("lamp " + std::to_string(light));
        engine::LightComponent point;
        point.type = engine::LightType::Point;
        scene.entity(lamp).light = point;
        scene.entity(lamp).transform.translation = {light == 0 ? 1.5f : -1.0f, 1.2f,
                                                    light == 0 ? 0.5f : -1.0f};
    }
    const auto render = [&](int resolution, int budgetMiB, ShadowStats& stats) {
        engine::Engine engine;
        ShadowSettings settings;
        settings.technique = ShadowTechnique::Evsm;
        settings.resolution = resolution;
        settings.fittedBudgetMiB = budgetMiB;
        auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
        engine::RenderTarget target({64, 64});
        engine.renderFrame(scene, camera, target);
        stats = module.stats();
        return target.readPixels();
    };
    ShadowStats budgeted;
    testing::internal::CaptureStderr();
    const engine::Image within = render(512, 16, budgeted);
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("fittedBudgetMiB 16"), std::string::npos) << said;
    EXPECT_NE(said.find("drawn at 256²"), std::string::npos) << said;
    EXPECT_EQ(budgeted.mapResolution, 256);
    EXPECT_LE(budgeted.bytes, std::size_t(16) << 20);
    EXPECT_GT(budgeted.shadowMaps, 2);

    ShadowStats asked;
    testing::internal::CaptureStderr();
    const engine::Image at256 = render(256, 1024, asked);
    EXPECT_EQ(testing::internal::GetCapturedStderr().find("fittedBudgetMiB"), std::string::npos);
    EXPECT_EQ(asked.mapResolution, 256);
    EXPECT_EQ(asked.shadowMaps, budgeted.shadowMaps);
    EXPECT_EQ(within.pixels, at256.pixels);

    // The budget that holds the twelve faces at 512² leaves them there.
    ShadowStats roomy;
    render(512, 64, roomy);
    EXPECT_EQ(roomy.mapResolution, 512);
}

#if !defined(GS_ADDRESS_SANITIZER)
/// The process's address space (/proc/self/status VmSize), bytes; 0 where it cannot be read.
std::size_t addressSpaceBytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmSize:", 0) == 0) {
            return std::stoull(line.substr(7)) << 10; // kB
        }
    }
    return 0;
}

/// Holds the address space to `bytes` for its life, so that the driver's allocations beyond it fail.
class AddressSpaceLimit {
public:
    explicit AddressSpaceLimit(std::size_t bytes) {
        getrlimit(RLIMIT_AS, &before_);
        rlimit limited = before_;
        limited.rlim_cur = bytes;
        setrlimit(RLIMIT_AS, &limited);
    }
    ~AddressSpaceLimit() { setrlimit(RLIMIT_AS, &before_); }
    AddressSpaceLimit(const AddressSpaceLimit&) = delete;
    AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;

private:
    rlimit before_{};
};
#endif

TEST(ShadowModuleGLTest, MapsTheDriverCannotAllocateTakeTheSideItCanAndSaySo) {
#if defined(GS_ADDRESS_SANITIZER)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no limit on it leaves it working";
#else
    glTestContext();
    const engine::Scene scene = boxOnPlaneUnderASun();
    const engine::EntityId camera = *scene.firstCamera();
    const auto settingsAt = [](int resolution) {
        ShadowSettings settings;
        settings.technique = ShadowTechnique::HardCompare;
        settings.resolution = resolution;
        settings.fittedTexelPixels = 0.0f; // the map takes `resolution`, whatever the view needs
        settings.fittedBudgetMiB = 65536;
        return settings;
    };
    engine::Engine engine;
    auto& module =
        static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settingsAt(256))));
    engine::RenderTarget target({64, 64});
    engine.renderFrame(scene, camera, target); // the shaders compiled before the limit
    ASSERT_GT(addressSpaceBytes(), 0u);

    // 16384² D24 takes 1 GiB: with half of that left to the driver, it cannot have it, and 8192² (256 MiB)
    // it can.
    module.setSettings(settingsAt(16384));
    testing::internal::CaptureStderr();
    {
        const AddressSpaceLimit limit(addressSpaceBytes() + (std::size_t(512) << 20));
        engine.renderFrame(scene, camera, target);
    }
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("the shadow maps, 1 layer of 16384² (1024 MiB), could not be allocated"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("drawn at 8192² while these settings hold"), std::string::npos) << said;
    EXPECT_EQ(module.stats().mapResolution, 8192);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const engine::Image fallen = target.readPixels();

    // The next frame keeps the side that held, without asking again.
    testing::internal::CaptureStderr();
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(module.stats().mapResolution, 8192);

    // What the side that held draws is what asking for it draws.
    module.setSettings(settingsAt(8192));
    engine.renderFrame(scene, camera, target);
    EXPECT_EQ(module.stats().mapResolution, 8192);
    EXPECT_EQ(fallen.pixels, target.readPixels().pixels);
#endif
}

TEST(ShadowModuleGLTest, LoadsAsAPluginAndCastsShadows) {
    glTestContext();
    const content::LoadedScene loaded = knob(engine::LightType::Directional);
    engine::Engine plain;
    engine::RenderTarget target({96, 72});
    plain.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    const engine::Image without = target.readPixels();

    engine::Engine withPlugin;
    engine::Module& module = withPlugin.loadModule("shadows");
    EXPECT_EQ(module.name(), "shadows");
    withPlugin.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    const engine::Image with = target.readPixels();
    std::size_t darker = 0;
    for (std::size_t i = 0; i < with.pixels.size(); i += 4) {
        darker += with.pixels[i] + 20 < without.pixels[i];
    }
    EXPECT_GT(darker, with.pixels.size() / 4 / 50); // the knob's shadow on the ground
}

TEST(ShadowModuleGLTest, RefusesInvalidSettingsNamingEveryBadField) {
    ShadowSettings settings;
    settings.jitterTaps = 7;
    settings.momentBlurRadius = 17;
    try {
        ShadowModule module(settings);
        FAIL();
    } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        for (const char* field : {"jitterTaps", "momentBlurRadius"}) {
            EXPECT_NE(message.find(field), std::string::npos) << message;
        }
    }
}
