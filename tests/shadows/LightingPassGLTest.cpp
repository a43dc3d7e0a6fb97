// The lighting pass's lean paths change no image: the early out of receivers facing away from the light, on
// every map layout (one map, cascades, cube faces) and technique family, exactly; the orthographic lookups of
// frames whose maps are all directional, the vertex stage's projection, and the faces of closed meshes left
// out of the sample, caster and lighting passes, within float tolerance. Flat casters that shadow nothing,
// left out of the caster pass of techniques that only compare, only ever take away a false shadow. The sample
// pass taking the lighting pass's depth pre-pass changes lookups within float tolerance.
#include "../engine/GLTestContext.h"

#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <engine/SurfaceClosure.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

using namespace shadows;

namespace {

/// Adds one define to every lighting-pass variant: what the shader would be without a lean path.
class DefineModule final : public engine::Module {
public:
    explicit DefineModule(std::string define) : define_(std::move(define)) {}
    [[nodiscard]] std::string_view name() const override { return "define"; }
    void attach(engine::ModuleHost& host) override { host_ = &host; }
    [[nodiscard]] engine::ShaderVariantKey variantBits(const engine::DrawContext&) const override {
        return host_->variantFlag(define_);
    }

private:
    std::string define_;
    engine::ModuleHost* host_ = nullptr;
};

struct Shaded {
    engine::Image image;
    bool orthographicVariant = false; // the module asked for GS_SHADOW_ORTHOGRAPHIC
    bool vertexProjection =
        false; // a light's layout is one the vertex stage projects (vertex-projection.glsl)
};

/// The frame with the module's lean paths, or, given `generic`, with the define that restores the code they
/// replace.
Shaded shaded(const content::LoadedScene& loaded, ShadowSettings settings, const std::string& generic = {}) {
    engine::Engine engine;
    auto module = std::make_unique<ShadowModule>(settings);
    const ShadowModule& shadows = *module;
    engine.addModule(std::move(module));
    if (!generic.empty()) {
        engine.addModule(std::make_unique<DefineModule>(generic));
    }
    engine::RenderTarget target({160, 120});
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    const engine::FrameContext frame(loaded.scene);
    const engine::MeshData mesh;
    const engine::ShaderVariantKey bits =
        shadows.variantBits(engine::DrawContext{frame, engine::kNoEntity, mesh});
    const engine::ShaderVariantKey vertexLayouts = engine.variants().flag("GS_SHADOW_LAYOUT_SINGLE") |
                                                   engine.variants().flag("GS_SHADOW_LAYOUT_CASCADES") |
                                                   engine.variants().flag("GS_SHADOW_LAYOUT_VIRTUAL");
    return {target.readPixels(), (bits & engine.variants().flag("GS_SHADOW_ORTHOGRAPHIC")) != 0,
            (bits & vertexLayouts) != 0};
}

content::LoadedScene loadScene(const std::string& name) {
    content::SceneLoadOptions options;
    options.subdivisionLevel = 1;
    return content::GltfLoader::load(std::filesystem::path(CONTENT_DIR) / "scenes" / (name + ".gltf"),
                                     options);
}

/// The comparison means something only where the scene is lit and shadowed.
void expectLitAndShadowed(const engine::Image& image, const std::string& what) {
    const auto [darkest, brightest] = std::minmax_element(image.pixels.begin(), image.pixels.end());
    EXPECT_GT(*brightest - *darkest, 64) << what;
}

void expectSameImage(const engine::Image& lean, const engine::Image& full, const std::string& what) {
    ASSERT_EQ(lean.size, full.size);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < lean.pixels.size(); ++i) {
        differing += lean.pixels[i] != full.pixels[i];
    }
    EXPECT_EQ(differing, 0u) << what;
    expectLitAndShadowed(lean, what);
}

/// Pixels whose channels differ by more than 2 of 255 between the two images.
std::size_t differingPixels(const engine::Image& a, const engine::Image& b) {
    std::size_t differing = 0;
    for (std::size_t pixel = 0; pixel + 3 < a.pixels.size(); pixel += 4) {
        bool differs = false;
        for (std::size_t channel = 0; channel < 3; ++channel) {
            differs =
                differs || std::abs(int(a.pixels[pixel + channel]) - int(b.pixels[pixel + channel])) > 2;
        }
        differing += differs;
    }
    return differing;
}

