#pragma once

#include <shadows/ShadowSettings.h>

#include <engine/Error.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace shadows {

/// @brief A settings document that cannot be used; the message names the source and the field.
class SettingsError : public engine::Error {
public:
    using engine::Error::Error;
};

/// @brief ShadowSettings as a JSON object: every field by its C++ name, enums by their names (e.g.
/// `{"technique": "pcf-gsm-average", "depthFormat": "d24", "pcfLayout": "grid", ...}`).
std::string settingsToJson(const ShadowSettings& settings);

/// @brief Parses a JSON object into settings. Missing fields keep their defaults; unknown fields, wrong
/// types, unknown enum names and values ShadowSettings::validate rejects throw SettingsError naming `source`
/// and the field (e.g. `sandbox.json: field 'pcfTaps': 12 is outside [2, 8] for a grid`).
ShadowSettings settingsFromJson(std::string_view text, const std::string& source);

/// @brief Reads a settings file (SettingsError names the path when it is missing or malformed).
ShadowSettings loadSettings(const std::filesystem::path& path);
/// @brief Writes settings as JSON atomically (temporary file + rename).
void saveSettings(const ShadowSettings& settings, const std::filesystem::path& path);

} // namespace shadows
