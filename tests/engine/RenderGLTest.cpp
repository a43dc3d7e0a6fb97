#include "GLTestContext.h"
#include "LitCubeScene.h"

#include <engine/Engine.h>
#include <engine/RenderTarget.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

using namespace engine;

namespace {

constexpr glm::ivec2 kSize{64, 64};
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
    RenderTarget target(kSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    const Image image = target.readPixels();

    const float lambert = std::max(0.0f, std::cos(glm::radians(c.angleDegrees)));
    expectPixel(image, kSize / 2, kBase * (c.ambient + lambert * c.intensity));
    expectPixel(image, {1, 1}, {0.2f, 0.4f, 0.6f}); // outside the cube: the clear colour
}

INSTANTIATE_TEST_SUITE_P(Cases, LitCubeGLTest,
                         testing::Values(DirectionalCase{"headOn", 0.0f, 1.0f, 0.0f},
                                         DirectionalCase{"sixtyDegrees", 60.0f, 1.0f, 0.0f},
                                         DirectionalCase{"headOnDimWithAmbient", 0.0f, 0.5f, 0.1f},
                                         DirectionalCase{"behindOnlyAmbient", 120.0f, 1.0f, 0.2f}),
                         [](const auto& test) { return std::string(test.param.name); });

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
    RenderTarget target(kSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    const Image image = target.readPixels();
    // Centre: on axis, lambert ≈ 1, attenuation 1/d² with d = 2.
    expectPixel(image, kSize / 2, kBase, 2);
    // Face corner (x = y = 0.9): 1.27 units off axis, angle atan(1.27/2) = 0.57 rad > outer cone: dark.
    expectPixel(image, {kSize.x / 2 + 14, kSize.y / 2 + 14}, glm::vec3(0.0f));
}

TEST(RenderGLTest, MeshWithoutNormalsUsesFlatVariantAndSameShading) {
    glTestContext();
    LitCubeScene fixture(kBase);
    fixture.mesh->normals.clear();
    fixture.addDirectionalLight(glm::radians(60.0f), 1.0f);
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    RenderTarget target(kSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    expectPixel(target.readPixels(), kSize / 2, kBase * 0.5f);
}

TEST(RenderGLTest, OnlyVariantsActuallyDrawnAreCompiled) {
    glTestContext();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(0.0f, 1.0f);
    Engine engine;
    RenderTarget target(kSize);
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
    RenderTarget target(kSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    expectPixel(target.readPixels(), kSize / 2, glm::vec3(0.0f));
}

TEST(RenderGLTest, PassTimingReportsBothPassesOnlyWhenEnabled) {
    auto& context = glTestContext();
    LitCubeScene fixture(kBase);
    fixture.addDirectionalLight(0.0f, 1.0f);
    Engine engine;
    RenderTarget target(kSize);
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
