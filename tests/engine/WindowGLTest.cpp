// Runs under Xvfb (see tests/CMakeLists.txt): a real GLFW window with a 4.5 core context.
#include "LitCubeScene.h"

#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/WindowContext.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace engine;

TEST(WindowGLTest, RendersLitCubeIntoTheWindow) {
    WindowContext window("WindowGLTest", {64, 64});
    const glm::ivec2 size = window.framebufferSize();
    ASSERT_GT(size.x, 0);
    LitCubeScene fixture({0.5f, 0.25f, 0.125f});
    fixture.addDirectionalLight(0.0f, 1.0f);
    Engine engine;
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    engine.renderFrame(fixture.scene, fixture.camera, FrameTarget{0, size});
    glFinish();
    std::uint8_t pixel[4] = {};
    glReadBuffer(GL_BACK);
    glReadPixels(size.x / 2, size.y / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    // The window's framebuffer may or may not be sRGB-capable: accept the linear or the encoded value.
    const int encoded = srgbByte(0.5f);
    const int linear = 128;
    EXPECT_TRUE(std::abs(pixel[0] - encoded) <= 1 || std::abs(pixel[0] - linear) <= 1) << int(pixel[0]);
    window.swapBuffers();
    EXPECT_TRUE(window.pollEvents());
}

TEST(WindowGLTest, NoDisplaySuggestsHeadless) {
    const char* display = std::getenv("DISPLAY");
    const std::string saved = display ? display : "";
    unsetenv("DISPLAY");
    try {
        WindowContext window("never", {16, 16});
        FAIL() << "expected ContextError";
    } catch (const ContextError& error) {
        EXPECT_NE(std::string(error.what()).find("--headless"), std::string::npos) << error.what();
    }
    if (!saved.empty()) {
        setenv("DISPLAY", saved.c_str(), 1);
    }
}
