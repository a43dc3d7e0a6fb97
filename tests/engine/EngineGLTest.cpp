#include "GLTestContext.h"
#include "LitCubeScene.h"
#include "ProbeModule.h"

#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/RenderTarget.h>

#include <gtest/gtest.h>

using namespace engine;

namespace {

constexpr glm::ivec2 kSize{32, 32};
const std::vector<std::string> kOneFrame{"prepareFrame:1 lights", "renderPrePasses",
                                         "bindLightingResources:cube", "debugDraw"};

int centreRed(Engine& engine, const LitCubeScene& fixture) {
    RenderTarget target(kSize);
    engine.renderFrame(fixture.scene, fixture.camera, target);
    return target.readPixels().at(kSize.x / 2, kSize.y / 2).r;
}

LitCubeScene litCube() {
    LitCubeScene fixture({1.0f, 1.0f, 1.0f});
    fixture.addDirectionalLight(0.0f, 0.8f);
    return fixture;
}

} // namespace

TEST(EngineGLTest, DirectlyLinkedModuleSeesHooksInDocumentedOrder) {
    glTestContext();
    LitCubeScene fixture = litCube();
    auto owned = std::make_unique<ProbeModule>();
    ProbeModule* probe = owned.get();
    {
        Engine engine;
        engine.renderer().environment.ambient = glm::vec3(0.0f);
        engine.addModule(std::move(owned));
        centreRed(engine, fixture);
        std::vector<std::string> expected{"attach"};
        expected.insert(expected.end(), kOneFrame.begin(), kOneFrame.end());
        EXPECT_EQ(probe->events, expected);
        EXPECT_TRUE(engine.removeModule("probe")); // destroys the probe: stop looking at it
        EXPECT_FALSE(engine.removeModule("probe"));
    }
}

TEST(EngineGLTest, LoadedModuleSeesHooksInDocumentedOrder) {
    glTestContext();
    LitCubeScene fixture = litCube();
    Engine engine;
    Module& module = engine.loadModule("probe");
    EXPECT_EQ(engine.module("probe"), &module);
    centreRed(engine, fixture);
    centreRed(engine, fixture);
    // The probe's own library tells its events (the test binary's ProbeModule is a different copy).
    ModuleLoader loader;
    auto reader = loader.load("probe");
    using EventsFunction = const std::vector<std::string>* (*)(const Module*);
    auto events = reinterpret_cast<EventsFunction>(reader->symbol("gsProbeEvents"));
    ASSERT_NE(events, nullptr);
    std::vector<std::string> expected{"attach"};
    for (int frame = 0; frame < 2; ++frame) {
        expected.insert(expected.end(), kOneFrame.begin(), kOneFrame.end());
    }
    EXPECT_EQ(*events(&module), expected);
}

TEST(EngineGLTest, ShaderChunkScalesVisibilityAndLeavesWithItsModule) {
    glTestContext();
    LitCubeScene fixture = litCube();
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    const int plain = centreRed(engine, fixture);
    EXPECT_NEAR(plain, srgbByte(0.8f), 1);

    auto owned = std::make_unique<ProbeModule>();
    owned->visibilityScale = 0.25f;
    engine.addModule(std::move(owned));
    EXPECT_NEAR(centreRed(engine, fixture), srgbByte(0.8f * 0.25f), 1);

    engine.removeModule("probe");
    EXPECT_EQ(centreRed(engine, fixture), plain);
}

TEST(EngineGLTest, AttachingTwoModulesOfOneNameIsAnError) {
    glTestContext();
    Engine engine;
    engine.addModule(std::make_unique<ProbeModule>());
    try {
        engine.loadModule("probe");
        FAIL() << "expected ModuleError";
    } catch (const ModuleError& error) {
        EXPECT_NE(std::string(error.what()).find("already attached"), std::string::npos) << error.what();
    }
    EXPECT_EQ(engine.modules().size(), 1u);
}

TEST(EngineGLTest, LoadingMissingOrWrongAbiModuleThrowsAndKeepsEngineUsable) {
    glTestContext();
    LitCubeScene fixture = litCube();
    Engine engine;
    EXPECT_THROW(engine.loadModule("does_not_exist"), ModuleError);
    EXPECT_THROW(engine.loadModule("wrong_abi"), ModuleError);
    EXPECT_TRUE(engine.modules().empty());
    EXPECT_GT(centreRed(engine, fixture), 0);
}

TEST(EngineGLTest, CameraEntityWithoutCameraIsAClearError) {
    glTestContext();
    LitCubeScene fixture = litCube();
    Engine engine;
    RenderTarget target(kSize);
    try {
        engine.renderFrame(fixture.scene, fixture.cube, target);
        FAIL() << "expected Error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("'cube' has no camera component"), std::string::npos);
    }
}