/// Within float tolerance: a lookup on a texel's edge may round to its neighbour, a pixel in a thousand.
void expectSameLookups(const engine::Image& lean, const engine::Image& full, const std::string& what) {
    ASSERT_EQ(lean.size, full.size);
    EXPECT_LE(differingPixels(lean, full), lean.pixels.size() / 4 / 1000) << what;
    expectLitAndShadowed(lean, what);
}

struct LeanPathCase {
    std::string name;
    std::string scene;
    ShadowTechnique technique;
};

ShadowSettings settingsFor(const LeanPathCase& c) {
    ShadowSettings settings;
    settings.technique = c.technique;
    settings.resolution = 512;
    return settings;
}

std::string describe(const LeanPathCase& c) {
    return c.scene + " " + std::string(toString(c.technique));
}

std::vector<LeanPathCase> cases(std::initializer_list<const char*> scenes,
                                std::initializer_list<ShadowTechnique> techniques) {
    std::vector<LeanPathCase> result;
    for (const std::string scene : scenes) {
        for (const ShadowTechnique technique : techniques) {
            std::string name = scene + "_" + std::string(toString(technique));
            std::replace(name.begin(), name.end(), '-', '_');
            result.push_back({name, scene, technique});
        }
    }
    return result;
}

class FacingAwayEarlyOut : public ::testing::TestWithParam<LeanPathCase> {};

TEST_P(FacingAwayEarlyOut, ChangesNoImage) {
    glTestContext();
    const LeanPathCase& c = GetParam();
    const content::LoadedScene loaded = loadScene(c.scene);
    expectSameImage(shaded(loaded, settingsFor(c)).image,
                    shaded(loaded, settingsFor(c), "GS_SHADOW_KEEP_FACING_AWAY").image, describe(c));
}

class OrthographicLookups : public ::testing::TestWithParam<LeanPathCase> {};

TEST_P(OrthographicLookups, ChangesNoImage) {
    glTestContext();
    const LeanPathCase& c = GetParam();
    const content::LoadedScene loaded = loadScene(c.scene);
    const Shaded lean = shaded(loaded, settingsFor(c));
    // Every map of these scenes is a sun's: the variant is the orthographic one.
    EXPECT_TRUE(lean.orthographicVariant) << describe(c);
    // The orthographic lookups move a receiver towards the light in depth alone, the generic ones through the
    // matrix: the same within float tolerance.
    expectSameLookups(lean.image, shaded(loaded, settingsFor(c), "GS_SHADOW_KEEP_PERSPECTIVE").image,
                      describe(c));
}

TEST(OrthographicVariant, NotForPerspectiveMaps) {
    glTestContext();
    const content::LoadedScene loaded = loadScene("room");
    ShadowSettings settings;
    settings.resolution = 256;
    EXPECT_FALSE(shaded(loaded, settings).orthographicVariant);
}

struct ProjectionCase {
    std::string name;
    std::string scene;
    ShadowTechnique technique;
    int cascadeCount = 0;
    bool addSun = false; // a low sun beside the scene's own lights: its map is projected in the vertex stage
    MapAllocation maps = MapAllocation::Fitted;
};

void PrintTo(const ProjectionCase& c, std::ostream* out) {
    *out << c.name;
}

void addLowSun(content::LoadedScene& loaded) {
    const engine::EntityId sun = loaded.scene.create("vertex-projection sun");
    engine::Entity& entity = loaded.scene.entity(sun);
    entity.transform.rotation =
        glm::quatLookAt(glm::normalize(glm::vec3(0.6f, -0.45f, -0.5f)), glm::vec3(0, 1, 0));
    entity.light = engine::LightComponent{};
    entity.light->intensity = 2.0f;
}

class VertexProjection : public ::testing::TestWithParam<ProjectionCase> {};

