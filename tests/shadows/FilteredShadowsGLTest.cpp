// VSM and MSM (16-bit and 32-bit), EVSM and jittered PCF with early-out inside the engine.
#include "../engine/GLTestContext.h"

#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

using namespace shadows;

namespace {

content::LoadedScene scene(const char* name) {
    content::SceneLoadOptions options;
    options.subdivisionLevel = 2;
    return content::GltfLoader::load(
        std::filesystem::path(CONTENT_DIR) / "scenes" / (std::string(name) + ".gltf"), options);
}

/// RGBA floats of one frame of `settings` on `loaded`.
std::vector<float> render(const content::LoadedScene& loaded, const ShadowSettings& settings,
                          glm::ivec2 size = {128, 96}) {
    glTestContext();
    engine::Engine engine;
    engine.addModule(std::make_unique<ShadowModule>(settings));
    engine.renderer().environment.background = glm::vec3(0.0f);
    engine::RenderTarget target(size, engine::ColorFormat::Rgba32F);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    return target.readPixelsFloat();
}

struct FilteredCase {
    const char* name;
    ShadowTechnique technique;
    bool moments16;
    int earlyOut;
};

class FilteredShadowsGLTest : public testing::TestWithParam<FilteredCase> {};

} // namespace

TEST_P(FilteredShadowsGLTest, RendersKnobAndSpheresWithBoundedVisibility) {
    for (const char* name : {"knob", "spheres"}) {
        const content::LoadedScene loaded = scene(name);
        ShadowSettings settings;
        settings.technique = GetParam().technique;
        settings.moments16 = GetParam().moments16;
        settings.earlyOutTestTaps = GetParam().earlyOut;
        settings.resolution = 512;
        settings.debugView = ShadowDebugView::Visibility;
        const std::vector<float> pixels = render(loaded, settings);
        std::size_t shadowed = 0;
        std::size_t lit = 0;
        for (std::size_t i = 0; i < pixels.size(); i += 4) {
            ASSERT_TRUE(std::isfinite(pixels[i])) << name;
            ASSERT_GE(pixels[i], 0.0f);
            ASSERT_LE(pixels[i], 1.0f);
            shadowed += pixels[i] < 0.2f;
            lit += pixels[i] > 0.8f;
        }
        EXPECT_GT(shadowed, pixels.size() / 4 / 100) << name; // some shadow...
        EXPECT_GT(lit, pixels.size() / 4 / 4) << name;        // ...on mostly lit surfaces
    }
}

