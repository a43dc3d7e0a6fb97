#include "GLTestContext.h"
#include "LitCubeScene.h"

#include <engine/Engine.h>
#include <engine/RenderTarget.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

using namespace engine;

namespace {

constexpr glm::ivec2 kTargetSize{64, 64};
constexpr glm::vec3 kBase{0.5f, 0.25f, 0.125f};

void expectPixel(const Image& image, glm::ivec2 at, glm::vec3 linear, int tolerance = 1) {
    const glm::u8vec4 pixel = image.at(at.x, at.y);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(pixel[c], srgbByte(linear[c]), tolerance)
            << "channel " << c << " at " << at.x << "," << at.y;
    }
}

} // namespace

struct DirectionalCase {
    const char* name;
    float angleDegrees;
    float intensity;
    float ambient;
};

class LitCubeGLTest : public testing::TestWithParam<DirectionalCase> {};

TEST_P(LitCubeGLTest, FaceShowsLambertPlusAmbientInSrgb) {
    glTestContext();
    const DirectionalCase& c = GetParam();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(glm::radians(c.angleDegrees), c.intensity);
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(c.ambient);
    engine.renderer().environment.background = {0.2f, 0.4f, 0.6f};
    RenderTarget target(kTargetSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    const Image image = target.readPixels();

    const float lambert = std::max(0.0f, std::cos(glm::radians(c.angleDegrees)));
    expectPixel(image, kTargetSize / 2, kBase * (c.ambient + lambert * c.intensity));
    expectPixel(image, {1, 1}, {0.2f, 0.4f, 0.6f}); // outside the cube: the clear colour
}

INSTANTIATE_TEST_SUITE_P(Cases, LitCubeGLTest,
                         testing::Values(DirectionalCase{"headOn", 0.0f, 1.0f, 0.0f},
                                         DirectionalCase{"sixtyDegrees", 60.0f, 1.0f, 0.0f},
                                         DirectionalCase{"headOnDimWithAmbient", 0.0f, 0.5f, 0.1f},
                                         DirectionalCase{"behindOnlyAmbient", 120.0f, 1.0f, 0.2f}),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(RenderGLTest, WithoutSrgbEncodingTheTargetStoresTheLinearColour) {
    glTestContext();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(0.0f, 1.0f);
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    engine.renderer().environment.background = {0.2f, 0.4f, 0.6f};
    engine.renderer().encodeSrgb = false;
    RenderTarget target(kTargetSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    const Image image = target.readPixels();
    // The face lit head-on is kBase itself, 0.5 stored as 128 (encoded it would be 188), the clear colour
    // likewise.
    const auto expectLinear = [&](glm::ivec2 at, glm::vec3 linear) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.at(at.x, at.y)[c], 255.0f * linear[c], 1.0f) << "channel " << c;
        }
    };
    expectLinear(kTargetSize / 2, kBase);
    expectLinear({1, 1}, {0.2f, 0.4f, 0.6f});
}