// The debug views of the lookups (the texel grid under each pixel, the map's depth there, the visibility)
// agree with the fragment stage's projection.
TEST_P(VertexProjection, SameLookupsAsFragmentStage) {
    glTestContext();
    const ProjectionCase& c = GetParam();
    content::LoadedScene loaded = loadScene(c.scene);
    if (c.addSun) {
        addLowSun(loaded);
    }
    for (const ShadowDebugView view :
         {ShadowDebugView::TexelCheckerboard, ShadowDebugView::ShadowMap, ShadowDebugView::Visibility}) {
        ShadowSettings settings;
        settings.technique = c.technique;
        settings.resolution = 512;
        settings.cascadeCount = c.cascadeCount;
        settings.mapAllocation = c.maps;
        settings.debugView = view;
        const std::string what = c.name + " " + std::string(toString(view));
        const Shaded vertex = shaded(loaded, settings);
        EXPECT_TRUE(vertex.vertexProjection) << what;
        expectSameLookups(vertex.image, shaded(loaded, settings, "GS_SHADOW_FRAGMENT_PROJECTION").image,
                          what);
    }
}

struct HiddenFacesCase {
    std::string name;
    std::string scene;
    MapAllocation maps = MapAllocation::Fitted;
    bool mirrored = false; // every mesh mirrored in x: its winding turns over
};

void PrintTo(const HiddenFacesCase& c, std::ostream* out) {
    *out << c.name;
}

/// The frame with the hidden faces of closed meshes left out of every pass (the defaults), or drawn.
engine::Image withHiddenFaces(const content::LoadedScene& loaded, ShadowSettings settings, bool leftOut) {
    settings.casterFaces = leftOut ? CasterFaces::Auto : CasterFaces::Both;
    engine::Engine engine;
    engine.addModule(std::make_unique<ShadowModule>(settings));
    engine.renderer().lightingHiddenFaces = leftOut ? engine::HiddenFaces::Skip : engine::HiddenFaces::Draw;
    engine.renderer().leaveOutShadowlessChunks =
        false; // changes the map's depth under a ground: ShadowlessPlanes
    engine::RenderTarget target({160, 120});
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    return target.readPixels();
}

class HiddenFaces : public ::testing::TestWithParam<HiddenFacesCase> {};

// The depth each pass keeps is the nearest, which a closed mesh's faces turned away never are: the map's
// depth under each pixel, and the frame, agree with every face drawn.
TEST_P(HiddenFaces, LeftOutOfEveryPassChangeNoLookup) {
    glTestContext();
    const HiddenFacesCase& c = GetParam();
    content::LoadedScene loaded = loadScene(c.scene);
    bool closedPart = false;
    std::vector<engine::EntityId> meshes;
    loaded.scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh) {
            return;
        }
        for (const auto& part : engine::surfaceParts(*entity.mesh->mesh).parts) {
            closedPart = closedPart || part.closure != engine::SurfaceClosure::Open;
        }
        meshes.push_back(id);
    });
    for (const engine::EntityId id : meshes) {
        loaded.scene.entity(id).transform.scale.x *= c.mirrored ? -1.0f : 1.0f;
    }
    ASSERT_TRUE(closedPart) << c.name << ": the scene has no closed mesh to leave faces out of";
    for (const ShadowDebugView view : {ShadowDebugView::None, ShadowDebugView::ShadowMap}) {
        ShadowSettings settings;
        settings.resolution = 512;
        settings.mapAllocation = c.maps;
        settings.debugView = view;
        const std::string what = c.name + " " + std::string(toString(view));
        expectSameLookups(withHiddenFaces(loaded, settings, true), withHiddenFaces(loaded, settings, false),
                          what);
    }
}

const auto caseName = [](const auto& caseInfo) { return caseInfo.param.name; };

// knob: a sun's map; spheres: a spot's; room: two point lights' cube faces; outdoor: cascades; and virtual
// pages, and a mirrored scene, whose faces turned away wind the other way.
INSTANTIATE_TEST_SUITE_P(
    , HiddenFaces,
    ::testing::Values(HiddenFacesCase{"knob", "knob"}, HiddenFacesCase{"spheres", "spheres"},
                      HiddenFacesCase{"room", "room"}, HiddenFacesCase{"outdoor", "outdoor"},
                      HiddenFacesCase{"knob_virtual", "knob", MapAllocation::Virtual},
                      HiddenFacesCase{"room_virtual", "room", MapAllocation::Virtual},
                      HiddenFacesCase{"knob_mirrored", "knob", MapAllocation::Fitted, true},
                      HiddenFacesCase{"room_mirrored", "room", MapAllocation::Fitted, true}),
    caseName);

