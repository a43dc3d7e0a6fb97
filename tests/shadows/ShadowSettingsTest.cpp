// ShadowSettings: validation names every bad field; the tap pattern the settings select (no GL).
#include <shadows/ShadowSettings.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace shadows;

TEST(ShadowSettingsTest, ValidateNamesEveryBadField) {
    ShadowSettings settings;
    settings.resolution = 32;
    settings.pcfRadius = -1.0f;
    settings.fuzzyScale = std::nanf("");
    settings.pcfTaps = 12;
    const std::vector<std::string> problems = settings.validate();
    ASSERT_EQ(problems.size(), 4u);
    EXPECT_EQ(problems[0], "resolution 32 is outside [64, 16384]");
    EXPECT_TRUE(ShadowSettings{}.validate().empty());
}

TEST(ShadowSettingsTest, LightSizeScaleIsRefusedNegativeNotANumberOrHuge) {
    for (const float scale : {-0.5f, std::nanf(""), std::numeric_limits<float>::infinity(), 17.0f}) {
        ShadowSettings settings;
        settings.technique = ShadowTechnique::Pcss;
        settings.lightSizeScale = scale;
        const std::vector<std::string> problems = settings.validate();
        ASSERT_EQ(problems.size(), 1u) << scale;
        EXPECT_NE(problems[0].find("lightSizeScale"), std::string::npos) << problems[0];
    }
    ShadowSettings hard;
    hard.lightSizeScale = 0.0f;
    EXPECT_TRUE(hard.validate().empty());
}

TEST(ShadowSettingsTest, CircularAverageFormsForceTheCircularLayout) {
    ShadowSettings settings;
    settings.technique = ShadowTechnique::PcfGsmAverageGradient;
    EXPECT_EQ(settings.tapPattern().layout, TapLayout::Grid);
    settings.averageGradientForm = AverageGradientForm::Circular8Vec4;
    EXPECT_EQ(settings.tapPattern().layout, TapLayout::Circular8);
    EXPECT_EQ(settings.tapPattern().offsets.size(), 8u);
    settings.technique = ShadowTechnique::Pcf;
    EXPECT_EQ(settings.tapPattern().layout, TapLayout::Grid) << "only the average gradient uses the forms";
}

TEST(ShadowSettingsTest, DepthStepsOfTheFormats) {
    EXPECT_EQ(depthStep(DepthFormat::D16), 1.0f / 65535.0f);
    EXPECT_EQ(depthStep(DepthFormat::D24), 1.0f / 16777215.0f);
    EXPECT_EQ(depthStep(DepthFormat::D32F), 0.0f);
}
