// Runs under Xvfb (see CMakeLists.txt): the windowed sandbox renders the scene, and its screenshots equal the
// headless render of the same settings.
#include "TestSupport.h"

#include <engine/Image.h>

#include <gtest/gtest.h>

#include <iostream>

using sandbox::test::runSandbox;

namespace {

/// Largest per-channel difference tolerated between window and headless pixels, and the share of pixels
/// allowed beyond it. Both paths draw the same frame into an sRGB target; the window gets a raw blit of it.
/// Measured on Mesa llvmpipe under Xvfb: identical (max diff 0); the margin covers drivers whose blit
/// re-encodes through float.
constexpr int kTolerance = 2;
constexpr double kAllowedFractionAbove = 0.005;
/// Distinct colours the centre of a frame that shows the scene has at least (a blank view has one or two; the
/// clean crease-cube view under a grazing light has 82).
constexpr std::size_t kSceneColours = 50;

struct Renders {
    engine::Image window;
    engine::Image headless;
};

Renders renderBoth(const std::string& name, const std::string& settingsJson, const std::string& windowFlags) {
    const auto folder = sandbox::test::freshFolder(name);
    const std::filesystem::path settings = folder / "settings.json";
    engine::writeTextFile(settings, settingsJson);
    const std::string common = "--settings " + settings.string() + " --size 320x240 --frames 3";
    const auto window =
        runSandbox(common + " " + windowFlags + " --screenshot " + (folder / "window.png").string());
    EXPECT_EQ(window.status, 0) << window.output;
    const auto headless = runSandbox("--headless " + common + " --out " + (folder / "headless.png").string());
    EXPECT_EQ(headless.status, 0) << headless.output;
    return {sandbox::test::loadPng(folder / "window.png"), sandbox::test::loadPng(folder / "headless.png")};
}

void expectSameImage(const Renders& renders, const std::string& name) {
    ASSERT_EQ(renders.window.size, glm::ivec2(320, 240));
    ASSERT_EQ(renders.headless.size, glm::ivec2(320, 240));
    const auto difference = sandbox::test::compare(renders.window, renders.headless, kTolerance);
    std::cout << "measured " << name << ": window vs headless max abs diff " << difference.maxAbsDiff << ", "
              << difference.fractionAbove * 100.0 << " % of pixels above " << kTolerance << "\n";
    EXPECT_LE(difference.fractionAbove, kAllowedFractionAbove) << "max abs diff " << difference.maxAbsDiff;
}

} // namespace

TEST(SandboxWindowTest, WindowShowsTheSplitSceneLikeHeadless) {
    // The default split view with the panels shown: screenshots hold the view, not the UI drawn over it.
    const Renders renders = renderBoth(
        "window-split",
        R"({"scene": "knob", "level": 1, "a": {"resolution": 512}, "b": {"resolution": 512}})", "");
    EXPECT_GT(sandbox::test::distinctCentreColours(renders.window), kSceneColours)
        << "the centre shows no scene";
    expectSameImage(renders, "split view, UI shown");
}

TEST(SandboxWindowTest, SteeredViewWithoutUiMatchesHeadless) {
    const Renders renders = renderBoth("window-steered", R"({
        "scene": "crease-cube", "level": 1, "azimuth": 200, "elevation": 8,
        "camera": {"target": [0, 0.6, 0], "yaw": 30, "pitch": 25, "distance": 5},
        "compare": true, "split": 0.3,
        "a": {"technique": "pcf", "resolution": 256, "pcfTaps": 3},
        "b": {"technique": "receiver-plane", "resolution": 256, "depthFormat": "d16"}})",
                                       "--no-ui");
    EXPECT_GT(sandbox::test::distinctCentreColours(renders.window), kSceneColours)
        << "the centre shows no scene";
    expectSameImage(renders, "steered camera and grazing light, no UI");
}