struct ShadowlessPlanesCase {
    std::string name;
    std::string scene;
    ShadowTechnique technique;
    MapAllocation maps = MapAllocation::Fitted;
    int cascadeCount = 0;
    bool leavesOut = true; // the technique leaves such planes out
};

void PrintTo(const ShadowlessPlanesCase& c, std::ostream* out) {
    *out << c.name;
}

struct CasterPass {
    engine::Image image;
    engine::DrawnMeshes casters;
};

/// The frame with flat casters that shadow nothing left out of the maps (the default), or drawn.
CasterPass withShadowlessPlanes(const content::LoadedScene& loaded, const ShadowSettings& settings,
                                bool leftOut) {
    engine::Engine engine;
    const auto& shadows =
        static_cast<const ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    engine.renderer().leaveOutShadowlessChunks = leftOut;
    engine::RenderTarget target({160, 120});
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    return {target.readPixels(), shadows.stats().casters};
}

class ShadowlessPlanes : public ::testing::TestWithParam<ShadowlessPlanesCase> {};

// Nothing lies behind such a plane as the light sees it, so a comparison that read it as nearer than the
// receiver was a false shadow (a kernel reaching across the receiver's own plane, a corner between walls):
// left out, a pixel only brightens, and few do. Techniques that read depth values keep the planes.
TEST_P(ShadowlessPlanes, LeftOutOfTheCasterPassOnlyTakeFalseShadowsAway) {
    glTestContext();
    const ShadowlessPlanesCase& c = GetParam();
    const content::LoadedScene loaded = loadScene(c.scene);
    ShadowSettings settings;
    settings.technique = c.technique;
    settings.resolution = 512;
    settings.mapAllocation = c.maps;
    settings.cascadeCount = c.cascadeCount;
    const CasterPass leftOut = withShadowlessPlanes(loaded, settings, true);
    const CasterPass drawn = withShadowlessPlanes(loaded, settings, false);
    EXPECT_EQ(drawn.casters.shadowlessChunks, 0u) << c.name;
    if (!c.leavesOut) {
        EXPECT_EQ(leftOut.casters.shadowlessChunks, 0u) << c.name;
        expectSameImage(leftOut.image, drawn.image, c.name);
        return;
    }
    EXPECT_GT(leftOut.casters.shadowlessChunks, 0u) << c.name;
    EXPECT_LT(leftOut.casters.triangles, drawn.casters.triangles) << c.name;
    std::size_t darker = 0;
    std::size_t brighter = 0;
    const std::size_t pixels = leftOut.image.pixels.size() / 4;
    for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
        int least = 0;
        int most = 0;
        for (std::size_t channel = 0; channel < 3; ++channel) {
            const std::size_t i = 4 * pixel + channel;
            const int change = int(leftOut.image.pixels[i]) - int(drawn.image.pixels[i]);
            least = std::min(least, change);
            most = std::max(most, change);
        }
        darker += least < -1 ? 1 : 0; // a unit of rounding either way
        brighter += most > 1 ? 1 : 0;
    }
    EXPECT_EQ(darker, 0u) << c.name;
    // A shadow a real caster casts, taken away, would brighten far more.
    EXPECT_LE(brighter, pixels / 100) << c.name;
    expectLitAndShadowed(leftOut.image, c.name);
}

