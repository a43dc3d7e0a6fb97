#pragma once

// Independent geometric checks shared by the tests: they recompute properties from raw triangles and cage
// faces rather than trusting library output.

#include "content/Cage.h"

#include <engine/MeshData.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace content::test {

/// Undirected edge use of a polygon soup.
struct EdgeReport {
    std::size_t edges = 0;
    /// Every edge used by exactly two polygons.
    bool closed = true;
    /// Every two-polygon edge traversed once in each direction.
    bool consistentlyOriented = true;
};

inline EdgeReport analyseEdges(const std::vector<std::vector<std::uint32_t>>& polygons) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& polygon : polygons) {
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            ++directed[{polygon[i], polygon[(i + 1) % polygon.size()]}];
        }
    }
    EdgeReport report;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        const int reverseCount = reverse == directed.end() ? 0 : reverse->second;
        if (edge.first < edge.second || reverseCount == 0) {
            ++report.edges;
        }
        if (count + reverseCount != 2) {
            report.closed = false;
        }
        if (count != 1 || reverseCount > 1) {
            report.consistentlyOriented = false;
        }
    }
    return report;
}

inline std::vector<std::vector<std::uint32_t>> triangles(const engine::MeshData& mesh) {
    std::vector<std::vector<std::uint32_t>> result;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        result.push_back({mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
    }
    return result;
}

inline long eulerCharacteristic(std::size_t vertices, std::size_t edges, std::size_t faces) {
    return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(faces);
}

/// Volume enclosed by a closed polygon soup (divergence theorem, fan triangulation); positive when the
/// polygons are counter-clockwise seen from outside.
inline double signedVolume(const std::vector<glm::vec3>& positions,
                           const std::vector<std::vector<std::uint32_t>>& polygons) {
    double volume = 0.0;
    for (const auto& polygon : polygons) {
        const glm::dvec3 a(positions[polygon[0]]);
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
            volume += glm::dot(
                a, glm::cross(glm::dvec3(positions[polygon[i]]), glm::dvec3(positions[polygon[i + 1]])));
        }
    }
    return volume / 6.0;
}

/// Per-vertex sum of the adjacent triangles' area-weighted normals: a finite-difference estimate of the
/// surface normal from neighbouring points.
inline std::vector<glm::vec3> neighbourNormals(const engine::MeshData& mesh) {
    std::vector<glm::vec3> sums(mesh.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]];
        const glm::vec3 n =
            glm::cross(mesh.positions[mesh.indices[t + 1]] - a, mesh.positions[mesh.indices[t + 2]] - a);
        for (int k = 0; k < 3; ++k) {
            sums[mesh.indices[t + static_cast<std::size_t>(k)]] += n;
        }
    }
    for (glm::vec3& n : sums) {
        n = glm::normalize(n);
    }
    return sums;
}

/// Distance from `point` to the nearest vertex of `mesh`.
inline float nearestVertexDistance(const engine::MeshData& mesh, const glm::vec3& point) {
    float best = std::numeric_limits<float>::max();
    for (const glm::vec3& p : mesh.positions) {
        best = std::min(best, glm::distance(p, point));
    }
    return best;
}

} // namespace content::test