INSTANTIATE_TEST_SUITE_P(Techniques, FilteredShadowsGLTest,
                         testing::Values(FilteredCase{"vsm16", ShadowTechnique::Vsm, true, 0},
                                         FilteredCase{"vsm32", ShadowTechnique::Vsm, false, 0},
                                         FilteredCase{"msm32", ShadowTechnique::Msm, false, 0},
                                         FilteredCase{"evsm", ShadowTechnique::Evsm, false, 0},
                                         FilteredCase{"msm16", ShadowTechnique::Msm, true, 0},
                                         FilteredCase{"jittered", ShadowTechnique::JitteredPcf, false, 0},
                                         FilteredCase{"jitteredEarlyOut", ShadowTechnique::JitteredPcf, false,
                                                      8}),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(FilteredShadowsGLTest, EarlyOutMatchesTheFullKernelWhereItRunsAndSkipsMostPixels) {
    const content::LoadedScene loaded = scene("knob");
    ShadowSettings settings;
    settings.technique = ShadowTechnique::JitteredPcf;
    settings.resolution = 512;
    settings.jitterTaps = 32;
    settings.pcfRadius = 2.0f;
    settings.earlyOutTestTaps = 0;
    settings.debugView = ShadowDebugView::Visibility;
    const std::vector<float> full = render(loaded, settings);
    settings.earlyOutTestTaps = 8;
    const std::vector<float> early = render(loaded, settings);
    settings.debugView = ShadowDebugView::FullKernel;
    const std::vector<float> kernel = render(loaded, settings);

    std::size_t covered = 0;
    std::size_t fullKernel = 0;
    std::size_t agreeing = 0;
    std::size_t agreeingButDifferent = 0;
    for (std::size_t i = 0; i < full.size(); i += 4) {
        if (kernel[i + 3] < 0.5f) {
            continue; // background
        }
        ++covered;
        if (kernel[i] > 0.5f) {
            ++fullKernel;
            // The full kernel ran: the same taps were averaged, so the result is the same.
            EXPECT_FLOAT_EQ(early[i], full[i]);
        } else {
            ++agreeing;
            // The test taps agreed: the early result is what they say (0 or 1); the full kernel rarely
            // disagrees.
            EXPECT_TRUE(early[i] == 0.0f || early[i] == 1.0f);
            agreeingButDifferent += std::abs(early[i] - full[i]) > 0.25f;
        }
    }
    std::cout << "[ measured ] early-out: " << fullKernel << " of " << covered
              << " pixels took the full kernel, " << agreeingButDifferent << " of " << agreeing
              << " early pixels differ from the full kernel by > 0.25\n";
    EXPECT_GT(fullKernel, 0u);
    EXPECT_LT(fullKernel, covered / 4); // mostly umbra or fully lit: most pixels stop after the test taps
    EXPECT_LT(agreeingButDifferent, agreeing / 100);
}

TEST(FilteredShadowsGLTest, ResourcesMatchTheTechnique) {
    glTestContext();
    const content::LoadedScene loaded = scene("knob");
    engine::Engine engine;
    ShadowSettings settings;
    settings.resolution = 256;
    settings.fittedTexelPixels = 0.0f; // maps of `resolution`, however little the 64x48 view needs
    settings.technique = ShadowTechnique::Msm;
    auto& module = static_cast<ShadowModule&>(engine.addModule(std::make_unique<ShadowModule>(settings)));
    engine::RenderTarget target({64, 48});
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    const std::size_t texels = 256u * 256u;
    // D24 depth + RGBA16 moments (64 bits per texel), one level; no blur by default, so no temporary level.
    EXPECT_EQ(module.stats().bytes, texels * 4 + texels * 8);
    settings.momentBlurRadius = 2; // + the blur's temporary level
    module.setSettings(settings);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    EXPECT_EQ(module.stats().bytes, texels * 4 + texels * 8 + texels * 8);
    settings.moments16 = false; // RGBA32F
    module.setSettings(settings);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    EXPECT_EQ(module.stats().bytes, texels * 4 + texels * 16 + texels * 16);
    settings.technique = ShadowTechnique::Vsm; // RG32F
    module.setSettings(settings);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    EXPECT_EQ(module.stats().bytes, texels * 4 + texels * 8 + texels * 8);
    settings.moments16 = true; // RG16
    module.setSettings(settings);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    EXPECT_EQ(module.stats().bytes, texels * 4 + texels * 4 + texels * 4);
    settings.technique = ShadowTechnique::HardCompare;
    module.setSettings(settings);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    EXPECT_EQ(module.stats().bytes, texels * 4);
}

// 16-bit moments (the default) shade as 32-bit float ones do: no pixel flips, and the mean difference stays
// within the quantisation's (about 3e-5 of visibility here), on a curved caster over a ground (knob) and a
// spot light's perspective map (spheres).
TEST(FilteredShadowsGLTest, SixteenBitMomentsShadeAsFloatMomentsDo) {
    for (const ShadowTechnique technique : {ShadowTechnique::Vsm, ShadowTechnique::Msm}) {
        for (const char* name : {"knob", "spheres"}) {
            const content::LoadedScene loaded = scene(name);
            ShadowSettings settings;
            settings.technique = technique;
            settings.resolution = 512;
            settings.debugView = ShadowDebugView::Visibility;
            const std::vector<float> sixteen = render(loaded, settings);
            settings.moments16 = false;
            const std::vector<float> floats = render(loaded, settings);
            std::size_t covered = 0;
            std::size_t flipped = 0;
            double difference = 0.0;
            for (std::size_t i = 0; i < floats.size(); i += 4) {
                if (floats[i + 3] < 0.5f) {
                    continue; // background
                }
                ++covered;
                const float delta = std::abs(sixteen[i] - floats[i]);
                flipped += delta > 0.5f;
                difference += delta;
            }
            const double mean = difference / static_cast<double>(std::max<std::size_t>(covered, 1));
            std::cout << "[ measured ] " << toString(technique) << " on " << name << ": " << flipped << " of "
                      << covered << " pixels differ by > 0.5, mean difference " << mean << "\n";
            ASSERT_GT(covered, floats.size() / 4 / 4) << name;
            EXPECT_LE(flipped, covered / 1000) << toString(technique) << " on " << name;
            EXPECT_LT(mean, 2e-4) << toString(technique) << " on " << name;
        }
    }
}
