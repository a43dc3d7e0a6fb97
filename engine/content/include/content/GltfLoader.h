#pragma once

#include <engine/Scene.h>

#include <filesystem>
#include <string>
#include <vector>

namespace content {

/// @brief Options for loading scenes.
struct SceneLoadOptions {
    /// Subdivision level for every node flagged for subdivision, overriding the file's own; -1 keeps each
    /// node's level. Range -1..6. Default -1.
    int subdivisionLevel = -1;
};

/// @brief How a node's mesh is made from a subdivision cage (the node's glTF `extras.subdivision`).
struct SubdivisionTag {
    /// "catmull-clark" or "loop". Default "catmull-clark".
    std::string scheme = "catmull-clark";
    /// Uniform refinement level, 0..6. Default 3.
    int level = 3;
    /// Cage file (OBJ/OFF) as written in the glTF, relative to the glTF file; empty = the node's own mesh.
    std::string cage;
};

/// @brief A loaded scene plus what the loader had to leave out (e.g. point lights), one line each.
struct LoadedScene {
    engine::Scene scene;
    /// Entities whose mesh is a subdivision surface, with the tag that made it.
    std::vector<std::pair<engine::EntityId, SubdivisionTag>> subdivided;
    std::vector<std::string> warnings;
};

/// @brief Loads glTF 2.0 scenes (.gltf with embedded/base64/external buffers, or .glb) with tinygltf.
///
/// Supported: the default scene's node hierarchy (TRS or matrix), triangle/strip/fan primitives with any
/// index type or none, interleaved accessors, base-colour factor (metallic/roughness mapped to Blinn-Phong),
/// perspective and orthographic cameras, directional and spot lights of KHR_lights_punctual.
///
/// Nodes whose `extras` hold `{"subdivision": {"scheme": "catmull-clark"|"loop", "level": 0..6,
/// "cage": "path.obj"}}` are replaced by the limit surface of the cage: the OBJ/OFF file `cage` (relative to
/// the glTF file) or, without it, the node's own mesh with coincident vertices welded.
///
/// Every accessor is bounds-checked; a malformed file throws ContentError naming the file and the field.
class GltfLoader {
public:
    [[nodiscard]] static LoadedScene load(const std::filesystem::path& path,
                                          const SceneLoadOptions& options = {});
};

/// @brief Writes the meshes, hierarchy, cameras and lights of a Scene as glTF 2.0 (.gltf with an embedded
/// base64 buffer, or .glb by extension), atomically. Entities listed in `subdivided` get their tag as
/// `extras.subdivision` (their mesh is written as the preview other viewers show). Throws ContentError
/// naming the path on failure.
class GltfWriter {
public:
    static void save(const engine::Scene& scene, const std::filesystem::path& path,
                     const std::vector<std::pair<engine::EntityId, SubdivisionTag>>& subdivided = {});
};

} // namespace content
