// Sandbox settings files: round trips and the errors bad files give (no GL).
#include "SandboxSettings.h"
#include "SandboxError.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>

using sandbox::SandboxError;
using sandbox::SandboxSettings;

namespace {

SandboxSettings everythingSet() {
    SandboxSettings settings;
    settings.scene = "thin-shell";
    settings.level = 2;
    settings.light = SandboxSettings::LightAngles{123.25f, 0.5f};
    settings.camera = sandbox::OrbitCamera{{0.25f, -1.5f, 3.0f}, 271.5f, -12.125f, 7.75f};
    settings.compare = false;
    settings.split = 0.3125f;
    settings.a.technique = shadows::ShadowTechnique::Pcf;
    settings.a.pcfLayout = shadows::TapLayout::Poisson;
    settings.a.pcfTaps = 16;
    settings.a.constantBiasTexels = 0.0123f;
    settings.a.debugView = shadows::ShadowDebugView::Bias;
    settings.b.technique = shadows::ShadowTechnique::ReceiverPlaneBias;
    settings.b.receiverPlaneKernel = shadows::ReceiverPlaneKernel::PerTap;
    settings.b.depthFormat = shadows::DepthFormat::D16;
    settings.b.resolution = 16384; // valid for the module though beyond the UI slider
    return settings;
}

std::string errorOf(const std::string& text) {
    try {
        SandboxSettings::fromJson(text, "bad.json");
    } catch (const SandboxError& error) {
        return error.what();
    }
    return "no error";
}

} // namespace

TEST(SandboxSettingsTest, DefaultsAreTheTwoGradientCorrections) {
    const SandboxSettings settings;
    EXPECT_EQ(settings.a.technique, shadows::ShadowTechnique::PcfGsmPointGradient);
    EXPECT_EQ(settings.b.technique, shadows::ShadowTechnique::PcfGsmAverageGradient);
    EXPECT_TRUE(settings.compare);
    EXPECT_EQ(settings.split, 0.5f);
    EXPECT_EQ(SandboxSettings::fromJson("{}", "empty.json"), settings);
}

TEST(SandboxSettingsTest, JsonRoundTripKeepsEveryField) {
    const SandboxSettings settings = everythingSet();
    const std::string json = settings.toJson();
    EXPECT_EQ(SandboxSettings::fromJson(json, "round.json"), settings) << json;
    // Defaults (file's own light and camera) round trip too, leaving those fields out.
    const std::string defaults = SandboxSettings{}.toJson();
    EXPECT_EQ(defaults.find("camera"), std::string::npos) << defaults;
    EXPECT_EQ(defaults.find("azimuth"), std::string::npos) << defaults;
    EXPECT_EQ(SandboxSettings::fromJson(defaults, "defaults.json"), SandboxSettings{});
}

TEST(SandboxSettingsTest, FileRoundTripIsAtomic) {
    const std::filesystem::path folder = sandbox::test::freshFolder("settings-round-trip");
    const std::filesystem::path path = folder / "view.json";
    everythingSet().save(path);
    EXPECT_EQ(SandboxSettings::load(path), everythingSet());
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) {
        ++files;
    }
    EXPECT_EQ(files, 1u) << "temporary file left beside view.json";
}

TEST(SandboxSettingsTest, BadDocumentsNameTheFileAndField) {
    const std::pair<const char*, const char*> cases[] = {
        {"not json", "bad.json: not valid JSON"},
        {"[1, 2]", "bad.json: expected a JSON object"},
        {R"({"scen": "knob"})", "bad.json: field 'scen': unknown field"},
        {R"({"scene": ""})", "bad.json: field 'scene': \"\" is not a non-empty string"},
        {R"({"level": 9})", "bad.json: field 'level': 9 is not an integer in [-1, 6]"},
        {R"({"azimuth": 0, "elevation": 95})", "bad.json: field 'elevation': 95 is outside [0.5, 90]"},
        {R"({"azimuth": 0, "elevation": 0.1})", "bad.json: field 'elevation': 0.1 is outside [0.5, 90]"},
        {R"({"azimuth": 10})", "bad.json: field 'elevation': missing"},
        {R"({"split": "half"})", "bad.json: field 'split': \"half\" is not a number"},
        {R"({"compare": 1})", "bad.json: field 'compare': 1 is not true or false"},
        {R"({"camera": {"target": [0, 0], "yaw": 0, "pitch": 0, "distance": 1}})",
         "bad.json: field 'camera.target': [0,0] is not an array of 3 numbers"},
        {R"({"camera": {"target": [0, "up", 0], "yaw": 0, "pitch": 0, "distance": 1}})",
         "bad.json: field 'camera.target.y': \"up\" is not a number"},
        {R"({"camera": {"target": [0, 0, 0], "yaw": 0, "pitch": 0}})",
         "bad.json: field 'camera.distance': missing"},
        {R"({"camera": {"target": [0, 0, 0], "yaw": 0, "pitch": 90, "distance": 1}})",
         "bad.json: field 'camera.pitch': 90 is outside [-89, 89]"},
        {R"({"a": 3})", "bad.json: field 'a': 3 is not an object"},
        {R"({"a": {"pcfTaps": 12}})", "bad.json: field 'a': pcfTaps 12 is outside [2, 8] for a grid"},
        {R"({"b": {"technique": "nope"}})", "bad.json: field 'b': field 'technique': \"nope\" is not one of"},
    };
    for (const auto& [text, expected] : cases) {
        EXPECT_NE(errorOf(text).find(expected), std::string::npos)
            << "document: " << text << "\n  error: " << errorOf(text) << "\n  wanted: " << expected;
    }
}

TEST(SandboxSettingsTest, MissingFileIsNamed) {
    try {
        SandboxSettings::load("/nonexistent/view.json");
        FAIL() << "expected SandboxError";
    } catch (const SandboxError& error) {
        EXPECT_NE(std::string(error.what()).find("/nonexistent/view.json: cannot open"), std::string::npos)
            << error.what();
    }
}
