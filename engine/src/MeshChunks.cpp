#include <engine/MeshChunks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
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

/// How far from a plane a point of a flat surface may lie: float rounding of coordinates around `box`, with
/// room for a model's transform (a relative 1e-5 of its size, far below a shadow map's depth step over it).
double flatnessTolerance(const Aabb& box) {
    const glm::dvec3 low(box.min);
    const glm::dvec3 high(box.max);
    const double reach = glm::max(glm::length(low), glm::length(high));
    return 1e-5 * glm::length(high - low) + 1e-6 * reach;
}

/// The plane of the triangle among `triangles` with the largest area, if all their corners lie on it within
/// flatnessTolerance(`box`); none for triangles of no area.
template <typename Triangles>
std::optional<glm::vec4> commonPlane(const MeshData& mesh, const Triangles& triangles, const Aabb& box) {
    const auto corner = [&](std::uint32_t triangle, std::uint32_t k) {
        return glm::dvec3(mesh.positions[mesh.indices[3 * triangle + k]]);
    };
    glm::dvec3 normal(0.0);
    glm::dvec3 origin(0.0);
    double largest = 0.0;
    for (const std::uint32_t t : triangles) {
        const glm::dvec3 cross = glm::cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0));
        const double area = glm::length(cross);
        if (area > largest) {
            largest = area;
            normal = cross / area;
            origin = corner(t, 0);
        }
    }
    if (!(largest > 0.0)) {
        return std::nullopt;
    }
    const double tolerance = flatnessTolerance(box);
    for (const std::uint32_t t : triangles) {
        for (std::uint32_t k = 0; k < 3; ++k) {
            if (!(std::abs(glm::dot(normal, corner(t, k) - origin)) <= tolerance)) {
                return std::nullopt;
            }
        }
    }
    return glm::vec4(glm::vec3(normal), static_cast<float>(-glm::dot(normal, origin)));
}

/// The group each part is chunked in, a chunk holding triangles of one: open parts (0), then flat open parts
/// by their plane (1 to planes), then outward parts (planes + 1) and inward ones (planes + 2).
struct PartGroups {
    std::vector<std::uint32_t> groupOfPart;
    std::uint32_t planes = 0;
};

PartGroups partGroups(const MeshData& mesh, const SurfaceParts& parts) {
    std::vector<std::vector<std::uint32_t>> triangles(parts.parts.size());
    for (std::uint32_t t = 0; t < parts.triangleParts.size(); ++t) {
        triangles[parts.triangleParts[t]].push_back(t);
    }
    Aabb meshBounds;
    for (const SurfaceParts::Part& part : parts.parts) {
        meshBounds.extend(part.bounds);
    }
    // Planes are keyed by their coordinates rounded to steps well above the flatness tolerance; a plane on
    // a step's edge may land in two groups, which costs a chunk, not a plane.
    const double offsetStep =
        1e-4 * static_cast<double>(glm::length(meshBounds.max - meshBounds.min)) + 1e-30;
    std::map<std::array<std::int64_t, 4>, std::uint32_t> planeGroups;
    PartGroups groups;
    groups.groupOfPart.assign(parts.parts.size(), 0);
    std::vector<SurfaceClosure> closures(parts.parts.size());
    for (std::size_t p = 0; p < parts.parts.size(); ++p) {
        closures[p] = parts.parts[p].closure;
        if (closures[p] != SurfaceClosure::Open) {
            continue;
        }
        const std::optional<glm::vec4> plane = commonPlane(mesh, triangles[p], parts.parts[p].bounds);
        if (!plane) {
            continue;
        }
        // One orientation per plane: its first non-zero normal coordinate positive.
        const glm::vec3 normal(*plane);
        const float sign = normal.x != 0.0f ? normal.x : normal.y != 0.0f ? normal.y : normal.z;
        const glm::vec4 oriented = sign < 0.0f ? -*plane : *plane;
        const std::array<std::int64_t, 4> key{std::llround(oriented.x * 1e3), std::llround(oriented.y * 1e3),
                                              std::llround(oriented.z * 1e3),
                                              std::llround(static_cast<double>(oriented.w) / offsetStep)};
        const auto [found, added] = planeGroups.try_emplace(key, groups.planes + 1);
        groups.planes += added ? 1 : 0;
        groups.groupOfPart[p] = found->second;
    }
    for (std::size_t p = 0; p < parts.parts.size(); ++p) {
        if (closures[p] != SurfaceClosure::Open) {
            groups.groupOfPart[p] = groups.planes + (closures[p] == SurfaceClosure::Outward ? 1 : 2);
        }
    }
    return groups;
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
    const PartGroups groups = partGroups(mesh, parts);
    const auto closureOf = [&](std::uint32_t triangle) {
        return parts.parts[parts.triangleParts[triangle]].closure;
    };
    const auto groupOf = [&](std::uint32_t triangle) {
        return groups.groupOfPart[parts.triangleParts[triangle]];
    };
    const auto flatGroup = [&](std::uint32_t group) { return group >= 1 && group <= groups.planes; };
    // Triangles grouped, each group in its original order.
    std::vector<std::uint32_t> order(triangleCount);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return groupOf(a) < groupOf(b); });
    std::vector<std::span<std::uint32_t>> leaves;
    const std::uint32_t maxTriangles = std::max<std::uint32_t>(limits.maxTriangles, 1);
    std::vector<glm::vec3> centroids;
    for (auto group = order.begin(); group != order.end();) {
        const std::uint32_t kind = groupOf(*group);
        const auto end =
            std::find_if(group, order.end(), [&](std::uint32_t t) { return groupOf(t) != kind; });
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
        if (flatGroup(groupOf(leaf.front()))) {
            chunk.plane =
                commonPlane(mesh, leaf, chunk.bounds); // none where rounding put two planes together
        }
        chunk.indexCount = static_cast<std::uint32_t>(result.indices.size()) - chunk.firstIndex;
        chunk.vertexCount = static_cast<std::uint32_t>(result.sourceVertex.size()) - chunk.firstVertex;
        result.chunks.push_back(chunk);
    }
    return result;
}

} // namespace engine
