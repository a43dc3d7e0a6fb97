#pragma once

#include <shadows/ShadowSettings.h>

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace sandbox {

/// @brief Closed interval [min, max] of an editable value.
template <typename T>
struct Range {
    T min;
    T max;

    [[nodiscard]] constexpr bool contains(T value) const { return value >= min && value <= max; }
};

/// @brief The one table of every value the sandbox lets people edit: the ranges of its own settings, and one
/// row per ShadowSettings field (its settings-file name, label, range and the techniques it applies to).
///
/// The UI draws its controls from this table. Sandbox settings files are checked against the k* ranges;
/// shadow settings in files only have to pass ShadowSettings::validate, so a file may hold values beyond a
/// slider's range (the slider shows them, Ctrl+click types any value).
class ParameterTable {
public:
    /// Subdivision level of every subdivided mesh; -1 keeps each node's own (content::SceneLoadOptions).
    static constexpr Range<int> kLevel{-1, 6};
    /// Light azimuth in degrees around the up axis (+Y), measured from +Z towards +X.
    static constexpr Range<float> kAzimuth{0.0f, 360.0f};
    /// Light elevation above the ground plane in degrees, from grazing to overhead.
    static constexpr Range<float> kElevation{0.5f, 90.0f};
    /// Divider position as a fraction of the view width (A left of it, B right of it).
    static constexpr Range<float> kSplit{0.0f, 1.0f};
    /// Orbit camera pitch in degrees; short of ±90 so the view never looks straight along the up axis.
    static constexpr Range<float> kPitch{-89.0f, 89.0f};
    /// Orbit camera distance to its target, world units.
    static constexpr Range<float> kDistance{0.05f, 1000.0f};

    /// @brief A float field edited with a slider.
    struct FloatField {
        float shadows::ShadowSettings::*member;
        Range<float> range;
        /// printf format of the slider's value.
        const char* format;
        /// Logarithmic slider (values spanning orders of magnitude).
        bool logarithmic;
    };
    /// @brief An integer field edited with a slider over the values it may take.
    struct IntField {
        int shadows::ShadowSettings::*member;
        /// The values offered, ascending; they may depend on other fields (pcfTaps on the layout).
        std::function<std::vector<int>(const shadows::ShadowSettings&)> values;
    };
    /// @brief A bool field edited with a checkbox.
    struct ToggleField {
        bool shadows::ShadowSettings::*member;
    };
    /// @brief An enum field: options are the enum's values in declaration order, named as in settings files.
    struct ChoiceField {
        std::vector<std::string> options;
        std::function<int(const shadows::ShadowSettings&)> get;
        std::function<void(shadows::ShadowSettings&, int)> set;
    };

    /// @brief One editable ShadowSettings field.
    struct Row {
        /// Field name in settings files (shadows::settingsToJson).
        std::string_view name;
        /// Label shown in the UI, with its unit.
        std::string_view label;
        /// What the field does, shown as a tooltip.
        std::string_view help;
        std::variant<FloatField, IntField, ToggleField, ChoiceField> field;
        /// Whether the field changes anything for these settings (their technique and options).
        std::function<bool(const shadows::ShadowSettings&)> applies;
    };

    /// @brief Every ShadowSettings field except the technique (picked from shadows::techniqueTable()), in the
    /// order the UI shows them.
    [[nodiscard]] static std::span<const Row> shadowRows();

    /// @brief Moves applicable integer fields to their nearest offered value where that makes invalid
    /// settings valid: switching the PCF layout can leave pcfTaps outside the new layout's range. Valid
    /// values the sliders do not offer (e.g. a 16384 map from a file) are kept.
    static void repairIntegers(shadows::ShadowSettings& settings);

    /// @brief The offered value nearest to `value` (`values` ascending, not empty).
    static int nearest(const std::vector<int>& values, int value);
};

} // namespace sandbox
