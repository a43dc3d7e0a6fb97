#include "SandboxSettings.h"

#include "ParameterTable.h"
#include "SandboxError.h"

#include <shadows/ShadowSettingsJson.h>

#include <engine/Image.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace sandbox {

namespace {

using Json = nlohmann::json;

/// Reads the fields of one JSON object, naming `source` and the field's path in every error.
class FieldReader {
public:
    FieldReader(const Json& object, std::string source, std::string prefix)
        : object_(object), source_(std::move(source)), prefix_(std::move(prefix)) {}

    [[nodiscard]] bool has(const std::string& name) const { return object_.contains(name); }

    [[noreturn]] void fail(const std::string& name, const std::string& detail) const {
        throw SandboxError(source_ + ": field '" + prefix_ + name + "': " + detail);
    }

    void rejectUnknown(const std::set<std::string>& known) const {
        for (const auto& [name, value] : object_.items()) {
            if (!known.contains(name)) {
                fail(name, "unknown field (known: " + list(known) + ")");
            }
        }
    }

    [[nodiscard]] const Json& required(const std::string& name) const {
        if (!has(name)) {
            fail(name, "missing");
        }
        return object_.at(name);
    }

    [[nodiscard]] float number(const std::string& name, const Range<float>& range) const {
        const Json& value = required(name);
        if (!value.is_number()) {
            fail(name, value.dump() + " is not a number");
        }
        const double number = value.get<double>();
        if (!std::isfinite(number) || number < range.min || number > range.max) {
            fail(name, value.dump() + " is outside [" + format(range.min) + ", " + format(range.max) + "]");
        }
        return static_cast<float>(number);
    }

    [[nodiscard]] float finite(const std::string& name) const { return number(name, {-3.0e38f, 3.0e38f}); }

    [[nodiscard]] int integer(const std::string& name, const Range<int>& range) const {
        const Json& value = required(name);
        if (!value.is_number_integer() || value.get<std::int64_t>() < range.min ||
            value.get<std::int64_t>() > range.max) {
            fail(name, value.dump() + " is not an integer in [" + std::to_string(range.min) + ", " +
                           std::to_string(range.max) + "]");
        }
        return value.get<int>();
    }

    [[nodiscard]] bool boolean(const std::string& name) const {
        const Json& value = required(name);
        if (!value.is_boolean()) {
            fail(name, value.dump() + " is not true or false");
        }
        return value.get<bool>();
    }

    [[nodiscard]] std::string text(const std::string& name) const {
        const Json& value = required(name);
        if (!value.is_string() || value.get<std::string>().empty()) {
            fail(name, value.dump() + " is not a non-empty string");
        }
        return value.get<std::string>();
    }

    [[nodiscard]] const Json& object(const std::string& name) const {
        const Json& value = required(name);
        if (!value.is_object()) {
            fail(name, value.dump() + " is not an object");
        }
        return value;
    }

    [[nodiscard]] const std::string& source() const { return source_; }

private:
    static std::string list(const std::set<std::string>& names) {
        std::string out;
        for (const std::string& name : names) {
            out += (out.empty() ? "" : ", ") + name;
        }
        return out;
    }
    static std::string format(float value) {
        std::ostringstream out;
        out << value;
        return out.str();
    }

    const Json& object_;
    std::string source_;
    std::string prefix_;
};

OrbitCamera readCamera(const FieldReader& reader) {
    reader.rejectUnknown({"target", "yaw", "pitch", "distance"});
    OrbitCamera camera;
    const Json& target = reader.required("target");
    if (!target.is_array() || target.size() != 3) {
        reader.fail("target", target.dump() + " is not an array of 3 numbers");
    }
    const Json named{{"x", target[0]}, {"y", target[1]}, {"z", target[2]}};
    const FieldReader coordinates(named, reader.source(), "camera.target.");
    camera.target = {coordinates.finite("x"), coordinates.finite("y"), coordinates.finite("z")};
    camera.yaw = reader.finite("yaw");
    camera.pitch = reader.number("pitch", ParameterTable::kPitch);
    camera.distance = reader.number("distance", ParameterTable::kDistance);
    return camera;
}

shadows::ShadowSettings readSide(const FieldReader& reader, const std::string& name) {
    try {
        return shadows::settingsFromJson(reader.object(name).dump(),
                                         reader.source() + ": field '" + name + "'");
    } catch (const shadows::SettingsError& error) {
        throw SandboxError(error.what());
    }
}

} // namespace

shadows::ShadowSettings SandboxSettings::withTechnique(shadows::ShadowTechnique technique) {
    shadows::ShadowSettings settings;
    settings.technique = technique;
    return settings;
}

std::string SandboxSettings::toJson() const {
    Json document = Json::object();
    document["scene"] = scene;
    document["level"] = level;
    if (light) {
        document["azimuth"] = light->azimuth;
        document["elevation"] = light->elevation;
    }
    if (camera) {
        document["camera"] = {{"target", {camera->target.x, camera->target.y, camera->target.z}},
                              {"yaw", camera->yaw},
                              {"pitch", camera->pitch},
                              {"distance", camera->distance}};
    }
    document["compare"] = compare;
    document["split"] = split;
    document["a"] = Json::parse(shadows::settingsToJson(a));
    document["b"] = Json::parse(shadows::settingsToJson(b));
    return document.dump(2) + "\n";
}

SandboxSettings SandboxSettings::fromJson(std::string_view text, const std::string& source) {
    Json document;
    try {
        document = Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error& error) {
        throw SandboxError(source + ": not valid JSON: " + error.what());
    }
    if (!document.is_object()) {
        throw SandboxError(source + ": expected a JSON object of sandbox settings");
    }
    const FieldReader reader(document, source, "");
    reader.rejectUnknown({"scene", "level", "azimuth", "elevation", "camera", "compare", "split", "a", "b"});
    SandboxSettings settings;
    if (reader.has("scene")) {
        settings.scene = reader.text("scene");
    }
    if (reader.has("level")) {
        settings.level = reader.integer("level", ParameterTable::kLevel);
    }
    if (reader.has("azimuth") || reader.has("elevation")) {
        // One angle without the other would leave the light half-specified.
        settings.light = LightAngles{reader.number("azimuth", ParameterTable::kAzimuth),
                                     reader.number("elevation", ParameterTable::kElevation)};
    }
    if (reader.has("camera")) {
        settings.camera = readCamera(FieldReader(reader.object("camera"), source, "camera."));
    }
    if (reader.has("compare")) {
        settings.compare = reader.boolean("compare");
    }
    if (reader.has("split")) {
        settings.split = reader.number("split", ParameterTable::kSplit);
    }
    if (reader.has("a")) {
        settings.a = readSide(reader, "a");
    }
    if (reader.has("b")) {
        settings.b = readSide(reader, "b");
    }
    return settings;
}

SandboxSettings SandboxSettings::load(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw SandboxError(path.string() + ": cannot open sandbox settings file");
    }
    std::ostringstream text;
    text << file.rdbuf();
    return fromJson(text.str(), path.string());
}

void SandboxSettings::save(const std::filesystem::path& path) const {
    engine::writeTextFile(path, toJson());
}

} // namespace sandbox
