// Virtual shadow maps on the GPU: they agree with a whole map for every technique, draw no page in a static
// frame, redraw only a moved caster's pages (and its old shadow goes), fall back to coarser levels over
// budget; the same for spot lights' maps and point lights' faces, and the room in the default budget.
#include "../engine/GLTestContext.h"
#include "../support/ComparisonSamplerLeftOnUnit.h"

#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace shadows;

namespace {

content::LoadedScene loadVirtualScene(const std::string& name) {
    content::SceneLoadOptions options;
    options.subdivisionLevel = 1;
    return content::GltfLoader::load(std::filesystem::path(CONTENT_DIR) / "scenes" / (name + ".gltf"),
                                     options);
}

/// An engine with the shadow module drawing `scene` frame after frame into one target.
struct VirtualRig {
    VirtualRig(content::LoadedScene& loaded, const ShadowSettings& settings, glm::ivec2 size = {160, 120})
        : scene(loaded), target(size) {
        auto owned = std::make_unique<ShadowModule>(settings);
        module = owned.get();
        engine.addModule(std::move(owned));
    }
    engine::Image frame() {
        engine.renderFrame(scene.scene, *scene.scene.firstCamera(), target);
        return target.readPixels();
    }

    content::LoadedScene& scene;
    engine::Engine engine;
    engine::RenderTarget target;
    ShadowModule* module = nullptr;
};

ShadowSettings virtualSettings(ShadowTechnique technique = ShadowTechnique::SlopeScaledBias) {
    ShadowSettings settings;
    settings.technique = technique;
    settings.mapAllocation = MapAllocation::Virtual;
    settings.debugView = ShadowDebugView::Visibility;
    return settings;
}

/// Pixels (of the red channel) whose visibility differs by more than a quarter.
std::size_t differing(const engine::Image& a, const engine::Image& b) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
        count += std::abs(int(a.pixels[i]) - int(b.pixels[i])) > 64;
    }
    return count;
}

std::size_t shadowed(const engine::Image& image) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
        count += image.pixels[i] < 128;
    }
    return count;
}

struct AgreementCase {
    std::string name;
    ShadowTechnique technique;
    /// The PCF pattern's radius, texels (a wide kernel straddles pages more often).
    float pcfRadius = ShadowSettings{}.pcfRadius;
    /// The moments' blur, texels (blurred within each page's tile, its border included).
    int momentBlurRadius = 0;

    [[nodiscard]] ShadowSettings settings() const {
        ShadowSettings result = virtualSettings(technique);
        result.pcfRadius = pcfRadius;
        result.momentBlurRadius = momentBlurRadius;
        return result;
    }
};

class VirtualShadowMapsAgree : public ::testing::TestWithParam<AgreementCase> {};

/// Renders `loaded` with `settings` (virtual maps) and with whole fitted maps otherwise alike: both show its
/// shadow (over 5 % of the pixels), every page request is served, and at most `perMille` of the pixels differ
/// (along the shadows' edges, where the pages' other texels place them differently; at 160x120 an edge pixel
/// is ~0.6 % of the image).
void expectAgreesWithWholeMaps(content::LoadedScene& loaded, const ShadowSettings& settings,
                               std::size_t perMille) {
    ShadowSettings fitted = settings;
    fitted.mapAllocation = MapAllocation::Fitted;
    VirtualRig whole(loaded, fitted);
    VirtualRig paged(loaded, settings);
    const engine::Image reference = whole.frame();
    const engine::Image image = paged.frame();
    const ShadowStats stats = paged.module->stats();
    EXPECT_TRUE(stats.virtualMaps);
    EXPECT_GT(stats.pages.rendered, 0);
    EXPECT_EQ(stats.pages.refused, 0);
    EXPECT_GT(shadowed(reference), reference.pixels.size() / 4 / 20);
    EXPECT_LE(differing(image, reference), reference.pixels.size() / 4 * perMille / 1000)
        << shadowed(image) << " shadowed pixels against " << shadowed(reference);
}

TEST_P(VirtualShadowMapsAgree, WithAWholeMap) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    expectAgreesWithWholeMaps(loaded, GetParam().settings(), 5);
}

