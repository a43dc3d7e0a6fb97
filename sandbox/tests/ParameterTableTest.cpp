// The parameter table behind the UI agrees with ShadowSettings and its JSON names (no GL).
#include "ParameterTable.h"

#include <shadows/ShadowSettingsJson.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>

using sandbox::ParameterTable;
using shadows::ShadowSettings;
using shadows::ShadowTechnique;

namespace {

std::set<std::string> shownRows(const ShadowSettings& settings) {
    std::set<std::string> names;
    for (const shadows::SettingRow& row : ParameterTable::shadowRows()) {
        if (row.applies(settings)) {
            names.emplace(row.name);
        }
    }
    return names;
}

ShadowSettings with(ShadowTechnique technique) {
    ShadowSettings settings;
    settings.technique = technique;
    return settings;
}

} // namespace

TEST(ParameterTableTest, EveryShadowSettingsFieldButTheTechniqueHasOneRow) {
    std::set<std::string> fields;
    const nlohmann::json defaults = nlohmann::json::parse(shadows::settingsToJson({}));
    for (const auto& [name, value] : defaults.items()) {
        fields.insert(name);
    }
    fields.erase("technique");
    std::multiset<std::string> rows;
    for (const shadows::SettingRow& row : ParameterTable::shadowRows()) {
        rows.emplace(row.name);
    }
    EXPECT_EQ(std::set<std::string>(rows.begin(), rows.end()), fields);
    EXPECT_EQ(rows.size(), fields.size()) << "a field has two rows";
}

TEST(ParameterTableTest, ChoiceOptionsAreTheSettingsFileNames) {
    for (const shadows::SettingRow& row : ParameterTable::shadowRows()) {
        const auto* choice = std::get_if<shadows::EnumSetting>(&row.field);
        if (!choice) {
            continue;
        }
        for (int index = 0; index < static_cast<int>(choice->names.size()); ++index) {
            ShadowSettings settings;
            choice->set(settings, index);
            EXPECT_EQ(choice->get(settings), index) << row.name;
            const auto json = nlohmann::json::parse(shadows::settingsToJson(settings));
            EXPECT_EQ(json.at(std::string(row.name)),
                      std::string(choice->names[static_cast<std::size_t>(index)]))
                << row.name;
        }
    }
}

TEST(ParameterTableTest, DefaultsLieInsideTheRanges) {
    for (const ShadowTechnique technique : shadows::allTechniques()) {
        const ShadowSettings settings = with(technique);
        for (const shadows::SettingRow& row : ParameterTable::shadowRows()) {
            if (const auto* real = std::get_if<shadows::FloatSetting>(&row.field)) {
                const float value = settings.*real->member;
                EXPECT_TRUE(real->valid.contains(value)) << row.name;
                EXPECT_TRUE(value >= real->sliderMin && value <= real->sliderMax) << row.name;
            } else if (const auto* integer = std::get_if<shadows::IntSetting>(&row.field)) {
                const std::vector<int> values = ParameterTable::offeredValues(*integer, settings);
                EXPECT_TRUE(std::is_sorted(values.begin(), values.end())) << row.name;
                EXPECT_NE(std::find(values.begin(), values.end(), settings.*integer->member), values.end())
                    << row.name;
            }
        }
    }
}

TEST(ParameterTableTest, RowsFollowTheTechnique) {
    const std::set<std::string> pcf = shownRows(with(ShadowTechnique::Pcf));
    EXPECT_TRUE(pcf.contains("pcfTaps") && pcf.contains("pcfRadius") && pcf.contains("floorReceiverDepth"));
    EXPECT_FALSE(pcf.contains("fuzzyScale") || pcf.contains("gradientSource") || pcf.contains("slopeScale"));

    const std::set<std::string> gsm = shownRows(with(ShadowTechnique::Gsm));
    EXPECT_TRUE(gsm.contains("fuzzyScale") && gsm.contains("gradientSource"));
    EXPECT_FALSE(gsm.contains("pcfTaps") || gsm.contains("floorReceiverDepth"));

    EXPECT_TRUE(shownRows(with(ShadowTechnique::SlopeScaledBias)).contains("slopeUnits"));
    EXPECT_TRUE(shownRows(with(ShadowTechnique::NormalOffset)).contains("normalOffsetTexels"));
    EXPECT_TRUE(shownRows(with(ShadowTechnique::ReceiverPlaneBias)).contains("receiverPlaneClamp"));

    ShadowSettings circular = with(ShadowTechnique::PcfGsmAverageGradient);
    EXPECT_TRUE(shownRows(circular).contains("pcfTaps"));
    circular.averageGradientForm = shadows::AverageGradientForm::Circular8;
    const std::set<std::string> forced = shownRows(circular);
    EXPECT_TRUE(forced.contains("averageGradientForm") && forced.contains("pcfRadius"));
    EXPECT_FALSE(forced.contains("pcfTaps") || forced.contains("pcfLayout"))
        << "circular-8 forces its layout";
}

TEST(ParameterTableTest, RepairIntegersFixesTapsAfterALayoutSwitchOnly) {
    ShadowSettings settings = with(ShadowTechnique::Pcf);
    settings.resolution = 3000;
    settings.pcfTaps = 4;
    settings.pcfLayout = shadows::TapLayout::Poisson;
    ASSERT_FALSE(settings.validate().empty());
    ParameterTable::repairIntegers(settings);
    EXPECT_TRUE(settings.validate().empty());
    EXPECT_EQ(settings.pcfTaps, 8);
    EXPECT_EQ(settings.resolution, 3000) << "a valid value the slider does not offer is kept";
}

TEST(ParameterTableTest, OfferedIntegersAreValid) {
    // Every value a slider offers is kept and gives valid settings (with the technique that shows the
    // slider).
    for (const ShadowTechnique technique : shadows::allTechniques()) {
        for (const shadows::SettingRow& row : ParameterTable::shadowRows()) {
            const auto* integer = std::get_if<shadows::IntSetting>(&row.field);
            ShadowSettings settings = with(technique);
            if (!integer || !row.applies(settings)) {
                continue;
            }
            for (const int value : ParameterTable::offeredValues(*integer, settings)) {
                // What the UI does after a slider moves: other integers follow (jitterTaps bounds
                // earlyOutTestTaps).
                ShadowSettings edited = settings;
                edited.*integer->member = value;
                ParameterTable::repairIntegers(edited);
                EXPECT_TRUE(edited.validate().empty()) << row.name << " = " << value;
                EXPECT_EQ(edited.*integer->member, value) << row.name;
            }
        }
    }
}

TEST(ParameterTableTest, LightReachesGrazing) {
    EXPECT_EQ(ParameterTable::kElevation.min, 0.5f);
    EXPECT_EQ(ParameterTable::kElevation.max, 90.0f);
}
