#pragma once

#include <engine/LightAim.h>

#include "OrbitCamera.h"

#include <shadows/ShadowSettings.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace sandbox {

/// @brief Everything that decides the sandbox's image: scene, subdivision level, light, camera, the two
/// sides' shadow settings and the divider. The windowed app and --headless render the same image from equal
/// settings.
///
/// As JSON (docs/SANDBOX.md): `{"scene": "knob", "level": -1, "azimuth": 40, "elevation": 35, "camera":
/// {"target": [x, y, z], "yaw": 30, "pitch": 20, "distance": 6}, "compare": true, "split": 0.5, "a": {...},
/// "b": {...}}` where "a" and "b" are shadow settings objects (shadows::settingsToJson). Missing fields keep
/// their defaults; azimuth/elevation and camera are left out while the scene's own light and camera are used.
struct SandboxSettings {
    /// @brief Direction the scene's first light comes from, in degrees (ParameterTable::kAzimuth,
    /// kElevation).
    /// Where the light comes from (degrees; azimuth around +Y from +Z towards +X, elevation above the
    /// horizon).
    using LightAngles = engine::LightAngles;

    /// Content scene name (content/scenes/NAME.gltf) or a .gltf/.glb path. Default "knob".
    std::string scene = "knob";
    /// Subdivision level for every subdivided mesh, -1 = each node's own (ParameterTable::kLevel). Default
    /// -1.
    int level = -1;
    /// Light direction applied to the scene's first light; nullopt keeps the light as the file has it.
    std::optional<LightAngles> light;
    /// Orbit camera; nullopt uses the scene's first camera as the file has it.
    std::optional<OrbitCamera> camera;
    /// Split screen: side A left of the divider, side B right of it; otherwise the whole view is A. Default
    /// on.
    bool compare = true;
    /// Divider position as a fraction of the view width (ParameterTable::kSplit). Default 0.5.
    float split = 0.5f;
    /// Shadow settings of side A. Default pcf-gsm-point.
    shadows::ShadowSettings a = withTechnique(shadows::ShadowTechnique::PcfGsmPointGradient);
    /// Shadow settings of side B. Default pcf-gsm-average.
    shadows::ShadowSettings b = withTechnique(shadows::ShadowTechnique::PcfGsmAverageGradient);

    /// @brief Default shadow settings with `technique`.
    static shadows::ShadowSettings withTechnique(shadows::ShadowTechnique technique);

    /// @brief The settings as a JSON document (pretty-printed, ends with a newline).
    [[nodiscard]] std::string toJson() const;
    /// @brief Parses a JSON document. Unknown fields, wrong types and out-of-range values throw SandboxError
    /// naming `source` and the field (e.g. `view.json: field 'elevation': 95 is outside [0.5, 90]`).
    static SandboxSettings fromJson(std::string_view text, const std::string& source);
    /// @brief Reads a settings file; SandboxError names the path when it is missing or malformed.
    static SandboxSettings load(const std::filesystem::path& path);
    /// @brief Writes the settings atomically (temporary file + rename). Throws engine::IoError.
    void save(const std::filesystem::path& path) const;

    bool operator==(const SandboxSettings&) const = default;
};

} // namespace sandbox