INSTANTIATE_TEST_SUITE_P(
    EveryFamily, VirtualShadowMapsAgree,
    // Not `hard`: the naive comparison's acne is a pattern of the texel grid, which the pages change.
    ::testing::Values(AgreementCase{"slope_scaled", ShadowTechnique::SlopeScaledBias},
                      AgreementCase{"hw_pcf", ShadowTechnique::HardwarePcf},
                      AgreementCase{"pcf", ShadowTechnique::Pcf}, AgreementCase{"gsm", ShadowTechnique::Gsm},
                      AgreementCase{"pcf_gsm_average", ShadowTechnique::PcfGsmAverageGradient},
                      AgreementCase{"receiver_plane", ShadowTechnique::ReceiverPlaneBias},
                      AgreementCase{"adaptive_bias", ShadowTechnique::AdaptiveBias},
                      AgreementCase{"pcf_jittered", ShadowTechnique::JitteredPcf},
                      AgreementCase{"vsm", ShadowTechnique::Vsm},
                      AgreementCase{"evsm", ShadowTechnique::Evsm},
                      AgreementCase{"msm", ShadowTechnique::Msm},
                      AgreementCase{"evsm_blurred", ShadowTechnique::Evsm, ShadowSettings{}.pcfRadius, 2},
                      AgreementCase{"vsm_blurred", ShadowTechnique::Vsm, ShadowSettings{}.pcfRadius, 3}),
    [](const ::testing::TestParamInfo<AgreementCase>& value) { return value.param.name; });

/// Visibility (red) or the slot view (red slot, green texels to the page's edge) of one frame, in floats.
std::vector<float> floatFrame(content::LoadedScene& loaded, ShadowSettings settings) {
    engine::Engine engine;
    engine.addModule(std::make_unique<ShadowModule>(settings));
    engine::RenderTarget target({160, 120}, engine::ColorFormat::Rgba32F);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    return target.readPixelsFloat();
}

class VirtualPageSeams : public ::testing::TestWithParam<AgreementCase> {};

// Lookups whose kernel straddles two pages read the neighbour's texels from the tile's border: they disagree
// with a whole map no more often than lookups inside a page do.
TEST_P(VirtualPageSeams, MatchPageInteriors) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    ShadowSettings settings = GetParam().settings();
    const std::vector<float> paged = floatFrame(loaded, settings);
    ShadowSettings fitted = settings;
    fitted.mapAllocation = MapAllocation::Fitted;
    const std::vector<float> whole = floatFrame(loaded, fitted);
    settings.debugView = ShadowDebugView::Slot;
    const std::vector<float> slots = floatFrame(loaded, settings);
    // Within the kernel's reach of a page's edge, and a texel for bilinear neighbours.
    const float reach = ShadowPlan::resolve(settings).kernelReachTexels + 1.0f;
    std::size_t seam = 0;
    std::size_t seamDisagree = 0;
    std::size_t interior = 0;
    std::size_t interiorDisagree = 0;
    for (std::size_t i = 0; i < paged.size(); i += 4) {
        const float edge = slots[i + 1];
        if (!(edge >= 0.0f)) {
            continue;
        }
        const bool disagree = std::abs(paged[i] - whole[i]) > 0.25f;
        (edge < reach ? seam : interior) += 1;
        (edge < reach ? seamDisagree : interiorDisagree) += disagree;
    }
    ASSERT_GT(seam, 100u) << "the view should hold page borders";
    ASSERT_GT(interior, seam);
    const double seamRate = static_cast<double>(seamDisagree) / static_cast<double>(seam);
    const double interiorRate = static_cast<double>(interiorDisagree) / static_cast<double>(interior);
    EXPECT_LE(seamRate, 2.0 * interiorRate + 0.002)
        << seamDisagree << " of " << seam << " seam pixels, " << interiorDisagree << " of " << interior
        << " inside pages";
}

