#include <engine/SurfaceClosure.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>

namespace engine {

namespace {

/// A coordinate's bits, with -0 as +0 so that the two weld.
std::uint32_t weldBits(float value) {
    return std::bit_cast<std::uint32_t>(value == 0.0f ? 0.0f : value);
}

/// Each position's welded point (positions with equal coordinates share one), through an open-addressing
/// table: node-based maps allocate per entry, several times the cost on meshes of a million triangles.
std::vector<std::uint32_t> weldPositions(const std::vector<glm::vec3>& positions,
                                         std::vector<glm::dvec3>& points) {
    constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
    const std::size_t slots = std::bit_ceil(std::max<std::size_t>(2 * positions.size(), 16));
    std::vector<std::uint32_t> table(slots, kEmpty); // a position index holding that slot's coordinates
    std::vector<std::uint32_t> welded(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3& p = positions[i];
        const std::uint32_t x = weldBits(p.x);
        const std::uint32_t y = weldBits(p.y);
        const std::uint32_t z = weldBits(p.z);
        std::uint64_t hash = (std::uint64_t{x} * 0x9e3779b97f4a7c15u) ^
                             (std::uint64_t{y} * 0xc2b2ae3d27d4eb4fu) ^
                             (std::uint64_t{z} * 0x165667b19e3779f9u);
        hash ^= hash >> 29;
        for (std::size_t slot = hash & (slots - 1);; slot = (slot + 1) & (slots - 1)) {
            const std::uint32_t held = table[slot];
            if (held == kEmpty) {
                table[slot] = static_cast<std::uint32_t>(i);
                welded[i] = static_cast<std::uint32_t>(points.size());
                points.emplace_back(p);
                break;
            }
            const glm::vec3& q = positions[held];
            if (weldBits(q.x) == x && weldBits(q.y) == y && weldBits(q.z) == z) {
                welded[i] = welded[held];
                break;
            }
        }
    }
    return welded;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

} // namespace

SurfaceParts surfaceParts(const MeshData& mesh) {
    SurfaceParts result;
    const std::size_t positionCount = mesh.positions.size();
    const std::size_t triangleCount = mesh.indices.size() / 3;
    const auto allOpen = [&] {
        result.triangleParts.assign(triangleCount, 0);
        result.parts.assign(1, {});
        for (const glm::vec3& position : mesh.positions) {
            result.parts[0].bounds.extend(position);
        }
        return result;
    };
    const bool finite = std::all_of(mesh.positions.begin(), mesh.positions.end(), [](const glm::vec3& p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    });
    if (!finite || std::any_of(mesh.indices.begin(), mesh.indices.end(),
                               [&](std::uint32_t index) { return index >= positionCount; })) {
        return allOpen();
    }
    std::vector<glm::dvec3> points;
    const std::vector<std::uint32_t> welded = weldPositions(mesh.positions, points);
    std::vector<std::uint32_t> corners(3 * triangleCount);
    std::vector<bool> degenerate(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t a = corners[3 * t] = welded[mesh.indices[3 * t]];
        const std::uint32_t b = corners[3 * t + 1] = welded[mesh.indices[3 * t + 1]];
        const std::uint32_t c = corners[3 * t + 2] = welded[mesh.indices[3 * t + 2]];
        degenerate[t] = a == b || b == c || a == c;
    }
    const auto corner = [&](std::size_t triangle, std::size_t k) { return corners[3 * triangle + k]; };
    // Parts: points joined by the triangles' edges.
    std::vector<std::uint32_t> parent(points.size());
    std::iota(parent.begin(), parent.end(), 0u);
    // Every undirected edge's uses, filed under its lower point (a counting sort): the higher point and which
    // way the use runs.
    std::vector<std::uint32_t> firstUse(points.size() + 1, 0);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        if (!degenerate[t]) {
            for (std::size_t k = 0; k < 3; ++k) {
                ++firstUse[std::min(corner(t, k), corner(t, (k + 1) % 3)) + 1];
                parent[findRoot(parent, corner(t, k))] = findRoot(parent, corner(t, (k + 1) % 3));
            }
        }
    }
    std::partial_sum(firstUse.begin(), firstUse.end(), firstUse.begin());
    std::vector<std::int64_t> uses(firstUse.back()); // higher point << 1 | (1 when used from lower to higher)
    {
        std::vector<std::uint32_t> filled(firstUse.begin(), firstUse.end() - 1);
        for (std::size_t t = 0; t < triangleCount; ++t) {
            if (!degenerate[t]) {
                for (std::size_t k = 0; k < 3; ++k) {
                    const std::uint32_t from = corner(t, k);
                    const std::uint32_t to = corner(t, (k + 1) % 3);
                    uses[filled[std::min(from, to)]++] =
                        std::int64_t{std::max(from, to)} << 1 | (from < to ? 1 : 0);
                }
            }
        }
    }
    // One part per root, numbered in first-use order; degenerate triangles share one part.
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> partOfRoot(points.size(), kNone);
    std::vector<bool> open;
    std::vector<glm::dvec3> reference; // a corner of each part: volumes about it keep their digits far out
    std::vector<double> volume;
    std::uint32_t degenerateParts = kNone;
    result.triangleParts.resize(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        std::uint32_t& part = degenerate[t] ? degenerateParts : partOfRoot[findRoot(parent, corner(t, 0))];
        if (part == kNone) {
            part = static_cast<std::uint32_t>(result.parts.size());
            result.parts.emplace_back();
            open.push_back(degenerate[t]);
            reference.push_back(points[corner(t, 0)]);
            volume.push_back(0.0);
        }
        result.triangleParts[t] = part;
        if (degenerate[t]) {
            for (std::size_t k = 0; k < 3; ++k) {
                result.parts[part].bounds.extend(glm::vec3(points[corner(t, k)]));
            }
        } else {
            // The divergence theorem, six times over.
            const glm::dvec3& o = reference[part];
            volume[part] += glm::dot(points[corner(t, 0)] - o,
                                     glm::cross(points[corner(t, 1)] - o, points[corner(t, 2)] - o));
        }
    }
    // The other parts' bounds, point by point (a point of a part is a corner of its triangles).
    for (std::uint32_t point = 0; point < points.size(); ++point) {
        const std::uint32_t part = partOfRoot[findRoot(parent, point)];
        if (part != kNone) {
            result.parts[part].bounds.extend(glm::vec3(points[point]));
        }
    }
    // A closed, consistently wound part uses each edge as often in one direction as in the other.
    for (std::uint32_t low = 0; low < points.size(); ++low) {
        const auto begin = uses.begin() + firstUse[low];
        const auto end = uses.begin() + firstUse[low + 1];
        std::sort(begin, end);
        for (auto edge = begin; edge != end;) {
            const std::int64_t high = *edge >> 1;
            std::int64_t balance = 0;
            for (; edge != end && *edge >> 1 == high; ++edge) {
                balance += (*edge & 1) != 0 ? 1 : -1;
            }
            if (balance != 0) {
                open[partOfRoot[findRoot(parent, low)]] = true;
            }
        }
    }
    for (std::size_t p = 0; p < result.parts.size(); ++p) {
        // A part enclosing no volume to rounding (two faces back to back, a flat closed fan) has no inside.
        const glm::vec3 extent = result.parts[p].bounds.max - result.parts[p].bounds.min;
        const double negligible = 1e-9 * std::pow(static_cast<double>(glm::length(extent)), 3.0);
        result.parts[p].closure = open[p]                   ? SurfaceClosure::Open
                                  : volume[p] > negligible  ? SurfaceClosure::Outward
                                  : volume[p] < -negligible ? SurfaceClosure::Inward
                                                            : SurfaceClosure::Open;
    }
    return result;
}

GLenum hiddenFace(SurfaceClosure closure, const Aabb& closedBounds, const glm::mat4& clipFromModel) {
    if (closure == SurfaceClosure::Open || closedBounds.empty()) {
        return GL_NONE;
    }
    for (const glm::vec3& corner : closedBounds.corners()) {
        const glm::vec4 clip = clipFromModel * glm::vec4(corner, 1.0f);
        // In front of the near plane (z > -w), with a little room for the clipper's rounding.
        if (!(clip.w > 0.0f) || !(clip.z + clip.w > 1e-5f * clip.w)) {
            return GL_NONE;
        }
    }
    const float orientation = glm::determinant(clipFromModel);
    if (!(std::abs(orientation) > 0.0f) || !std::isfinite(orientation)) {
        return GL_NONE;
    }
    // A standard view and projection have a negative determinant and show a surface's outside
    // counter-clockwise: the clockwise faces of an Outward part are the hidden ones.
    const bool backIsHidden = (closure == SurfaceClosure::Outward) == (orientation < 0.0f);
    return backIsHidden ? GL_BACK : GL_FRONT;
}

} // namespace engine
