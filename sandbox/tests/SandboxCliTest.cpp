// gs-sandbox end to end without a display server: headless renders and the exits of bad input.
#include "TestSupport.h"

#include <engine/Image.h>

#include <gtest/gtest.h>

using sandbox::test::runSandbox;

namespace {

const std::string kSmall = "--scene knob --level 1 --size 160x120 --shadow-size 512";

void expectFailure(const std::string& arguments, int status, const std::string& message,
                   const std::string& environment = "") {
    const auto result = runSandbox(arguments, environment);
    EXPECT_EQ(result.status, status) << arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos)
        << arguments << "\n  output: " << result.output << "\n  wanted: " << message;
}

} // namespace

TEST(SandboxCliTest, HeadlessWritesTheSplitView) {
    const auto folder = sandbox::test::freshFolder("cli-headless");
    const auto result =
        runSandbox("--headless " + kSmall + " --frames 2 --out " + (folder / "view.png").string());
    ASSERT_EQ(result.status, 0) << result.output;
    EXPECT_NE(result.output.find("wrote " + (folder / "view.png").string()), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("A pcf-gsm-point: shadow pass"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("B pcf-gsm-average: shadow pass"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("timing: "), std::string::npos) << result.output;
    const engine::Image image = sandbox::test::loadPng(folder / "view.png");
    EXPECT_EQ(image.size, glm::ivec2(160, 120));
    EXPECT_GT(sandbox::test::distinctCentreColours(image), 100u);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) {
        ++files;
    }
    EXPECT_EQ(files, 1u) << "temporary file left behind";
}

TEST(SandboxCliTest, TechniqueAloneFillsTheView) {
    const auto folder = sandbox::test::freshFolder("cli-technique");
    const auto result =
        runSandbox("--headless " + kSmall + " --technique pcf --out " + (folder / "pcf.png").string());
    ASSERT_EQ(result.status, 0) << result.output;
    EXPECT_NE(result.output.find("A pcf: shadow pass"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("B "), std::string::npos) << result.output;
}

TEST(SandboxCliTest, GroundTruthOverlayTintsAcneOfAHardComparison) {
    const auto folder = sandbox::test::freshFolder("cli-truth");
    const auto result =
        runSandbox("--headless " + kSmall + " --technique hard --out " + (folder / "view.png").string() +
                   " --ground-truth " + (folder / "truth.png").string());
    ASSERT_EQ(result.status, 0) << result.output;
    // A hard comparison with the default (tiny) bias self-shadows much of the knob and the ground.
    const auto at = result.output.find("ground truth (A): acne ");
    ASSERT_NE(at, std::string::npos) << result.output;
    EXPECT_GT(std::stod(result.output.substr(at + 23)), 10.0) << result.output;
    const engine::Image view = sandbox::test::loadPng(folder / "view.png");
    const engine::Image truth = sandbox::test::loadPng(folder / "truth.png");
    ASSERT_EQ(truth.size, view.size);
    std::size_t red = 0;
    for (std::size_t i = 0; i < truth.pixels.size(); i += 4) {
        red += truth.pixels[i] > 150 && truth.pixels[i + 1] < 100 && truth.pixels[i + 2] < 100;
    }
    EXPECT_GT(red, truth.pixels.size() / 4 / 20); // acne tinted red
}

TEST(SandboxCliTest, GroundTruthMeasuresSideBToo) {
    const auto folder = sandbox::test::freshFolder("cli-truth-b");
    const auto result =
        runSandbox("--headless " + kSmall + " --technique pcf-gsm-average --compare hard --out " +
                   (folder / "view.png").string() + " --ground-truth " + (folder / "truth.png").string());
    ASSERT_EQ(result.status, 0) << result.output;
    const auto acneOf = [&](const std::string& side) {
        const std::string label = "ground truth (" + side + "): acne ";
        const auto at = result.output.find(label);
        EXPECT_NE(at, std::string::npos) << result.output;
        return at == std::string::npos ? -1.0 : std::stod(result.output.substr(at + label.size()));
    };
    // B's hard comparison self-shadows; A's corrected filter hardly does.
    const double acneA = acneOf("A");
    const double acneB = acneOf("B");
    EXPECT_GT(acneB, 10.0) << result.output;
    EXPECT_LT(acneA, acneB / 4.0) << result.output;
    // The overlay tints each half with its own side's errors: the red is on B's side.
    const engine::Image truth = sandbox::test::loadPng(folder / "truth.png");
    std::size_t redLeft = 0;
    std::size_t redRight = 0;
    for (int y = 0; y < truth.size.y; ++y) {
        for (int x = 0; x < truth.size.x; ++x) {
            const glm::u8vec4 p = truth.at(x, y);
            const bool red = p.r > 150 && p.g < 100 && p.b < 100;
            (x < truth.size.x / 2 ? redLeft : redRight) += red;
        }
    }
    EXPECT_GT(redRight, 4 * redLeft + 20) << redLeft << " red pixels left, " << redRight << " right";
}

TEST(SandboxCliTest, SoakRefusesImageOptionsAndUnknownScenes) {
    expectFailure("--headless --soak 3 --out x.png", 2, "--out does not apply to --soak");
    expectFailure("--headless --soak 3 --soak-scenes knob,nope", 2, "--soak-scenes: unknown scene 'nope'");
    expectFailure("--headless --soak-scenes knob", 2, "--soak-scenes applies to --soak only");
    expectFailure("--headless --soak 2", 2, "--soak: '2' is not an integer in [3, 100000]");
    expectFailure("--soak 3", 2, "--soak applies to --headless only");
}

TEST(SandboxCliTest, UnknownTechniqueExits2) {
    expectFailure("--headless --technique nope", 2,
                  "--technique: unknown technique 'nope' (hard, slope-scaled, hw-pcf, pcf, gsm,");
    expectFailure("--headless --compare gsm2", 2, "--compare: unknown technique 'gsm2'");
}

TEST(SandboxCliTest, SchemaInvalidGltfExits1NamingTheMember) {
    const auto folder = sandbox::test::freshFolder("cli-wrong-type");
    const auto scene = folder / "wrong-type.gltf";
    engine::writeTextFile(scene, R"({"asset":{"version":"2.0"},"nodes":[{"mesh":"0"}]})");
    expectFailure("--headless --scene " + scene.string() + " --size 32x24", 1,
                  scene.string() + ": nodes[0].mesh: expected a non-negative integer");
}

TEST(SandboxCliTest, UnknownSceneExits2) {
    expectFailure("--headless --scene nope", 2, "--scene: unknown scene 'nope' (scenes: bowl, crease-cube,");
    expectFailure("--headless --scene /nonexistent/x.gltf", 2,
                  "--scene: scene file '/nonexistent/x.gltf' does not exist");
}

TEST(SandboxCliTest, BadSizeAndValuesExit2) {
    expectFailure("--headless --size 0x10", 2, "--size: '0' is not an integer in [1, 16384]");
    expectFailure("--headless --size big", 2, "--size: 'big' is not WIDTHxHEIGHT");
    expectFailure("--headless --frames", 2, "--frames needs a value");
    expectFailure("--headless --level 7", 2, "--level: '7' is not an integer in [-1, 6]");
    expectFailure("--headless --bogus", 2, "unknown option '--bogus'");
    expectFailure("--headless --no-ui", 2, "--no-ui applies to the window only");
    expectFailure("--out x.png", 2, "--out applies to --headless only");
}

TEST(SandboxCliTest, BadSettingsFilesExit2NamingFileAndField) {
    const auto folder = sandbox::test::freshFolder("cli-settings");
    const auto write = [&](const std::string& name, const std::string& text) {
        const std::filesystem::path path = folder / name;
        engine::writeTextFile(path, text);
        return path.string();
    };
    const std::string taps = write("taps.json", R"({"a": {"pcfTaps": 12}})");
    expectFailure("--headless --settings " + taps, 2, taps + ": field 'a': pcfTaps 12 is outside [2, 8]");
    const std::string scene = write("scene.json", R"({"scene": "nope"})");
    expectFailure("--headless --settings " + scene, 2, scene + ": field 'scene': unknown scene 'nope'");
    expectFailure("--headless --settings " + (folder / "missing.json").string(), 2,
                  (folder / "missing.json").string() + ": cannot open");
}

TEST(SandboxCliTest, WindowWithoutDisplaySuggestsHeadless) {
    const auto result = runSandbox("--frames 1", "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_NE(result.status, 0) << result.output;
    EXPECT_NE(result.output.find("cannot open a display"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("--headless"), std::string::npos) << result.output;
}

TEST(SandboxCliTest, HelpListsTheOptions) {
    const auto result = runSandbox("--help");
    EXPECT_EQ(result.status, 0);
    for (const char* option : {"--headless", "--scene", "--technique", "--compare", "--settings", "--out",
                               "--size", "--frames", "--screenshot", "--no-ui"}) {
        EXPECT_NE(result.output.find(option), std::string::npos) << option;
    }
}