INSTANTIATE_TEST_SUITE_P(
    EveryFamily, VirtualPageSeams,
    ::testing::Values(AgreementCase{"slope_scaled", ShadowTechnique::SlopeScaledBias},
                      AgreementCase{"pcf", ShadowTechnique::Pcf},
                      AgreementCase{"pcf_wide", ShadowTechnique::Pcf, 3.0f},
                      AgreementCase{"gsm", ShadowTechnique::Gsm},
                      AgreementCase{"receiver_plane", ShadowTechnique::ReceiverPlaneBias},
                      AgreementCase{"pcf_gsm_average", ShadowTechnique::PcfGsmAverageGradient},
                      AgreementCase{"pcf_gsm_average_wide", ShadowTechnique::PcfGsmAverageGradient, 3.0f},
                      AgreementCase{"evsm", ShadowTechnique::Evsm},
                      AgreementCase{"msm", ShadowTechnique::Msm},
                      AgreementCase{"evsm_blurred", ShadowTechnique::Evsm, ShadowSettings{}.pcfRadius, 3}),
    [](const ::testing::TestParamInfo<AgreementCase>& value) { return value.param.name; });

// The moments of each new page are blurred within its tile: the shadow's edge widens into a penumbra as a
// whole map's does (the agreement and seam cases above show it stays where a whole map puts it).
TEST(VirtualShadowMaps, MomentsAreBlurredPerPage) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    const auto penumbra = [&](int radius) {
        ShadowSettings settings = virtualSettings(ShadowTechnique::Evsm);
        settings.momentBlurRadius = radius;
        const std::vector<float> frame = floatFrame(loaded, settings);
        std::size_t count = 0;
        for (std::size_t i = 0; i < frame.size(); i += 4) {
            count += frame[i] > 0.1f && frame[i] < 0.9f;
        }
        return count;
    };
    const std::size_t sharp = penumbra(0);
    const std::size_t blurred = penumbra(3);
    EXPECT_GT(blurred, sharp * 3 / 2) << sharp << " penumbra pixels unblurred";
}

TEST(VirtualShadowMaps, OverBudgetFallsBackToCoarserLevels) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    VirtualRig full(loaded, virtualSettings());
    ShadowSettings small = virtualSettings();
    small.virtualBudgetMiB = 2; // about 0.5 MiB beside the page tables: 8 pages
    VirtualRig tight(loaded, small);
    const engine::Image reference = full.frame();
    const engine::Image image = tight.frame();
    const ShadowStats stats = tight.module->stats();
    EXPECT_GT(stats.pages.coarsened, 0);
    EXPECT_EQ(stats.pages.refused, 0);
    EXPECT_LE(stats.pages.resident, stats.pages.poolPages);
    // Still the knob's shadow: coarser texels move its edge, they do not lose it.
    EXPECT_LE(differing(image, reference), reference.pixels.size() / 4 / 50);
    EXPECT_GT(shadowed(image), shadowed(reference) * 9 / 10);
}

// The page marking gathers the view's depth through a sampler: one the application (or a fitted map's lookup)
// left bound to that unit, with comparison and linear filtering, changes no page and no pixel.
TEST(VirtualShadowMaps, MarkingIgnoresASamplerLeftOnItsUnit) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    VirtualRig clean(loaded, virtualSettings(), {157, 113});
    const engine::Image reference = clean.frame();
    const ShadowStats cleanStats = clean.module->stats();
    const testsupport::ComparisonSamplerLeftOnUnit sampler(0);
    VirtualRig left(loaded, virtualSettings(), {157, 113});
    const engine::Image image = left.frame();
    EXPECT_EQ(left.module->stats().pages.requested, cleanStats.pages.requested);
    EXPECT_EQ(differing(image, reference), 0u);
}

// The pool holds what the view asks for, not the whole budget: it grows by doubling as a larger view asks
// for more, its resident pages copied along, within the budget.
TEST(VirtualShadowMaps, PoolGrowsToWhatTheViewAsksWithinTheBudget) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    for (const ShadowTechnique technique : {ShadowTechnique::SlopeScaledBias, ShadowTechnique::Evsm}) {
        SCOPED_TRACE(toString(technique));
        const ShadowSettings settings = virtualSettings(technique);
        const std::size_t budget = static_cast<std::size_t>(settings.virtualBudgetMiB) << 20;
        VirtualRig rig(loaded, settings, {80, 60});
        rig.frame();
        const ShadowStats small = rig.module->stats();
        EXPECT_GE(small.pages.poolPages, small.pages.requested);
        EXPECT_LT(small.bytes, budget / 2) << small.pages.poolPages << " pages";
        // The same engine draws a larger view: more pages, a larger pool, the same image a new pool gives.
        engine::RenderTarget large({320, 240});
        const auto frame = [&] {
            rig.engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), large);
            return large.readPixels();
        };
        const engine::Image grownFrame = frame();
        const ShadowStats grown = rig.module->stats();
        EXPECT_GT(grown.pages.poolPages, small.pages.poolPages);
        EXPECT_GE(grown.pages.poolPages, grown.pages.requested);
        EXPECT_GT(grown.pages.cached, 0) << "pages of the small view are kept";
        EXPECT_LE(grown.bytes, budget);
        VirtualRig fresh(loaded, settings, {320, 240});
        EXPECT_EQ(differing(grownFrame, fresh.frame()), 0u);
        frame();
        EXPECT_EQ(rig.module->stats().pages.rendered, 0);
    }
}

