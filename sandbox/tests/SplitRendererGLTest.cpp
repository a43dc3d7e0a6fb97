// The split-screen path on EGL: each side of the divider is exactly that side's single-technique frame, and
// the sandbox's light and camera controls reproduce the file's (needs no display).
#include "Session.h"
#include "TestSupport.h"

#include <engine/HeadlessContext.h>
#include <engine/RenderTarget.h>

#include <gtest/gtest.h>

using namespace sandbox;

namespace {

constexpr glm::ivec2 kSize{160, 120};

SandboxSettings smallKnob() {
    SandboxSettings settings;
    settings.scene = "knob";
    settings.level = 1;
    settings.a.resolution = 512;
    settings.b.resolution = 512;
    return settings;
}

class SplitRendererGLTest : public ::testing::Test {
protected:
    engine::Image render(Session& session) {
        session.render({target.framebuffer().id(), target.size()});
        return target.readPixels();
    }

    engine::HeadlessContext context;
    engine::RenderTarget target{kSize};
    SceneCatalog catalog{GS_CONTENT_DIR};
};

/// How `a` differs from `reference` over columns [x0, x1): the largest channel difference, and whether every
/// differing pixel is `background` in the reference.
struct ColumnDifference {
    int maxAbsDiff = 0;
    bool onlyBackground = true;
};
ColumnDifference differenceInColumns(const engine::Image& a, const engine::Image& reference, int x0, int x1,
                                     glm::u8vec4 background) {
    ColumnDifference difference;
    for (int y = 0; y < a.size.y; ++y) {
        for (int x = x0; x < x1; ++x) {
            const glm::ivec4 d = glm::abs(glm::ivec4(a.at(x, y)) - glm::ivec4(reference.at(x, y)));
            const int largest = std::max({d.r, d.g, d.b});
            difference.maxAbsDiff = std::max(difference.maxAbsDiff, largest);
            if (largest > 0 && reference.at(x, y) != background) {
                difference.onlyBackground = false;
            }
        }
    }
    return difference;
}

} // namespace

TEST_F(SplitRendererGLTest, EachSideIsThatSidesSingleTechniqueFrame) {
    SandboxSettings settings = smallKnob();
    // Hard comparison without bias shows acne everywhere lit; the average-gradient correction none.
    settings.a.technique = shadows::ShadowTechnique::HardCompare;
    settings.a.constantBiasTexels = 0.0f;
    settings.split = 0.4f;
    Session session(catalog, settings);

    const engine::Image split = render(session);
    session.settings().compare = false;
    const engine::Image onlyA = render(session);
    session.settings().a = settings.b;
    const engine::Image onlyB = render(session);

    const int splitX = 64; // round(0.4 * 160)
    // Every surface pixel is identical. The background may differ by one level: llvmpipe rounds the sRGB
    // encoding of a scissored glClear differently from a full one (0.03 linear blue: 49 against 48).
    const glm::u8vec4 background = onlyA.at(0, 0);
    const ColumnDifference left = differenceInColumns(split, onlyA, 0, splitX, background);
    EXPECT_LE(left.maxAbsDiff, 1);
    EXPECT_TRUE(left.onlyBackground);
    const ColumnDifference right = differenceInColumns(split, onlyB, splitX, kSize.x, background);
    EXPECT_LE(right.maxAbsDiff, 1);
    EXPECT_TRUE(right.onlyBackground);
    EXPECT_GT(differenceInColumns(onlyA, onlyB, 0, kSize.x, background).maxAbsDiff, 40)
        << "the two techniques should look different";
    EXPECT_GT(sandbox::test::distinctCentreColours(split), 100u);
}

TEST_F(SplitRendererGLTest, FileLightAndCameraAsSettingsReproduceTheFile) {
    SandboxSettings settings = smallKnob();
    settings.compare = false;
    Session session(catalog, settings);
    const engine::Image file = render(session);
    session.settings().light = session.scene().fileLightAngles();
    session.settings().camera = session.scene().fileOrbit();
    const engine::Image steered = render(session);
    const auto difference = sandbox::test::compare(file, steered, 8);
    EXPECT_LT(difference.fractionAbove, 0.002) << "max diff " << difference.maxAbsDiff;
}

TEST_F(SplitRendererGLTest, SpotLightSwingsToTheGivenAngles) {
    SandboxSettings settings;
    settings.scene = "spheres";
    settings.level = 0;
    settings.a.resolution = 256;
    settings.compare = false;
    settings.light = SandboxSettings::LightAngles{90.0f, 30.0f};
    Session session(catalog, settings);
    ASSERT_EQ(session.scene().lightType(), engine::LightType::Spot);
    render(session);
    const engine::Scene& scene = session.scene().scene();
    engine::EntityId light = engine::kNoEntity;
    scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (entity.light && light == engine::kNoEntity) {
            light = id;
        }
    });
    const glm::vec3 forward = glm::normalize(-glm::vec3(scene.worldMatrix(light)[2]));
    const glm::vec3 expected = -glm::vec3(std::cos(glm::radians(30.0f)), 0.5f, 0.0f);
    EXPECT_LT(glm::length(forward - expected), 1e-4f);
}

