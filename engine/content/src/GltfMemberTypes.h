#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace content {

/// @brief Refuses a glTF document whose members have the wrong JSON type, in every part the loader reads
/// (glTF 2.0 schema: asset, scenes, nodes, meshes and primitives, accessors, buffer views, buffers,
/// materials' base colour, cameras, KHR_lights_punctual, our extras.subdivision). tinygltf drops such members
/// silently, so a broken file would otherwise render as a partial or empty scene. Throws
/// ContentError("<source>: <path>: expected <type>"), e.g. "scene.gltf: meshes[0].primitives: expected an
/// array".
void checkGltfMemberTypes(const nlohmann::json& document, const std::string& source);

} // namespace content
