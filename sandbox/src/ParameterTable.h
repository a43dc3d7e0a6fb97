#pragma once

#include <shadows/ShadowSettingsSchema.h>

#include <span>
#include <vector>

namespace sandbox {

/// @brief Closed interval [min, max] of an editable value.
template <typename T>
struct Range {
    T min;
    T max;

    [[nodiscard]] constexpr bool contains(T value) const { return value >= min && value <= max; }
};

/// @brief Every value the sandbox lets people edit: the ranges of its own settings, and the rows of the
/// shadow settings schema (shadows::settingsSchema()).
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

    /// @brief The shadow settings the UI edits: every row of shadows::settingsSchema() except the technique
    /// (picked from shadows::techniqueTable()), in the schema's order.
    [[nodiscard]] static std::span<const shadows::SettingRow> shadowRows();

    /// @brief The values the slider of an integer row offers for `settings`, ascending; the current value
    /// alone where the row accepts any.
    [[nodiscard]] static std::vector<int> offeredValues(const shadows::IntSetting& field,
                                                        const shadows::ShadowSettings& settings);

    /// @brief Moves applicable integer fields to their nearest offered value where that makes invalid
    /// settings valid: switching the PCF layout can leave pcfTaps outside the new layout's range. Valid
    /// values the sliders do not offer (e.g. a 3000-texel map from a file) are kept.
    static void repairIntegers(shadows::ShadowSettings& settings);

    /// @brief The offered value nearest to `value` (`values` ascending, not empty).
    static int nearest(const std::vector<int>& values, int value);
};

} // namespace sandbox
