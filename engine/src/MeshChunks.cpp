#include <engine/MeshChunks.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace engine {

namespace {

/// Centroid with non-finite coordinates replaced by 0, so the ordering stays a strict weak order.
glm::vec3 finiteCentroid(const MeshData& mesh, std::uint32_t triangle) {
    glm::vec3 sum(0.0f);
    for (std::uint32_t corner = 0; corner < 3; ++corner) {
        sum += mesh.positions[mesh.indices[3 * triangle + corner]];
    }
    for (int axis = 0; axis < 3; ++axis) {
        sum[axis] = std::isfinite(sum[axis]) ? sum[axis] : 0.0f;
    }
    return sum / 3.0f;
}

/// Orders `triangles` so that every run of at most `maxTriangles` is a leaf of a median split.
void partition(std::span<std::uint32_t> triangles, const std::vector<glm::vec3>& centroids,
               std::uint32_t maxTriangles, std::vector<std::span<std::uint32_t>>& leaves) {
    if (triangles.size() <= maxTriangles) {
        std::sort(triangles.begin(), triangles.end()); // original order inside the chunk
        leaves.push_back(triangles);
        return;
    }
    Aabb box;
    for (const std::uint32_t t : triangles) {
        box.extend(centroids[t]);
    }
    const glm::vec3 extent = box.max - box.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    // Split at a multiple of maxTriangles near the middle, so leaves come out full.
    const std::size_t leavesNeeded = (triangles.size() + maxTriangles - 1) / maxTriangles;
    const std::size_t middle = (leavesNeeded / 2) * maxTriangles;
    std::nth_element(triangles.begin(), triangles.begin() + static_cast<std::ptrdiff_t>(middle),
                     triangles.end(), [&](std::uint32_t a, std::uint32_t b) {
                         return centroids[a][axis] < centroids[b][axis] ||
                                (centroids[a][axis] == centroids[b][axis] && a < b);
                     });
    partition(triangles.first(middle), centroids, maxTriangles, leaves);
    partition(triangles.subspan(middle), centroids, maxTriangles, leaves);
}

} // namespace

ChunkedMesh splitIntoChunks(const MeshData& mesh, const ChunkLimits& limits) {
    ChunkedMesh result;
    for (const glm::vec3& p : mesh.positions) {
        result.bounds.extend(p);
    }
    const auto triangleCount = static_cast<std::uint32_t>(mesh.triangleCount());
    if (triangleCount == 0) {
        return result;
    }
    const SurfaceParts parts = surfaceParts(mesh);
    const auto closureOf = [&](std::uint32_t triangle) {
        return parts.parts[parts.triangleParts[triangle]].closure;
    };
    // Triangles grouped by closure, each group in its original order.
    std::vector<std::uint32_t> order;
    order.reserve(triangleCount);
    for (const SurfaceClosure closure :
         {SurfaceClosure::Open, SurfaceClosure::Outward, SurfaceClosure::Inward}) {
        for (std::uint32_t t = 0; t < triangleCount; ++t) {
            if (closureOf(t) == closure) {
                order.push_back(t);
            }
        }
    }
    std::vector<std::span<std::uint32_t>> leaves;
    const std::uint32_t maxTriangles = std::max<std::uint32_t>(limits.maxTriangles, 1);
    std::vector<glm::vec3> centroids;
    for (auto group = order.begin(); group != order.end();) {
        const SurfaceClosure closure = closureOf(*group);
        const auto end =
            std::find_if(group, order.end(), [&](std::uint32_t t) { return closureOf(t) != closure; });
        const std::span<std::uint32_t> triangles(group, end);
        if (triangles.size() <= maxTriangles) {
            leaves.push_back(triangles);
        } else {
            if (centroids.empty()) {
                centroids.resize(triangleCount);
                for (std::uint32_t t = 0; t < triangleCount; ++t) {
                    centroids[t] = finiteCentroid(mesh, t);
                }
            }
            partition(triangles, centroids, maxTriangles, leaves);
        }
        group = end;
    }

    // Each chunk numbers the vertices it uses in first-use order; `seenIn` says which chunk numbered a
    // vertex.
    constexpr std::uint32_t kUnseen = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> seenIn(mesh.positions.size(), kUnseen);
    std::vector<std::uint32_t> chunkedIndex(mesh.positions.size(), 0);
    result.indices.reserve(3 * static_cast<std::size_t>(triangleCount));
    for (const std::span<std::uint32_t> leaf : leaves) {
        MeshChunk chunk;
        chunk.firstIndex = static_cast<std::uint32_t>(result.indices.size());
        chunk.firstVertex = static_cast<std::uint32_t>(result.sourceVertex.size());
        const auto chunkNumber = static_cast<std::uint32_t>(result.chunks.size());
        chunk.closure = closureOf(leaf.front());
        for (const std::uint32_t triangle : leaf) {
            if (chunk.closure != SurfaceClosure::Open) {
                chunk.closedBounds.extend(parts.parts[parts.triangleParts[triangle]].bounds);
            }
            for (std::uint32_t corner = 0; corner < 3; ++corner) {
                const std::uint32_t vertex = mesh.indices[3 * triangle + corner];
                if (seenIn[vertex] != chunkNumber) {
                    seenIn[vertex] = chunkNumber;
                    chunkedIndex[vertex] = static_cast<std::uint32_t>(result.sourceVertex.size());
                    result.sourceVertex.push_back(vertex);
                    chunk.bounds.extend(mesh.positions[vertex]);
                }
                result.indices.push_back(chunkedIndex[vertex]);
            }
        }
        chunk.indexCount = static_cast<std::uint32_t>(result.indices.size()) - chunk.firstIndex;
        chunk.vertexCount = static_cast<std::uint32_t>(result.sourceVertex.size()) - chunk.firstVertex;
        result.chunks.push_back(chunk);
    }
    return result;
}

} // namespace engine