/// The knob under a spot light instead of its sun, of cone half-angle `outerCone` (radians).
content::LoadedScene spotKnob(float outerCone = 0.5f) {
    content::LoadedScene loaded = loadVirtualScene("knob");
    loaded.scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
        if (e.light) {
            engine::Entity& light = loaded.scene.entity(id);
            light.light->type = engine::LightType::Spot;
            light.light->intensity = 40.0f;
            light.light->outerConeAngle = outerCone;
            light.light->innerConeAngle = outerCone - 0.1f;
            light.transform = engine::Transform::lookAt({3.0f, 4.0f, 2.0f}, {0.0f, 0.5f, 0.0f});
        }
    });
    return loaded;
}

/// The knob under its sun and a spot light beside it: a clipmap's pages and a spot map's marked in one frame,
/// each by its own variant of the marking shader.
content::LoadedScene sunAndSpotKnob() {
    content::LoadedScene loaded = loadVirtualScene("knob");
    const engine::EntityId spot = loaded.scene.create("spot");
    engine::LightComponent light;
    light.type = engine::LightType::Spot;
    light.intensity = 40.0f;
    light.outerConeAngle = 0.5f;
    light.innerConeAngle = 0.4f;
    loaded.scene.entity(spot).light = light;
    loaded.scene.entity(spot).transform = engine::Transform::lookAt({-3.0f, 4.0f, 2.0f}, {0.0f, 0.5f, 0.0f});
    return loaded;
}

// The room's two point lights and a sun: 12 faces and 16 clipmap levels, page-table layers and map slots
// beyond the 24 there were, so the sun cast no shadow.
content::LoadedScene roomAndSun() {
    content::LoadedScene loaded = loadVirtualScene("room");
    const engine::EntityId sun = loaded.scene.create("sun");
    engine::LightComponent light;
    light.intensity = 2.0f;
    loaded.scene.entity(sun).light = light;
    loaded.scene.entity(sun).transform = engine::Transform::lookAt({2.0f, 6.0f, 3.0f}, {0.0f, 0.0f, 0.0f});
    return loaded;
}

content::LoadedScene loadFaceScene(const std::string& name) {
    if (name == "spot-knob") {
        return spotKnob();
    }
    if (name == "room-and-sun") {
        return roomAndSun();
    }
    return name == "sun-and-spot-knob" ? sunAndSpotKnob() : loadVirtualScene(name);
}

struct FaceAgreementCase {
    std::string name;
    std::string scene; // "spot-knob", "sun-and-spot-knob" or a content scene with point lights
    ShadowTechnique technique;
    /// Pixels that may differ, per 1000: at 160x120 a page texel spans a pixel, coarser than 2048² faces, and
    /// the room's two lights give twice the edges (measured 5.7 and 8.1 per 1000 for pcf and msm there). The
    /// sun and spot's shaded image differs in 7 pixels (0.4 per 1000); marking the spot's pages as a
    /// clipmap's gives 35.
    std::size_t perMille = 5;
    /// What is compared. The visibility view shows, per pixel, the first map the lights' lookups read, which
    /// differs with two lights where a fitted sun's map leaves out ground that no caster shadows; the shaded
    /// image then compares both lights.
    ShadowDebugView view = ShadowDebugView::Visibility;
};

class VirtualFaceMapsAgree : public ::testing::TestWithParam<FaceAgreementCase> {};

