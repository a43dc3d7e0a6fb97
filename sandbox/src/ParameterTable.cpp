#include "ParameterTable.h"

#include <algorithm>
#include <cstdlib>

namespace sandbox {

std::span<const shadows::SettingRow> ParameterTable::shadowRows() {
    static const std::vector<shadows::SettingRow> rows = [] {
        std::vector<shadows::SettingRow> edited;
        for (const shadows::SettingRow& row : shadows::settingsSchema()) {
            if (row.name != "technique") {
                edited.push_back(row);
            }
        }
        return edited;
    }();
    return rows;
}

std::vector<int> ParameterTable::offeredValues(const shadows::IntSetting& field,
                                               const shadows::ShadowSettings& settings) {
    const std::optional<shadows::IntLimits> limits = field.limits(settings);
    return limits ? limits->offered() : std::vector<int>{settings.*field.member};
}

int ParameterTable::nearest(const std::vector<int>& values, int value) {
    return *std::min_element(values.begin(), values.end(),
                             [value](int a, int b) { return std::abs(a - value) < std::abs(b - value); });
}

void ParameterTable::repairIntegers(shadows::ShadowSettings& settings) {
    for (const shadows::SettingRow& row : shadowRows()) {
        const auto* field = std::get_if<shadows::IntSetting>(&row.field);
        if (!field || !row.applies(settings)) {
            continue;
        }
        shadows::ShadowSettings snapped = settings;
        snapped.*field->member = nearest(offeredValues(*field, settings), settings.*field->member);
        if (snapped.validate().size() < settings.validate().size()) {
            settings = snapped;
        }
    }
}

} // namespace sandbox
