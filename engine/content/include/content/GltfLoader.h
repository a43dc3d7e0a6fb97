#pragma once

#include <engine/Scene.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace content {

/// @brief Options for loading scenes.
struct SceneLoadOptions {
    /// Subdivision level for every node flagged for subdivision, overriding the file's own; -1 keeps each
    /// node's level. Range -1..6. Default -1.
    int subdivisionLevel = -1;
    /// Most bytes of mesh data (positions, normals, indices, subdivided surfaces) the scene may make; the
    /// loader checks each part against it before allocating, so a small file cannot demand a huge allocation
    /// through absurd counts or by instancing large meshes many times. Default 512 MiB (every content scene
    /// fits at subdivision level 6).
    std::uint64_t meshByteLimit = std::uint64_t{512} << 20;
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
/// Every accessor is bounds-checked before anything is allocated, node hierarchies must be trees (at most 256
/// deep), JSON may nest at most 128 levels and the scene's mesh data is bounded by
/// SceneLoadOptions::meshByteLimit; a malformed file throws ContentError naming the file and the field
/// (docs/ROBUSTNESS.md).
class GltfLoader {
public:
    /// @brief Reads `path` and loads it with loadFromMemory, resolving external files against its folder.
    /// @throws ContentError naming `path` if the file is missing, unreadable or malformed.
    [[nodiscard]] static LoadedScene load(const std::filesystem::path& path,
                                          const SceneLoadOptions& options = {});

    /// @brief Loads a glTF document held in memory: GLB when `bytes` start with the magic "glTF", JSON text
    /// otherwise.
    /// @param baseFolder Folder that relative URIs of buffers and images, and subdivision cage paths, resolve
    /// against. Buffers and images must lie inside it: a buffer URI that leaves it (through "..", an absolute
    /// path or a symbolic link) is an error, such an image is left out with a warning. Cage paths may leave
    /// it (the content's scenes use "../cages/"). Empty means no external file at all: only data URIs and the
    /// GLB's own binary chunk are read, which is what untrusted input (and the fuzzer) should use.
    /// @param sourceName Names the document in every error and warning, e.g. the file path.
    /// @throws ContentError naming `sourceName` and the offending field.
    [[nodiscard]] static LoadedScene loadFromMemory(std::span<const std::uint8_t> bytes,
                                                    const std::filesystem::path& baseFolder,
                                                    const std::string& sourceName,
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
