// The lighting pass's lean paths change no image: the early out of receivers facing away from the light, on
// every map layout (one map, cascades, cube faces) and technique family.
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

engine::Image shaded(const content::LoadedScene& loaded, ShadowSettings settings, bool withoutEarlyOut) {
    engine::Engine engine;
    engine.addModule(std::make_unique<ShadowModule>(settings));
    if (withoutEarlyOut) {
        engine.addModule(std::make_unique<DefineModule>("GS_SHADOW_KEEP_FACING_AWAY"));
    }
    engine::RenderTarget target({160, 120});
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    return target.readPixels();
}

struct EarlyOutCase {
    std::string name;
    std::string scene;
    ShadowTechnique technique;
};

class FacingAwayEarlyOut : public ::testing::TestWithParam<EarlyOutCase> {};

TEST_P(FacingAwayEarlyOut, ChangesNoImage) {
    glTestContext();
    const EarlyOutCase& c = GetParam();
    content::SceneLoadOptions options;
    options.subdivisionLevel = 1;
    const content::LoadedScene loaded = content::GltfLoader::load(
        std::filesystem::path(CONTENT_DIR) / "scenes" / (c.scene + ".gltf"), options);
    ShadowSettings settings;
    settings.technique = c.technique;
    settings.resolution = 512;
    const engine::Image lean = shaded(loaded, settings, false);
    const engine::Image full = shaded(loaded, settings, true);
    ASSERT_EQ(lean.size, full.size);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < lean.pixels.size(); ++i) {
        differing += lean.pixels[i] != full.pixels[i];
    }
    EXPECT_EQ(differing, 0u) << c.scene << " " << toString(c.technique);
    // The comparison means something only where the scene is lit and shadowed.
    const auto [darkest, brightest] = std::minmax_element(lean.pixels.begin(), lean.pixels.end());
    EXPECT_GT(*brightest - *darkest, 64);
}

std::vector<EarlyOutCase> earlyOutCases() {
    std::vector<EarlyOutCase> cases;
    // knob: one directional map; outdoor: cascades; room: two point lights' cube faces.
    for (const std::string scene : {"knob", "outdoor", "room"}) {
        for (const ShadowTechnique technique : {ShadowTechnique::SlopeScaledBias, ShadowTechnique::Gsm,
                                                ShadowTechnique::Pcf, ShadowTechnique::Evsm}) {
            std::string name = scene + "_" + std::string(toString(technique));
            std::replace(name.begin(), name.end(), '-', '_');
            cases.push_back({name, scene, technique});
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(, FacingAwayEarlyOut, ::testing::ValuesIn(earlyOutCases()),
                         [](const auto& caseInfo) { return caseInfo.param.name; });

} // namespace
