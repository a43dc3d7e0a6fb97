// Runs under Xvfb (see tests/CMakeLists.txt): a real GLFW window with a 4.5 core context.
#include "LitCubeScene.h"

#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/WindowContext.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace engine;

namespace {

/// Asks for the view's depth in its pre-pass, as the shadow module's sample pass does.
class ViewDepthAsker final : public Module {
public:
    [[nodiscard]] std::string_view name() const override { return "view-depth-asker"; }
    void attach(ModuleHost& host) override { host_ = &host; }
    void renderPrePasses(const FrameContext& frame) override { texture = host_->viewDepth(frame); }
    GLuint texture = 0;

private:
    ModuleHost* host_ = nullptr;
};

/// Draws the lit cube into the window with `engine` and checks the centre pixel, the cube's face.
FrameStats expectLitCubeInWindow(Engine& engine, glm::ivec2 size) {
    LitCubeScene fixture({0.5f, 0.25f, 0.125f});
    fixture.addDirectionalLight(0.0f, 1.0f);
    engine.renderer().environment.ambient = glm::vec3(0.0f);
    const FrameStats stats = engine.renderFrame(fixture.scene, fixture.camera, FrameTarget{0, size});
    glFinish();
    std::uint8_t pixel[4] = {};
    glReadBuffer(GL_BACK);
    glReadPixels(size.x / 2, size.y / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    // The window's framebuffer may or may not be sRGB-capable: accept the linear or the encoded value.
    const int encoded = srgbByte(0.5f);
    const int linear = 128;
    EXPECT_TRUE(std::abs(pixel[0] - encoded) <= 1 || std::abs(pixel[0] - linear) <= 1) << int(pixel[0]);
    return stats;
}

} // namespace

TEST(WindowGLTest, RendersLitCubeIntoTheWindow) {
    WindowContext window("WindowGLTest", {64, 64});
    const glm::ivec2 size = window.framebufferSize();
    ASSERT_GT(size.x, 0);
    Engine engine;
    expectLitCubeInWindow(engine, size);
    window.swapBuffers();
    EXPECT_TRUE(window.pollEvents());
}

// A module asking for the view depth of a frame drawn into the window: the default framebuffer takes a copy
// where its format copies exactly (not GLFW's usual packed 24-bit depth and 8-bit stencil on llvmpipe), and
// the lighting pass draws the same pixel either way.
TEST(WindowGLTest, ViewDepthAskedForKeepsTheWindowsImage) {
    WindowContext window("WindowGLTest", {64, 64});
    const glm::ivec2 size = window.framebufferSize();
    ASSERT_GT(size.x, 0);
    Engine engine;
    auto& asker = static_cast<ViewDepthAsker&>(engine.addModule(std::make_unique<ViewDepthAsker>()));
    EXPECT_EQ(expectLitCubeInWindow(engine, size).sharedViewDepth, asker.texture != 0u);
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