TEST_F(SplitRendererGLTest, GrazingLightDarkensTheGround) {
    SandboxSettings settings = smallKnob();
    settings.compare = false;
    settings.light = SandboxSettings::LightAngles{40.0f, 60.0f};
    Session session(catalog, settings);
    auto meanLevel = [](const engine::Image& image) {
        double sum = 0.0;
        for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
            sum += image.pixels[i] + image.pixels[i + 1] + image.pixels[i + 2];
        }
        return sum / static_cast<double>(image.pixels.size());
    };
    const double high = meanLevel(render(session));
    session.settings().light->elevation = 0.5f;
    const double grazing = meanLevel(render(session));
    EXPECT_LT(grazing, high * 0.7) << "high " << high << ", grazing " << grazing;
}

namespace {

/// Live GL objects but the programs: those are the variant cache, which the spot light of `spheres` extends.
engine::gl::LiveObjectCounts liveObjectsButPrograms() {
    engine::gl::LiveObjectCounts counts = engine::gl::liveObjectCounts();
    counts.programs = 0;
    return counts;
}

} // namespace

TEST_F(SplitRendererGLTest, SwitchingScenesFreesTheOldScenesGlObjects) {
    Session session(catalog, smallKnob());
    const engine::Image knob = render(session);
    const engine::gl::LiveObjectCounts withKnob = liveObjectsButPrograms();
    session.loadScene("spheres", -1);
    render(session);
    EXPECT_GT(engine::gl::liveObjectCounts().buffers, withKnob.buffers); // more meshes than the knob's two
    session.loadScene("knob", 1);
    // The same renderers draw the knob again: the spheres' meshes are gone, nothing else was made anew.
    EXPECT_EQ(sandbox::test::compare(render(session), knob, 0).maxAbsDiff, 0);
    EXPECT_EQ(liveObjectsButPrograms(), withKnob);
}

TEST_F(SplitRendererGLTest, LightTypesConvertBothWaysAndRestoreTheFile) {
    Session session(catalog, smallKnob());
    session.settings().light = session.scene().fileLightAngles();
    const engine::Image directional = render(session);
    ASSERT_EQ(session.scene().lightType(), engine::LightType::Directional);
    session.scene().setLightType(engine::LightType::Spot);
    EXPECT_EQ(session.scene().lightType(), engine::LightType::Spot);
    const engine::Image spot = render(session);
    // A spot lights the knob differently (falloff, perspective shadow) but still lights the view.
    EXPECT_GT(sandbox::test::compare(spot, directional, 2).fractionAbove, 0.01);
    EXPECT_GT(sandbox::test::distinctCentreColours(spot), 100u);
    session.scene().setLightType(engine::LightType::Point);
    EXPECT_EQ(session.scene().lightType(), engine::LightType::Point);
    const engine::Image point = render(session);
    // A point light lights every way (no cone): the view is lit, and not as the sun or the spot light it.
    EXPECT_GT(sandbox::test::compare(point, directional, 2).fractionAbove, 0.01);
    EXPECT_GT(sandbox::test::compare(point, spot, 2).fractionAbove, 0.01);
    EXPECT_GT(sandbox::test::distinctCentreColours(point), 100u);
    session.scene().setLightType(engine::LightType::Directional);
    EXPECT_EQ(sandbox::test::compare(render(session), directional, 0).maxAbsDiff, 0);
}

TEST_F(SplitRendererGLTest, LightSizeSoftensPcssAndIsClampedToWhatAFileMayHold) {
    SandboxSettings settings = smallKnob();
    settings.a.technique = shadows::ShadowTechnique::Pcss;
    settings.b.technique = shadows::ShadowTechnique::Pcss;
    Session session(catalog, settings);
    EXPECT_FLOAT_EQ(session.scene().lightSize(), engine::LightComponent::kSunAngularDiameter);
    session.scene().setLightSize(0.0f);
    const engine::Image hard = render(session);
    session.scene().setLightSize(glm::radians(8.0f));
    EXPECT_FLOAT_EQ(session.scene().lightSize(), glm::radians(8.0f));
    // A sun 8° wide spreads the knob's shadow edges into penumbrae.
    EXPECT_GT(sandbox::test::compare(render(session), hard, 8).fractionAbove, 0.002);
    session.scene().setLightSize(-1.0f);
    EXPECT_EQ(session.scene().lightSize(), 0.0f);
    session.scene().setLightSize(10.0f);
    EXPECT_LT(session.scene().lightSize(), engine::LightComponent::kMaxAngularDiameter);
    session.scene().setLightType(engine::LightType::Point);
    session.scene().setLightSize(0.05f);
    EXPECT_FLOAT_EQ(session.scene().lightSize(), 0.05f);
}
