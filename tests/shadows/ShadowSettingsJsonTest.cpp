#include <shadows/ShadowSettingsJson.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace shadows;

TEST(ShadowSettingsJsonTest, RoundTripsEveryField) {
    ShadowSettings settings;
    settings.technique = ShadowTechnique::ReceiverPlaneBias;
    settings.resolution = 512;
    settings.depthFormat = DepthFormat::D16;
    settings.casterFaces = CasterFaces::Back;
    settings.constantBiasTexels = 0.125f;
    settings.depthBiasSteps = 3.5f;
    settings.slopeScale = 2.5f;
    settings.slopeUnits = 3.0f;
    settings.pcfLayout = TapLayout::Poisson;
    settings.pcfTaps = 32;
    settings.pcfRadius = 2.75f;
    settings.pcfRotate = true;
    settings.gradientSource = GradientSource::ScreenSpace;
    settings.fuzzyScale = 0.5f;
    settings.averageGradientForm = AverageGradientForm::Circular8Vec4;
    settings.receiverPlaneKernel = ReceiverPlaneKernel::PerTap;
    settings.receiverPlaneClamp = false;
    settings.normalOffsetTexels = 0.75f;
    settings.floorReceiverDepth = true;
    settings.texelSnapping = false;
    settings.debugView = ShadowDebugView::Bias;
    EXPECT_EQ(settingsFromJson(settingsToJson(settings), "test"), settings);
    EXPECT_EQ(settingsFromJson(settingsToJson(ShadowSettings{}), "test"), ShadowSettings{});
}

TEST(ShadowSettingsJsonTest, MissingFieldsKeepDefaults) {
    const ShadowSettings settings = settingsFromJson(R"({"technique": "gsm"})", "test");
    EXPECT_EQ(settings.technique, ShadowTechnique::Gsm);
    EXPECT_EQ(settings.resolution, ShadowSettings{}.resolution);
}

struct BadJsonCase {
    const char* name;
    const char* text;
    const char* expected;
};

class ShadowSettingsJsonErrorTest : public testing::TestWithParam<BadJsonCase> {};

TEST_P(ShadowSettingsJsonErrorTest, NamesSourceAndField) {
    try {
        (void)settingsFromJson(GetParam().text, "my.json");
        FAIL() << "accepted " << GetParam().text;
    } catch (const SettingsError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("my.json: ", 0), 0u) << message;
        EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ShadowSettingsJsonErrorTest,
    testing::Values(
        BadJsonCase{"malformed", R"({"technique": )", "not valid JSON"},
        BadJsonCase{"notAnObject", "[1, 2]", "expected a JSON object"},
        BadJsonCase{"unknownField", R"({"techniqe": "gsm"})", "unknown field 'techniqe'"},
        BadJsonCase{"renamedField", R"({"msmQuantize16": true})",
                    "unknown field 'msmQuantize16' (now 'moments16')"},
        BadJsonCase{"unknownTechnique", R"({"technique": "shadow-volumes"})", "field 'technique'"},
        BadJsonCase{"wrongType", R"({"resolution": "big"})", "field 'resolution'"},
        BadJsonCase{"fractionalInteger", R"({"pcfTaps": 4.5})", "field 'pcfTaps'"},
        BadJsonCase{"hugeNumber", R"({"pcfRadius": 1e300})", "field 'pcfRadius'"},
        BadJsonCase{"outOfRange", R"({"resolution": 32})", "resolution 32 is outside [64, 16384]"},
        BadJsonCase{"badBool", R"({"pcfRotate": 1})", "field 'pcfRotate'"},
        BadJsonCase{"negativeBias", R"({"constantBiasTexels": -1})", "constantBiasTexels"},
        BadJsonCase{"hugeDepthBias", R"({"depthBiasSteps": 1e9})", "depthBiasSteps"},
        BadJsonCase{"negativeNormalOffset", R"({"normalOffsetTexels": -0.5})", "normalOffsetTexels"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(ShadowSettingsJsonTest, FilesRoundTripAndMissingFilesAreNamed) {
    const auto path =
        std::filesystem::temp_directory_path() / ("gs_settings_" + std::to_string(::getpid()) + ".json");
    ShadowSettings settings;
    settings.technique = ShadowTechnique::PcfGsmQuadratic;
    saveSettings(settings, path);
    EXPECT_EQ(loadSettings(path), settings);
    std::filesystem::remove(path);
    try {
        (void)loadSettings(path);
        FAIL();
    } catch (const SettingsError& error) {
        EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos);
    }
}

// Robustness (see docs/ROBUSTNESS.md): each of these used to escape as another exception, crash or misread.

TEST(ShadowSettingsJsonTest, NumberTooLargeForADoubleIsASettingsError) {
    // Found by the fuzzer: nlohmann::json reports the overflow as out_of_range, not parse_error, and it
    // escaped settingsFromJson.
    try {
        (void)settingsFromJson(R"({"pcfRadius": 73.5e3844073709551615})", "my.json");
        FAIL();
    } catch (const SettingsError& error) {
        EXPECT_NE(std::string(error.what())
                      .find("my.json: not valid JSON: [json.exception.out_of_range.406] "
                            "number overflow"),
                  std::string::npos)
            << error.what();
    }
}

TEST(ShadowSettingsJsonTest, DeeplyNestedValuesAreDescribedWithoutRecursion) {
    // The error message used to dump the value, recursing once per level: a stack overflow at this depth.
    const std::size_t depth = 1'000'000;
    const std::string text = R"({"technique": )" + std::string(depth, '[') + std::string(depth, ']') + "}";
    try {
        (void)settingsFromJson(text, "my.json");
        FAIL();
    } catch (const SettingsError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("my.json: field 'technique': an array is not one of ", 0),
                  0u)
            << error.what();
    }
}

TEST(ShadowSettingsJsonTest, UnsignedNumbersBeyondInt64AreOutOfRange) {
    // 18446744073709551615 used to be read as -1 (and reported as "resolution -1 is outside ...").
    try {
        (void)settingsFromJson(R"({"resolution": 18446744073709551615})", "my.json");
        FAIL();
    } catch (const SettingsError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "my.json: field 'resolution': 18446744073709551615 is out of range");
    }
}

TEST(ShadowSettingsJsonTest, LongStringsAreCutInMessages) {
    try {
        (void)settingsFromJson(R"({"technique": ")" + std::string(100000, 'x') + R"("})", "my.json");
        FAIL();
    } catch (const SettingsError& error) {
        EXPECT_LT(std::string(error.what()).size(), 1000u);
        EXPECT_NE(
            std::string(error.what()).find(R"(: "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx... is not one of )"),
            std::string::npos)
            << error.what();
    }
}
