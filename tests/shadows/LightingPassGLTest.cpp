// The lighting pass's lean paths change no image: the early out of receivers facing away from the light, on
// every map layout (one map, cascades, cube faces) and technique family, and the orthographic lookups of
// frames whose maps are all directional.
#include "../engine/GLTestContext.h"

#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
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
    return {target.readPixels(), (bits & engine.variants().flag("GS_SHADOW_ORTHOGRAPHIC")) != 0};
}

content::LoadedScene loadScene(const std::string& name) {
    content::SceneLoadOptions options;
    options.subdivisionLevel = 1;
    return content::GltfLoader::load(std::filesystem::path(CONTENT_DIR) / "scenes" / (name + ".gltf"),
                                     options);
}

void expectSameImage(const engine::Image& lean, const engine::Image& full, const std::string& what) {
    ASSERT_EQ(lean.size, full.size);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < lean.pixels.size(); ++i) {
        differing += lean.pixels[i] != full.pixels[i];
    }
    EXPECT_EQ(differing, 0u) << what;
    // The comparison means something only where the scene is lit and shadowed.
    const auto [darkest, brightest] = std::minmax_element(lean.pixels.begin(), lean.pixels.end());
    EXPECT_GT(*brightest - *darkest, 64) << what;
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
    expectSameImage(lean.image, shaded(loaded, settingsFor(c), "GS_SHADOW_KEEP_PERSPECTIVE").image,
                    describe(c));
}

TEST(OrthographicVariant, NotForPerspectiveMaps) {
    glTestContext();
    const content::LoadedScene loaded = loadScene("room");
    ShadowSettings settings;
    settings.resolution = 256;
    EXPECT_FALSE(shaded(loaded, settings).orthographicVariant);
}

const auto caseName = [](const auto& caseInfo) { return caseInfo.param.name; };

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

} // namespace