// knob: a sun over a ground, fitted, cascaded and on virtual pages; spheres: a spot over a ground; room:
// walls, floor and ceiling around two point lights. Techniques that read depths themselves keep every caster,
// as do the naive reproductions.
INSTANTIATE_TEST_SUITE_P(
    , ShadowlessPlanes,
    ::testing::Values(
        ShadowlessPlanesCase{"knob_slope_scaled", "knob", ShadowTechnique::SlopeScaledBias},
        ShadowlessPlanesCase{"knob_pcf", "knob", ShadowTechnique::Pcf},
        ShadowlessPlanesCase{"knob_cascades_hw_pcf", "knob", ShadowTechnique::HardwarePcf,
                             MapAllocation::Fitted, 3},
        ShadowlessPlanesCase{"knob_virtual_slope_scaled", "knob", ShadowTechnique::SlopeScaledBias,
                             MapAllocation::Virtual},
        ShadowlessPlanesCase{"spheres_pcf_adaptive_bias", "spheres", ShadowTechnique::PcfAdaptiveBias},
        ShadowlessPlanesCase{"room_pcf", "room", ShadowTechnique::Pcf},
        ShadowlessPlanesCase{"room_normal_offset", "room", ShadowTechnique::NormalOffset},
        ShadowlessPlanesCase{"room_virtual_pcf_jittered", "room", ShadowTechnique::JitteredPcf,
                             MapAllocation::Virtual},
        ShadowlessPlanesCase{"knob_gsm_keeps", "knob", ShadowTechnique::Gsm, MapAllocation::Fitted, 0, false},
        ShadowlessPlanesCase{"room_evsm_keeps", "room", ShadowTechnique::Evsm, MapAllocation::Fitted, 0,
                             false},
        ShadowlessPlanesCase{"knob_hard_keeps", "knob", ShadowTechnique::HardCompare, MapAllocation::Fitted,
                             0, false}),
    caseName);

// knob: one directional map; outdoor: three cascades; spheres: a spot map; room: a sun's map beside two point
// lights' cube faces (which the fragment stage projects), so the vertex stage's per-light outputs are indexed
// past lights it does not project; and virtual maps: a sun's clipmap levels, from its finest level's
// projection, on a small model, a large ground and beside a spot light's virtual map.
INSTANTIATE_TEST_SUITE_P(
    , VertexProjection,
    ::testing::Values(
        ProjectionCase{"knob_slope_scaled", "knob", ShadowTechnique::SlopeScaledBias},
        ProjectionCase{"knob_gsm", "knob", ShadowTechnique::Gsm},
        ProjectionCase{"knob_normal_offset", "knob", ShadowTechnique::NormalOffset},
        ProjectionCase{"outdoor_cascades_gsm", "outdoor", ShadowTechnique::Gsm, 3},
        ProjectionCase{"outdoor_cascades_receiver_plane", "outdoor", ShadowTechnique::ReceiverPlaneBias, 3},
        ProjectionCase{"spheres_spot_gsm", "spheres", ShadowTechnique::Gsm},
        ProjectionCase{"spheres_spot_normal_offset", "spheres", ShadowTechnique::NormalOffset},
        ProjectionCase{"room_sun_and_points_slope_scaled", "room", ShadowTechnique::SlopeScaledBias, 0, true},
        ProjectionCase{"knob_virtual_slope_scaled", "knob", ShadowTechnique::SlopeScaledBias, 0, false,
                       MapAllocation::Virtual},
        ProjectionCase{"outdoor_virtual_receiver_plane", "outdoor", ShadowTechnique::ReceiverPlaneBias, 0,
                       false, MapAllocation::Virtual},
        ProjectionCase{"spheres_virtual_sun_and_spot_gsm", "spheres", ShadowTechnique::Gsm, 0, true,
                       MapAllocation::Virtual}),
    caseName);

// knob: one directional map; outdoor: cascades; room: two point lights' cube faces.
INSTANTIATE_TEST_SUITE_P(, FacingAwayEarlyOut,
                         ::testing::ValuesIn(cases({"knob", "outdoor", "room"},
                                                   {ShadowTechnique::SlopeScaledBias, ShadowTechnique::Gsm,
                                                    ShadowTechnique::Pcf, ShadowTechnique::Evsm})),
                         caseName);
// The techniques reading each dropped term: the texel size and divide (all), the map-space derivative
// (gsm's screen gradient, receiver-plane), the normal offset's axis angle, the tangent plane (adaptive-bias),
// the moments' depth (evsm).
INSTANTIATE_TEST_SUITE_P(, OrthographicLookups,
                         ::testing::ValuesIn(cases({"knob", "outdoor"},
                                                   {ShadowTechnique::SlopeScaledBias, ShadowTechnique::Gsm,
                                                    ShadowTechnique::ReceiverPlaneBias,
                                                    ShadowTechnique::NormalOffset,
                                                    ShadowTechnique::AdaptiveBias, ShadowTechnique::Evsm})),
                         caseName);

