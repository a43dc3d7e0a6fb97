#pragma once

#include <engine/Bounds.h>
#include <engine/MeshData.h>
#include <engine/SurfaceClosure.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace engine {

/// @brief Largest chunk a mesh is drawn in. Bounded draws keep software rasterisers' per-draw vertex buffers
/// small (llvmpipe's would otherwise be allocated and unmapped every frame) and let chunks be culled one by
/// one.
struct ChunkLimits {
    /// Triangles per chunk, >= 1. Default 4096.
    std::uint32_t maxTriangles = 4096;
};

/// @brief A run of triangles drawn with one call; its vertices are contiguous in the chunked vertex order.
struct MeshChunk {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    /// Bounds of the chunk's vertices in the mesh's local space.
    Aabb bounds;
    /// The closure its triangles' parts share (a chunk holds one kind), and the bounds of those parts whole
    /// (empty for Open): where a pass may leave out the faces hidden behind the others (hiddenFace).
    SurfaceClosure closure = SurfaceClosure::Open;
    Aabb closedBounds;
    /// The plane (local space, unit normal: n·p + w = 0) every vertex of the chunk lies on, for a flat one: a
    /// shadow pass may leave out a flat chunk that nothing lies behind (chunksCastingNoShadow).
    std::optional<glm::vec4> plane;
};

/// @brief A mesh reordered into spatially compact chunks.
struct ChunkedMesh {
    /// Vertex i of the chunked order is vertex `sourceVertex[i]` of the mesh (vertices shared by two chunks
    /// appear once in each).
    std::vector<std::uint32_t> sourceVertex;
    /// Three per triangle, into the chunked vertex order.
    std::vector<std::uint32_t> indices;
    std::vector<MeshChunk> chunks;
    /// Bounds of every position of the mesh, local space.
    Aabb bounds;
};

/// @brief Splits `mesh` into chunks of at most `limits.maxTriangles` triangles: first by the kind of their
/// parts (surfaceParts: open, flat open ones plane by plane, outward, inward), then by recursive median
/// splits of the triangle centroids along the longest axis, so that each chunk's bounds are tight for
/// culling. Triangles keep their original order inside a chunk; a mesh whose parts are of one kind and fit
/// one chunk keeps its triangle order entirely. Indices out of range are the caller's to reject (the loaders
/// do).
[[nodiscard]] ChunkedMesh splitIntoChunks(const MeshData& mesh, const ChunkLimits& limits = {});

} // namespace engine