// A spot light's map and a point light's faces through pages and mip levels show what whole fitted maps do,
// and so does a frame with a sun's clipmap beside a spot map.
TEST_P(VirtualFaceMapsAgree, WithWholeMaps) {
    glTestContext();
    content::LoadedScene loaded = loadFaceScene(GetParam().scene);
    ShadowSettings settings = virtualSettings(GetParam().technique);
    settings.debugView = GetParam().view;
    expectAgreesWithWholeMaps(loaded, settings, GetParam().perMille);
}

INSTANTIATE_TEST_SUITE_P(
    SpotAndPoint, VirtualFaceMapsAgree,
    ::testing::Values(FaceAgreementCase{"spot_slope_scaled", "spot-knob", ShadowTechnique::SlopeScaledBias},
                      FaceAgreementCase{"spot_pcf", "spot-knob", ShadowTechnique::Pcf},
                      FaceAgreementCase{"spot_gsm", "spot-knob", ShadowTechnique::Gsm},
                      FaceAgreementCase{"spot_evsm", "spot-knob", ShadowTechnique::Evsm},
                      FaceAgreementCase{"room_slope_scaled", "room", ShadowTechnique::SlopeScaledBias, 10},
                      FaceAgreementCase{"room_pcf", "room", ShadowTechnique::Pcf, 10},
                      FaceAgreementCase{"room_gsm", "room", ShadowTechnique::Gsm, 10},
                      FaceAgreementCase{"room_msm", "room", ShadowTechnique::Msm, 10},
                      FaceAgreementCase{"spheres_receiver_plane", "spheres",
                                        ShadowTechnique::ReceiverPlaneBias},
                      FaceAgreementCase{"sun_and_spot_slope_scaled", "sun-and-spot-knob",
                                        ShadowTechnique::SlopeScaledBias, 1, ShadowDebugView::None},
                      FaceAgreementCase{"room_and_sun_slope_scaled", "room-and-sun",
                                        ShadowTechnique::SlopeScaledBias, 10, ShadowDebugView::None}),
    [](const ::testing::TestParamInfo<FaceAgreementCase>& value) { return value.param.name; });

struct CacheCase {
    std::string name;
    std::string scene;  // as FaceAgreementCase, or "knob" under its sun
    std::string caster; // an entity to move
    std::string lamp;   // a light to move, and what stays (empty: the only light)
};

class VirtualMapsCache : public ::testing::TestWithParam<CacheCase> {
protected:
    // A wide spot, so that it lights ground far from the knob and its shadow too.
    content::LoadedScene load() const {
        return GetParam().scene == "spot-knob" ? spotKnob(1.0f) : loadVirtualScene(GetParam().scene);
    }
};

TEST_P(VirtualMapsCache, StaticFrameDrawsNoPage) {
    glTestContext();
    content::LoadedScene loaded = load();
    VirtualRig rig(loaded, virtualSettings());
    const engine::Image first = rig.frame();
    const VirtualPageStats cold = rig.module->stats().pages;
    EXPECT_GT(cold.rendered, 0);
    EXPECT_EQ(cold.rendered, cold.requested);
    const engine::Image second = rig.frame();
    const VirtualPageStats warm = rig.module->stats().pages;
    EXPECT_EQ(warm.rendered, 0);
    EXPECT_EQ(warm.cached, warm.requested);
    EXPECT_EQ(warm.requested, cold.requested);
    EXPECT_EQ(differing(first, second), 0u);
}

TEST_P(VirtualMapsCache, MovedCasterRedrawsItsPagesAndNoOthers) {
    glTestContext();
    content::LoadedScene loaded = load();
    VirtualRig rig(loaded, virtualSettings());
    rig.frame();
    const engine::Image before = rig.frame();
    const int requested = rig.module->stats().pages.requested;
    const std::optional<engine::EntityId> caster = loaded.scene.find(GetParam().caster);
    ASSERT_TRUE(caster);
    loaded.scene.entity(*caster).transform.translation.x += 0.3f;
    const engine::Image moved = rig.frame();
    const VirtualPageStats pages = rig.module->stats().pages;
    EXPECT_GT(pages.invalidated, 0);
    EXPECT_GT(pages.rendered, 0);
    EXPECT_LT(pages.rendered, requested) << "pages away from the caster and its shadow stay cached";
    EXPECT_EQ(pages.cached + pages.rendered, pages.requested);
    EXPECT_GT(differing(before, moved), 0u);
    // The old shadow is gone: the warm frame matches a cold one of the moved scene.
    VirtualRig cold(loaded, virtualSettings());
    EXPECT_EQ(differing(moved, cold.frame()), 0u);
}

