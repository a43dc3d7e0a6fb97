#pragma once

#include <shadows/ShadowSettings.h>

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace shadows {

/// @brief The values a float setting accepts: finite, at least `min` (above it when `minExclusive`), at most
/// `max`.
struct FloatLimits {
    /// Lowest value accepted (excluded when `minExclusive`).
    float min = 0.0f;
    /// Highest value accepted.
    float max = std::numeric_limits<float>::infinity();
    /// Whether `min` itself is refused (the setting must be positive).
    bool minExclusive = false;

    /// @brief Whether `value` is finite and within the limits.
    [[nodiscard]] bool contains(float value) const;
};

/// @brief A float setting; the slider range is what the sandbox offers, narrower than `valid` where the
/// valid range is unbounded or mostly useless.
struct FloatSetting {
    /// The ShadowSettings field.
    float ShadowSettings::*member;
    /// The values validation accepts.
    FloatLimits valid;
    /// Lower end of the sandbox's slider.
    float sliderMin;
    /// Upper end of the sandbox's slider.
    float sliderMax;
    /// printf format of the slider's value.
    const char* format;
    /// Logarithmic slider (values spanning orders of magnitude).
    bool logarithmic = false;
};

/// @brief The values an integer setting accepts: `min`, `min + step`, ... up to `max`, and 0 when
/// `zeroAllowed`. `powersOfTwo` narrows what the sandbox offers (every value stays valid) unless
/// `powerOfTwoRequired`.
struct IntLimits {
    /// Lowest value accepted, besides 0 when `zeroAllowed`.
    int min;
    /// Highest value accepted.
    int max;
    /// Accepted values are `min` plus multiples of `step`.
    int step = 1;
    /// Whether 0 is accepted too (it switches the feature off).
    bool zeroAllowed = false;
    /// Whether the sandbox offers only powers of two.
    bool powersOfTwo = false;
    /// Whether only powers of two are accepted (and offered).
    bool powerOfTwoRequired = false;
    /// Says which case of a setting-dependent range applies, e.g. "for a grid".
    std::string_view qualifier = {};

    /// @brief Whether `value` is one of the accepted values.
    [[nodiscard]] bool contains(int value) const;
    /// @brief The values the sandbox offers, ascending.
    [[nodiscard]] std::vector<int> offered() const;
    /// @brief "[2, 8]", "[8, 64] in steps of 2", "0 or [4, 14] in steps of 2".
    [[nodiscard]] std::string describe() const;
};

/// @brief An integer setting; its limits may depend on the other settings (pcfTaps on the layout), and an
/// empty result means any value is accepted (the setting is ignored there).
struct IntSetting {
    /// The ShadowSettings field.
    int ShadowSettings::*member;
    /// The accepted values given the other settings, or nullopt where any value is accepted.
    std::optional<IntLimits> (*limits)(const ShadowSettings&);
};

/// @brief A true/false setting; every value is valid.
struct BoolSetting {
    /// The ShadowSettings field.
    bool ShadowSettings::*member;
};

/// @brief An enum setting, read and written through its index in the enum's name table.
struct EnumSetting {
    /// The enum's names in declaration order (its name table).
    std::vector<std::string_view> names;
    /// The index of the field's value in `names`.
    int (*get)(const ShadowSettings&);
    /// Sets the field to the value at index `names[i]`.
    void (*set)(ShadowSettings&, int);

    /// @brief "grid, poisson, circular8".
    [[nodiscard]] std::string nameList() const;
};

/// @brief One ShadowSettings field: everything validation, JSON, the sandbox, the docs and command lines
/// need to know about it.
struct SettingRow {
    /// The member's name, also its name in settings files.
    std::string_view name;
    /// Unit of the value ("texels", "world units"), empty for counts and choices.
    std::string_view unit;
    /// Short label for controls and tables.
    std::string_view label;
    /// What the field does, one sentence.
    std::string_view help;
    /// The field's type, with its member pointer (or accessors) and accepted values.
    std::variant<FloatSetting, IntSetting, BoolSetting, EnumSetting> field;
    /// Whether the field changes anything for these settings (their technique's needs and options).
    bool (*applies)(const ShadowSettings&);
    /// Command-line option of the tools that take it (e.g. "--shadow-size"), empty where none does.
    std::string_view option = {};

    /// @brief The problem with this field's value in `settings`, empty when it is acceptable.
    [[nodiscard]] std::optional<std::string> problem(const ShadowSettings& settings) const;
    /// @brief The value in `settings` as written in docs and files ("0.002", "true", "grid").
    [[nodiscard]] std::string valueText(const ShadowSettings& settings) const;
    /// @brief What the field accepts, for docs ("finite >= 0", "[64, 16384]", "grid, poisson, circular8").
    [[nodiscard]] std::string rangeText() const;
    /// @brief The label with its unit, e.g. "PCF radius (texels)".
    [[nodiscard]] std::string labelWithUnit() const;
};

/// @brief Every ShadowSettings field once, in the order the sandbox shows them (technique first).
std::span<const SettingRow> settingsSchema();

/// @brief The row named `name` (a settings-file name), null if there is none.
const SettingRow* findSetting(std::string_view name);

/// @brief The limits of integer setting `name` for `settings` (e.g. "pcfTaps" for their layout), for tools
/// that take the value on their command line. Throws std::logic_error for a name that is no constrained
/// integer.
IntLimits integerLimits(std::string_view name, const ShadowSettings& settings = {});

/// @brief The settings table of docs/SHADOWS.md (Markdown), generated from the schema.
std::string settingsMarkdownTable();

} // namespace shadows
