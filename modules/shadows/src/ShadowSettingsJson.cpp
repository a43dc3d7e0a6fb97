#include <shadows/ShadowSettingsJson.h>
#include <shadows/ShadowSettingsSchema.h>

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

Field enumField(const EnumSetting& choice) {
    return {[=](const ShadowSettings& s) {
                return Json(std::string(choice.names[static_cast<std::size_t>(choice.get(s))]));
            },
            [=](ShadowSettings& s, const Json& value) {
                if (value.is_string()) {
                    for (std::size_t index = 0; index < choice.names.size(); ++index) {
                        if (value.get<std::string>() == choice.names[index]) {
                            choice.set(s, static_cast<int>(index));
                            return;
                        }
                    }
                }
                throw std::invalid_argument(describe(value) + " is not one of " + choice.nameList());
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

Field fieldOf(const SettingRow& row) {
    if (const auto* real = std::get_if<FloatSetting>(&row.field)) {
        return floatField(real->member);
    }
    if (const auto* integer = std::get_if<IntSetting>(&row.field)) {
        return intField(integer->member);
    }
    if (const auto* toggle = std::get_if<BoolSetting>(&row.field)) {
        return boolField(toggle->member);
    }
    return enumField(std::get<EnumSetting>(row.field));
}

/// Fields a release renamed: a file that still names one is refused, saying what it is called now.
const std::map<std::string, std::string_view>& renamedFields() {
    static const std::map<std::string, std::string_view> table{{"msmQuantize16", "moments16"}};
    return table;
}

const std::map<std::string, Field>& fields() {
    static const std::map<std::string, Field> table = [] {
        std::map<std::string, Field> byName;
        for (const SettingRow& row : settingsSchema()) {
            byName.emplace(row.name, fieldOf(row));
        }
        return byName;
    }();
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
            const auto renamed = renamedFields().find(name);
            throw SettingsError(source + ": unknown field '" + name + "'" +
                                (renamed != renamedFields().end()
                                     ? " (now '" + std::string(renamed->second) + "')"
                                     : std::string()));
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