TEST_P(VirtualMapsCache, MovedLightRedrawsItsPages) {
    glTestContext();
    content::LoadedScene loaded = load();
    VirtualRig rig(loaded, virtualSettings());
    rig.frame();
    rig.frame();
    const std::optional<engine::EntityId> lamp =
        GetParam().lamp.empty() ? std::nullopt : loaded.scene.find(GetParam().lamp);
    engine::EntityId moving = 0;
    loaded.scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
        if (e.light && (!lamp || id == *lamp)) {
            moving = id;
        }
    });
    engine::Transform& transform = loaded.scene.entity(moving).transform;
    if (loaded.scene.entity(moving).light->type == engine::LightType::Directional) {
        transform.rotation =
            glm::angleAxis(0.02f, glm::vec3(0.0f, 1.0f, 0.0f)) * transform.rotation; // a sun turns
    } else {
        transform.translation.x += 0.2f;
    }
    const engine::Image moved = rig.frame();
    const VirtualPageStats pages = rig.module->stats().pages;
    EXPECT_GT(pages.invalidated, 0);
    EXPECT_GT(pages.rendered, 0);
    if (lamp) {
        EXPECT_GT(pages.cached, 0) << "the other light's pages stay";
    }
    VirtualRig cold(loaded, virtualSettings());
    EXPECT_EQ(differing(moved, cold.frame()), 0u);
}

INSTANTIATE_TEST_SUITE_P(EveryLightType, VirtualMapsCache,
                         ::testing::Values(CacheCase{"sun", "knob", "knob", ""},
                                           CacheCase{"spot", "spot-knob", "knob", ""},
                                           CacheCase{"room", "room", "crate", "lamp west"}),
                         [](const ::testing::TestParamInfo<CacheCase>& value) { return value.param.name; });

// The room's two point lights held 960 MiB of whole 2048² cube faces with moment techniques; their virtual
// faces, tables included, stay in the default budget.
TEST(VirtualShadowMaps, RoomFitsTheDefaultBudget) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("room");
    for (const ShadowTechnique technique : {ShadowTechnique::SlopeScaledBias, ShadowTechnique::Msm}) {
        VirtualRig rig(loaded, virtualSettings(technique), {320, 240});
        rig.frame();
        const ShadowStats stats = rig.module->stats();
        EXPECT_TRUE(stats.virtualMaps);
        EXPECT_EQ(stats.shadowMaps, 12) << "every face of both lights sees a receiver";
        EXPECT_LE(stats.bytes, std::size_t(ShadowSettings{}.virtualBudgetMiB) << 20) << toString(technique);
        EXPECT_EQ(stats.pages.refused, 0) << toString(technique);
    }
}

// Four suns' clipmaps need 64 page-table layers of the 48: the fourth casts no shadow (and is warned), the
// others still do.
TEST(VirtualShadowMaps, LightsBeyondThePageTableLayersAreLeftOut) {
    glTestContext();
    content::LoadedScene loaded = loadVirtualScene("knob");
    engine::EntityId sun = 0;
    loaded.scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
        if (e.light) {
            sun = id;
        }
    });
    for (const char* name : {"second sun", "third sun", "fourth sun"}) {
        const engine::EntityId another = loaded.scene.create(name, loaded.scene.entity(sun).parent);
        loaded.scene.entity(another).transform = loaded.scene.entity(sun).transform;
        loaded.scene.entity(another).light = loaded.scene.entity(sun).light;
    }
    static_assert(3 * kClipmapLevels == kPageTableLayers);
    VirtualRig rig(loaded, virtualSettings());
    const engine::Image image = rig.frame();
    EXPECT_EQ(rig.module->stats().shadowMaps, 3 * kClipmapLevels);
    EXPECT_GT(shadowed(image), image.pixels.size() / 4 / 20);
}

} // namespace