TEST(RenderGLTest, SpotLightFallsOffWithInverseSquareAndCone) {
    glTestContext();
    LitCubeScene fixture(kBase);
    const EntityId spot = fixture.scene.create("spot");
    LightComponent light;
    light.type = LightType::Spot;
    light.intensity = 4.0f; // at distance 2 from the face: 4 / 2² = 1
    light.innerConeAngle = 0.2f;
    light.outerConeAngle = 0.3f;
    fixture.scene.entity(spot).light = light;
    fixture.scene.entity(spot).transform = Transform::lookAt({0, 0, 3}, {0, 0, 0});
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    RenderTarget target(kTargetSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    const Image image = target.readPixels();
    // Centre: on axis, lambert ≈ 1, attenuation 1/d² with d = 2.
    expectPixel(image, kTargetSize / 2, kBase, 2);
    // Face corner (x = y = 0.9): 1.27 units off axis, angle atan(1.27/2) = 0.57 rad > outer cone: dark.
    expectPixel(image, {kTargetSize.x / 2 + 14, kTargetSize.y / 2 + 14}, glm::vec3(0.0f));
}

namespace {

/// Renders `scene` without ambient light into a linear float target (no sRGB encoding): the shaded colour,
/// or the world position of each pixel's surface with OutputMode::WorldPosition.
std::vector<float> renderLinear(const Scene& scene, EntityId camera, OutputMode output) {
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    engine.renderer().output = output;
    RenderTarget target(kTargetSize, ColorFormat::Rgba32F);
    engine.renderFrame(scene, camera, target);
    return target.readPixelsFloat();
}

glm::vec3 texel(const std::vector<float>& pixels, glm::ivec2 at) {
    const std::size_t i = 4 * static_cast<std::size_t>(at.y * kTargetSize.x + at.x);
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

/// What a light of `intensity` at `light` gives a surface point `p` of the cube's +Z face (normal +Z) with
/// base colour kBase: Lambert times the inverse square, windowed by KHR_lights_punctual's range
/// (clamp(1 - (d/range)^4, 0, 1), "Range Property"; range 0 = unlimited).
glm::vec3 expectedPositional(glm::vec3 p, glm::vec3 light, float intensity, float range) {
    const glm::vec3 offset = light - p;
    const float d = glm::length(offset);
    const float window = range > 0.0f ? glm::clamp(1.0f - std::pow(d / range, 4.0f), 0.0f, 1.0f) : 1.0f;
    return kBase * intensity * std::max(offset.z / d, 0.0f) * window / (d * d);
}

// Pixels of the face's centre row: on the axis under the light, 0.53 and 0.78 units off it.
constexpr glm::ivec2 kOnAxis{32, 32};
constexpr glm::ivec2 kNear{40, 32};
constexpr glm::ivec2 kFar{44, 32};
constexpr glm::vec3 kLightAboveFace{0.0f, 0.0f, 1.5f}; // 0.5 in front of the +Z face

} // namespace

TEST(RenderGLTest, PointLightFallsOffWithTheInverseSquareInEveryDirection) {
    glTestContext();
    LitCubeScene fixture(kBase);
    const EntityId bulb = fixture.scene.create("bulb");
    LightComponent light;
    light.type = LightType::Point;
    light.intensity = 0.25f; // at distance 0.5 from the face: 0.25 / 0.5² = 1
    fixture.scene.entity(bulb).light = light;
    // Facing away from the face: a point light has no cone, so the orientation must not matter (a spot so
    // placed would leave the face dark).
    fixture.scene.entity(bulb).transform = Transform::lookAt(kLightAboveFace, {0, 0, 5});
    const std::vector<float> positions =
        renderLinear(fixture.scene, fixture.camera, OutputMode::WorldPosition);
    const std::vector<float> shaded = renderLinear(fixture.scene, fixture.camera, OutputMode::Shaded);

    for (const glm::ivec2 at : {kOnAxis, kNear, kFar}) {
        const glm::vec3 p = texel(positions, at);
        ASSERT_NEAR(p.z, 1.0f, 1e-4f) << "pixel " << at.x << " is not on the +Z face";
        const glm::vec3 expected = expectedPositional(p, kLightAboveFace, light.intensity, 0.0f);
        EXPECT_NEAR(texel(shaded, at).r, expected.r, 0.01f * expected.r) << "pixel " << at.x;
    }
    // The far pixel is ~1.9x as far from the light and lit at cos ~0.54: 1/(1.9² / 0.54) ~ 1/6.4 of the
    // centre, as the inverse square and Lambert predict together.
    const glm::vec3 centre = texel(positions, kOnAxis);
    const glm::vec3 far = texel(positions, kFar);
    const float expectedRatio = expectedPositional(centre, kLightAboveFace, 1.0f, 0.0f).r /
                                expectedPositional(far, kLightAboveFace, 1.0f, 0.0f).r;
    EXPECT_GT(expectedRatio, 5.0f);
    EXPECT_NEAR(texel(shaded, kOnAxis).r / texel(shaded, kFar).r, expectedRatio, 0.01f * expectedRatio);
}

TEST(RenderGLTest, MeasurementOutputsMarkOnlyCoveredPixels) {
    glTestContext();
    LitCubeScene fixture(kBase);
    for (const OutputMode output : {OutputMode::WorldPosition, OutputMode::WorldNormal}) {
        const std::vector<float> pixels = renderLinear(fixture.scene, fixture.camera, output);
        const auto alpha = [&](glm::ivec2 at) {
            return pixels[4 * static_cast<std::size_t>(at.y * kTargetSize.x + at.x) + 3];
        };
        EXPECT_EQ(alpha(kOnAxis), 1.0f) << "the cube's face";
        // The corner shows no surface: the background's colour must not read as a surface there.
        EXPECT_EQ(alpha({0, 0}), 0.0f);
        EXPECT_EQ(texel(pixels, {0, 0}), glm::vec3(0.0f));
    }
    const std::vector<float> shaded = renderLinear(fixture.scene, fixture.camera, OutputMode::Shaded);
    EXPECT_EQ(texel(shaded, {0, 0}), Engine().renderer().environment.background)
        << "the corner is background";
}

class PositionalRangeGLTest : public testing::TestWithParam<LightType> {};

TEST_P(PositionalRangeGLTest, RangeWindowsTheFalloffToZeroAtTheRange) {
    glTestContext();
    LitCubeScene fixture(kBase);
    const EntityId lamp = fixture.scene.create("lamp");
    LightComponent light;
    light.type = GetParam();
    light.intensity = 0.25f;
    light.range = 0.8f; // between the near (0.73 away) and the far pixel (0.93 away)
    // A spot's cone wide enough to cover every sampled pixel fully: only the range window differs.
    light.innerConeAngle = 1.2f;
    light.outerConeAngle = 1.3f;
    fixture.scene.entity(lamp).light = light;
    fixture.scene.entity(lamp).transform = Transform::lookAt(kLightAboveFace, {0, 0, 0});
    const std::vector<float> positions =
        renderLinear(fixture.scene, fixture.camera, OutputMode::WorldPosition);
    const std::vector<float> shaded = renderLinear(fixture.scene, fixture.camera, OutputMode::Shaded);

    const glm::vec3 onAxis = expectedPositional(texel(positions, kOnAxis), kLightAboveFace, 0.25f, 0.8f);
    const glm::vec3 near = expectedPositional(texel(positions, kNear), kLightAboveFace, 0.25f, 0.8f);
    // Inside the range the window is clamp(1 - (d/range)^4, 0, 1): 0.85 on the axis, 0.3 at the near pixel.
    EXPECT_NEAR(texel(shaded, kOnAxis).r, onAxis.r, 0.01f * onAxis.r);
    EXPECT_NEAR(texel(shaded, kNear).r, near.r, 0.01f * near.r);
    EXPECT_LT(near.r, 0.4f * expectedPositional(texel(positions, kNear), kLightAboveFace, 0.25f, 0.0f).r);
    // Beyond the range: no light at all.
    EXPECT_EQ(texel(shaded, kFar), glm::vec3(0.0f));
}

INSTANTIATE_TEST_SUITE_P(Types, PositionalRangeGLTest, testing::Values(LightType::Point, LightType::Spot),
                         [](const auto& test) { return test.param == LightType::Point ? "point" : "spot"; });

TEST(RenderGLTest, MeshWithoutNormalsUsesFlatVariantAndSameShading) {
    glTestContext();
    LitCubeScene fixture(kBase);
    fixture.mesh->normals.clear();
    fixture.addDirectionalLight(glm::radians(60.0f), 1.0f);
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    RenderTarget target(kTargetSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    expectPixel(target.readPixels(), kTargetSize / 2, kBase * 0.5f);
}

TEST(RenderGLTest, OnlyVariantsActuallyDrawnAreCompiled) {
    glTestContext();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(0.0f, 1.0f);
    Engine engine;
    RenderTarget target(kTargetSize);
    EXPECT_EQ(engine.programs().compileCount(), 0u); // nothing compiled before the first draw
    engine.renderFrame(fixture.scene, fixture.camera, target);
    EXPECT_EQ(engine.programs().compileCount(), 1u);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    EXPECT_EQ(engine.programs().compileCount(), 1u); // cached

    // A second mesh without normals needs the flat-normal variant: exactly one more program.
    auto faceted = std::make_shared<MeshData>(primitives::cube(0.5f));
    faceted->normals.clear();
    const EntityId extra = fixture.scene.create("faceted");
    fixture.scene.entity(extra).mesh = MeshComponent{faceted};
    fixture.scene.entity(extra).transform.translation = {0, 0, 3};
    engine.renderFrame(fixture.scene, fixture.camera, target);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    EXPECT_EQ(engine.programs().compileCount(), 2u);
}

TEST(RenderGLTest, ChildEntitiesFollowTheirParent) {
    glTestContext();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(0.0f, 1.0f);
    const EntityId pivot = fixture.scene.create("pivot");
    fixture.scene.setParent(fixture.cube, pivot);
    fixture.scene.entity(pivot).transform.translation = {10, 0, 0}; // out of view
    Engine engine;
    engine.renderer().environment.background = glm::vec3(0.0f);
    RenderTarget target(kTargetSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    expectPixel(target.readPixels(), kTargetSize / 2, glm::vec3(0.0f));
}

TEST(RenderGLTest, PassTimingReportsBothPassesOnlyWhenEnabled) {
    auto& context = glTestContext();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(0.0f, 1.0f);
    Engine engine;
    RenderTarget target(kTargetSize);
    FrameStats stats = engine.renderFrame(fixture.scene, fixture.camera, target);
    EXPECT_LT(stats.prePassMilliseconds, 0.0);
    EXPECT_LT(stats.lightingMilliseconds, 0.0);
    const TimingMethod method = PassTimer::methodFor(context);
    EXPECT_EQ(method,
              context.isSoftwareRenderer() ? TimingMethod::FinishAndSteadyClock : TimingMethod::TimerQuery);
    engine.setPassTiming(method);
    stats = engine.renderFrame(fixture.scene, fixture.camera, target);
    EXPECT_GE(stats.prePassMilliseconds, 0.0);
    EXPECT_GT(stats.lightingMilliseconds, 0.0);
    EXPECT_EQ(engine.passTiming(), method);
}
