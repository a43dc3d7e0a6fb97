#include <shadows/ShadowSettingsJson.h>

#include <engine/AtomicFile.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

namespace shadows {

namespace {

using Json = nlohmann::json;

template <typename Enum>
struct EnumNames {
    std::vector<std::pair<Enum, std::string_view>> names;

    std::string_view nameOf(Enum value) const {
        for (const auto& [entry, name] : names) {
            if (entry == value) {
                return name;
            }
        }
        return "?";
    }
    std::string list() const {
        std::string out;
        for (const auto& [entry, name] : names) {
            out += (out.empty() ? "" : ", ") + std::string(name);
        }
        return out;
    }
};

const EnumNames<TapLayout> kLayouts{
    {{TapLayout::Grid, "grid"}, {TapLayout::Poisson, "poisson"}, {TapLayout::Circular8, "circular8"}}};
const EnumNames<CasterFaces> kFaces{{{CasterFaces::Front, "front"}, {CasterFaces::Back, "back"}}};
const EnumNames<AverageGradientForm> kForms{{{AverageGradientForm::LeastSquares, "least-squares"},
                                             {AverageGradientForm::Circular8, "circular8"},
                                             {AverageGradientForm::Circular8Vec4, "circular8-vec4"}}};
const EnumNames<ReceiverPlaneKernel> kKernels{
    {{ReceiverPlaneKernel::Bilinear2x2, "bilinear2x2"}, {ReceiverPlaneKernel::PerTap, "per-tap"}}};

EnumNames<ShadowTechnique> techniqueNames() {
    EnumNames<ShadowTechnique> names;
    for (const ShadowTechnique technique : allTechniques()) {
        names.names.emplace_back(technique, toString(technique));
    }
    return names;
}
template <typename Enum, std::size_t N>
EnumNames<Enum> namesFrom(const Enum (&values)[N]) {
    EnumNames<Enum> names;
    for (const Enum value : values) {
        names.names.emplace_back(value, toString(value));
    }
    return names;
}
const DepthFormat kFormats[] = {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F};
const GradientSource kSources[] = {GradientSource::StoredDerivatives, GradientSource::CentralDifferences,
                                   GradientSource::ScreenSpace};
const ShadowDebugView kViews[] = {
    ShadowDebugView::None,      ShadowDebugView::TexelCheckerboard, ShadowDebugView::GradientMagnitude,
    ShadowDebugView::Bias,      ShadowDebugView::Visibility,        ShadowDebugView::ShadowMap,
    ShadowDebugView::FullKernel};

/// The offending value for an error message: scalars as written (strings cut short), arrays and objects by
/// kind only. Dumping a container recurses once per nesting level, so a deeply nested value in a settings
/// file would overflow the stack while its error was being reported.
std::string describe(const Json& value) {
    if (value.is_array()) {
        return "an array";
    }
    if (value.is_object()) {
        return "an object";
    }
    constexpr std::size_t kLongest = 40;
    std::string text = value.dump();
    if (text.size() > kLongest) {
        text = text.substr(0, kLongest) + "...";
    }
    return text;
}

/// One field: how to write it and how to read it (throwing a message without the source prefix).
struct Field {
    std::function<Json(const ShadowSettings&)> write;
    std::function<void(ShadowSettings&, const Json&)> read;
};

template <typename Enum>
Field enumField(Enum ShadowSettings::*member, EnumNames<Enum> names) {
    return {[=](const ShadowSettings& s) { return Json(std::string(names.nameOf(s.*member))); },
            [=](ShadowSettings& s, const Json& value) {
                if (value.is_string()) {
                    for (const auto& [entry, name] : names.names) {
                        if (value.get<std::string>() == name) {
                            s.*member = entry;
                            return;
                        }
                    }
                }
                throw std::invalid_argument(describe(value) + " is not one of " + names.list());
            }};
}

Field floatField(float ShadowSettings::*member) {
    return {[=](const ShadowSettings& s) { return Json(s.*member); },
            [=](ShadowSettings& s, const Json& value) {
                if (!value.is_number()) {
                    throw std::invalid_argument(describe(value) + " is not a number");
                }
                const double number = value.get<double>();
                if (!std::isfinite(number) || std::abs(number) > 3.0e38) {
                    throw std::invalid_argument(describe(value) + " is out of range");
                }
                s.*member = static_cast<float>(number);
            }};
}

Field intField(int ShadowSettings::*member) {
    return {[=](const ShadowSettings& s) { return Json(s.*member); },
            [=](ShadowSettings& s, const Json& value) {
                if (!value.is_number_integer()) {
                    throw std::invalid_argument(describe(value) + " is not an integer");
                }
                // Unsigned numbers above INT64_MAX would wrap to negative int64 values, so compare them
                // unsigned (18446744073709551615 once read as -1).
                const bool inRange = value.is_number_unsigned() ? value.get<std::uint64_t>() <= (1u << 30)
                                                                : value.get<std::int64_t>() >= -(1 << 30) &&
                                                                      value.get<std::int64_t>() <= (1 << 30);
                if (!inRange) {
                    throw std::invalid_argument(describe(value) + " is out of range");
                }
                s.*member = value.get<int>();
            }};
}

Field boolField(bool ShadowSettings::*member) {
    return {[=](const ShadowSettings& s) { return Json(s.*member); },
            [=](ShadowSettings& s, const Json& value) {
                if (!value.is_boolean()) {
                    throw std::invalid_argument(describe(value) + " is not true or false");
                }
                s.*member = value.get<bool>();
            }};
}

const std::map<std::string, Field>& fields() {
    static const std::map<std::string, Field> table = {
        {"technique", enumField(&ShadowSettings::technique, techniqueNames())},
        {"resolution", intField(&ShadowSettings::resolution)},
        {"depthFormat", enumField(&ShadowSettings::depthFormat, namesFrom(kFormats))},
        {"casterFaces", enumField(&ShadowSettings::casterFaces, kFaces)},
        {"constantBias", floatField(&ShadowSettings::constantBias)},
        {"slopeScale", floatField(&ShadowSettings::slopeScale)},
        {"slopeUnits", floatField(&ShadowSettings::slopeUnits)},
        {"pcfLayout", enumField(&ShadowSettings::pcfLayout, kLayouts)},
        {"pcfTaps", intField(&ShadowSettings::pcfTaps)},
        {"pcfRadius", floatField(&ShadowSettings::pcfRadius)},
        {"pcfRotate", boolField(&ShadowSettings::pcfRotate)},
        {"gradientSource", enumField(&ShadowSettings::gradientSource, namesFrom(kSources))},
        {"fuzzyScale", floatField(&ShadowSettings::fuzzyScale)},
        {"averageGradientForm", enumField(&ShadowSettings::averageGradientForm, kForms)},
        {"receiverPlaneKernel", enumField(&ShadowSettings::receiverPlaneKernel, kKernels)},
        {"receiverPlaneClamp", boolField(&ShadowSettings::receiverPlaneClamp)},
        {"normalOffsetTexels", floatField(&ShadowSettings::normalOffsetTexels)},
        {"floorReceiverDepth", boolField(&ShadowSettings::floorReceiverDepth)},
        {"texelSnapping", boolField(&ShadowSettings::texelSnapping)},
        {"momentBlurRadius", intField(&ShadowSettings::momentBlurRadius)},
        {"vsmMinimumVariance", floatField(&ShadowSettings::vsmMinimumVariance)},
        {"lightBleedingReduction", floatField(&ShadowSettings::lightBleedingReduction)},
        {"msmMomentBias", floatField(&ShadowSettings::msmMomentBias)},
        {"msmQuantize16", boolField(&ShadowSettings::msmQuantize16)},
        {"jitterTaps", intField(&ShadowSettings::jitterTaps)},
        {"earlyOutTestTaps", intField(&ShadowSettings::earlyOutTestTaps)},
        {"debugView", enumField(&ShadowSettings::debugView, namesFrom(kViews))},
    };
    return table;
}

} // namespace

std::string settingsToJson(const ShadowSettings& settings) {
    Json document = Json::object();
    for (const auto& [name, field] : fields()) {
        document[name] = field.write(settings);
    }
    return document.dump(2) + "\n";
}

ShadowSettings settingsFromJson(std::string_view text, const std::string& source) {
    Json document;
    try {
        document = Json::parse(text.begin(), text.end());
    } catch (const Json::exception& error) {
        // Not only parse_error: a number too large for a double is an out_of_range error.
        throw SettingsError(source + ": not valid JSON: " + error.what());
    }
    if (!document.is_object()) {
        throw SettingsError(source + ": expected a JSON object of shadow settings");
    }
    ShadowSettings settings;
    for (const auto& [name, value] : document.items()) {
        const auto field = fields().find(name);
        if (field == fields().end()) {
            throw SettingsError(source + ": unknown field '" + name + "'");
        }
        try {
            field->second.read(settings, value);
        } catch (const std::invalid_argument& error) {
            throw SettingsError(source + ": field '" + name + "': " + error.what());
        }
    }
    const std::vector<std::string> problems = settings.validate();
    if (!problems.empty()) {
        std::string message = source + ":";
        for (const std::string& problem : problems) {
            message += " " + problem + ";";
        }
        message.pop_back();
        throw SettingsError(message);
    }
    return settings;
}

ShadowSettings loadSettings(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw SettingsError(path.string() + ": cannot open settings file");
    }
    std::ostringstream text;
    text << file.rdbuf();
    return settingsFromJson(text.str(), path.string());
}

void saveSettings(const ShadowSettings& settings, const std::filesystem::path& path) {
    const std::string text = settingsToJson(settings);
    engine::writeAtomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        return static_cast<bool>(out.flush());
    });
}

} // namespace shadows
