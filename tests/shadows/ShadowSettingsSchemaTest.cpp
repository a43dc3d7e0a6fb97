// The settings schema: one row per ShadowSettings field, validation from its limits, and the settings table
// of docs/SHADOWS.md generated from it (no GL).
#include "GeneratedDocs.h"

#include <shadows/ShadowSettingsSchema.h>

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

using namespace shadows;

namespace {

/// A settings object in which only the field of `row` differs from the defaults.
ShadowSettings changedOnly(const SettingRow& row) {
    ShadowSettings settings;
    if (const auto* real = std::get_if<FloatSetting>(&row.field)) {
        settings.*real->member += 1.0f;
    } else if (const auto* integer = std::get_if<IntSetting>(&row.field)) {
        settings.*integer->member += 1;
    } else if (const auto* toggle = std::get_if<BoolSetting>(&row.field)) {
        settings.*toggle->member = !(settings.*toggle->member);
    } else {
        const auto& choice = std::get<EnumSetting>(row.field);
        choice.set(settings, (choice.get(settings) + 1) % static_cast<int>(choice.names.size()));
    }
    return settings;
}

} // namespace

TEST(ShadowSettingsSchemaTest, EveryRowNamesItsOwnMemberOnce) {
    std::set<std::string_view> names;
    for (const SettingRow& row : settingsSchema()) {
        EXPECT_TRUE(names.insert(row.name).second) << row.name << " has two rows";
        EXPECT_FALSE(row.label.empty() || row.help.empty()) << row.name;
        // Changing the row's member changes the settings: no two rows share a member.
        EXPECT_NE(changedOnly(row), ShadowSettings{}) << row.name;
        for (const SettingRow& other : settingsSchema()) {
            if (&other != &row) {
                EXPECT_NE(changedOnly(row), changedOnly(other)) << row.name << " and " << other.name;
            }
        }
    }
}

TEST(ShadowSettingsSchemaTest, DefaultsAreValidAndInsideTheSliders) {
    const ShadowSettings defaults;
    EXPECT_TRUE(defaults.validate().empty());
    for (const SettingRow& row : settingsSchema()) {
        EXPECT_FALSE(row.problem(defaults)) << row.name;
        if (const auto* real = std::get_if<FloatSetting>(&row.field)) {
            EXPECT_GE(defaults.*real->member, real->sliderMin) << row.name;
            EXPECT_LE(defaults.*real->member, real->sliderMax) << row.name;
        }
    }
}

TEST(ShadowSettingsSchemaTest, ProblemsNameTheFieldTheValueAndTheRange) {
    ShadowSettings settings;
    settings.resolution = 32;
    EXPECT_EQ(findSetting("resolution")->problem(settings), "resolution 32 is outside [64, 16384]");
    settings.pcfLayout = TapLayout::Poisson;
    settings.pcfTaps = 4;
    EXPECT_EQ(findSetting("pcfTaps")->problem(settings), "pcfTaps 4 is outside [8, 64] for a Poisson disk");
    settings.pcfLayout = TapLayout::Circular8;
    EXPECT_FALSE(findSetting("pcfTaps")->problem(settings)) << "circular-8 ignores the tap count";
    settings.pcfRadius = 0.0f;
    EXPECT_EQ(findSetting("pcfRadius")->problem(settings), "pcfRadius must be a finite number > 0 (texels)");
    settings.jitterTaps = 8;
    settings.earlyOutTestTaps = 8;
    EXPECT_TRUE(findSetting("earlyOutTestTaps")->problem(settings))
        << "test taps must be fewer than the taps";
    settings.earlyOutTestTaps = 0;
    EXPECT_FALSE(findSetting("earlyOutTestTaps")->problem(settings));
    EXPECT_EQ(findSetting("nope"), nullptr);
}

TEST(ShadowSettingsSchemaTest, OfferedIntegersAreTheAcceptedOnes) {
    const IntLimits evenTaps{.min = 8, .max = 14, .step = 2, .zeroAllowed = true};
    EXPECT_EQ(evenTaps.offered(), (std::vector<int>{0, 8, 10, 12, 14}));
    EXPECT_TRUE(evenTaps.contains(0) && evenTaps.contains(10));
    EXPECT_FALSE(evenTaps.contains(9) || evenTaps.contains(16) || evenTaps.contains(2));
    const IntLimits sizes{.min = 64, .max = 512, .powersOfTwo = true};
    EXPECT_EQ(sizes.offered(), (std::vector<int>{64, 128, 256, 512}));
    EXPECT_TRUE(sizes.contains(100)) << "powers of two are what is offered, not what is accepted";
}

TEST(ShadowSettingsSchemaTest, IntegerLimitsForCommandLines) {
    EXPECT_EQ(integerLimits("resolution").max, 16384);
    EXPECT_EQ(integerLimits("pcfTaps").max, 8);
    EXPECT_EQ(integerLimits("pcfTaps", ShadowSettings{.pcfLayout = TapLayout::Poisson}).max, 64);
    EXPECT_THROW(integerLimits("pcfRadius"), std::logic_error);
    EXPECT_THROW(integerLimits("pcfTaps", ShadowSettings{.pcfLayout = TapLayout::Circular8}),
                 std::logic_error);
}

TEST(ShadowSettingsSchemaTest, DocsSettingsTableIsGenerated) {
    expectGeneratedSection("docs/SHADOWS.md", "settings", settingsMarkdownTable());
}