struct SharedViewDepthCase {
    std::string name;
    std::string scene;
    MapAllocation maps = MapAllocation::Fitted;
    int cascadeCount = 0;
    bool frozenFit = false; // fitted to another view than the camera's: its depth is not the lighting pass's
    bool samplesTheView =
        true; // a sun's maps fitted to the camera's samples, or virtual pages marked from them
};

void PrintTo(const SharedViewDepthCase& c, std::ostream* out) {
    *out << c.name;
}

struct SampledFrame {
    engine::Image image;
    bool moduleShared = false;   // ShadowStats::sharedViewDepth
    bool lightingShared = false; // FrameStats::sharedViewDepth
};

/// Three frames of the scene, the last a still view's, which keeps the maps (virtual maps are kept once a
/// frame drew no page), the sample pass taking the lighting pass's depth where `share`.
std::array<SampledFrame, 3> sampledFrames(const content::LoadedScene& loaded, const SharedViewDepthCase& c,
                                          bool share) {
    ShadowSettings settings;
    settings.resolution = 512;
    settings.mapAllocation = c.maps;
    settings.cascadeCount = c.cascadeCount;
    engine::Engine engine;
    engine.renderer().shareViewDepth = share;
    auto& shadows = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    const engine::EntityId camera = *loaded.scene.firstCamera();
    const glm::ivec2 size{160, 120};
    if (c.frozenFit) {
        const engine::CameraComponent& lens = *loaded.scene.entity(camera).camera;
        const glm::mat4 view = glm::inverse(loaded.scene.worldMatrix(camera));
        shadows.setFitView(FitView{glm::translate(view, glm::vec3(0.05f, 0.0f, 0.0f)),
                                   lens.projectionMatrix(float(size.x) / float(size.y))});
    }
    engine::RenderTarget target(size);
    std::array<SampledFrame, 3> frames;
    for (SampledFrame& frame : frames) {
        const engine::FrameStats stats = engine.renderFrame(loaded.scene, camera, target);
        frame = {target.readPixels(), shadows.stats().sharedViewDepth, stats.sharedViewDepth};
    }
    return frames;
}

class SharedViewDepth : public ::testing::TestWithParam<SharedViewDepthCase> {};

// The sample pass's depth of the camera's view is the lighting pass's depth pre-pass, drawn once for both:
// the maps fit the same samples (read at the target's depth format, D24, rather than D32F), and the lighting
// pass, shading against that depth, draws the same frame. A still view's frame runs no sample pass, nor do
// point lights' maps, and a fit to another view draws its own.
TEST_P(SharedViewDepth, TheSamplePassTakesTheLightingPassDepth) {
    glTestContext();
    const SharedViewDepthCase& c = GetParam();
    const content::LoadedScene loaded = loadScene(c.scene);
    const std::array<SampledFrame, 3> shared = sampledFrames(loaded, c, true);
    const std::array<SampledFrame, 3> own = sampledFrames(loaded, c, false);
    EXPECT_EQ(shared[0].moduleShared, c.samplesTheView) << c.name;
    EXPECT_EQ(shared[0].lightingShared, c.samplesTheView) << c.name;
    for (const SampledFrame& frame : {own[0], own[1], own[2], shared[2]}) {
        EXPECT_FALSE(frame.moduleShared) << c.name;
        EXPECT_FALSE(frame.lightingShared) << c.name;
    }
    if (!c.samplesTheView) {
        expectSameImage(shared[0].image, own[0].image, c.name);
    } else {
        expectSameLookups(shared[0].image, own[0].image, c.name);
    }
    expectSameImage(shared[2].image, shared[0].image, c.name + ", still");
}

// knob: a sun's map fitted to the samples; outdoor: cascades; virtual pages, marked from the samples; room:
// point lights only; and a frozen fit.
INSTANTIATE_TEST_SUITE_P(
    , SharedViewDepth,
    ::testing::Values(SharedViewDepthCase{"knob", "knob"},
                      SharedViewDepthCase{"outdoor_cascades", "outdoor", MapAllocation::Fitted, 3},
                      SharedViewDepthCase{"room_point_lights", "room", MapAllocation::Fitted, 0, false,
                                          false},
                      SharedViewDepthCase{"knob_virtual", "knob", MapAllocation::Virtual},
                      SharedViewDepthCase{"knob_frozen_fit", "knob", MapAllocation::Fitted, 0, true, false}),
    caseName);

} // namespace
