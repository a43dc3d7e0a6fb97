// Fuzz target: glTF text and GLB documents through GltfLoader::loadFromMemory, the code path every scene file
// takes. ContentError is the expected answer to bad input; anything else (another exception, a crash, a
// sanitizer report, a scene that breaks the invariants the renderer relies on) is a bug.
#include <content/ContentError.h>
#include <content/GltfLoader.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

namespace {

/// Every mesh the loader returns must be drawable without further checks.
void checkMesh(const engine::MeshData& mesh) {
    const bool normalsMatch = mesh.normals.empty() || mesh.normals.size() == mesh.positions.size();
    bool indicesInRange = mesh.indices.size() % 3 == 0;
    for (const std::uint32_t index : mesh.indices) {
        indicesInRange = indicesInRange && index < mesh.positions.size();
    }
    if (!normalsMatch || !indicesInRange) {
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // No base folder: the input may not make the loader read any file. Level 1 keeps every accepted
    // subdivision node cheap; the level tags themselves are still parsed and checked.
    content::SceneLoadOptions options;
    options.subdivisionLevel = 1;
    try {
        const content::LoadedScene loaded =
            content::GltfLoader::loadFromMemory(std::span(data, size), {}, "fuzz.gltf", options);
        loaded.scene.forEach([](engine::EntityId, const engine::Entity& entity) {
            if (entity.mesh && entity.mesh->mesh) {
                checkMesh(*entity.mesh->mesh);
            }
        });
    } catch (const content::ContentError&) {
    }
    return 0;
}
