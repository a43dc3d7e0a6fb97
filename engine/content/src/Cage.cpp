#include "content/Cage.h"

#include "content/ContentError.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace content {
namespace {

// Relative threshold below which a face counts as having zero area: |area| <= kDegenerateAreaRatio * e^2,
// with e the face's longest edge. Catches collinear and collapsed faces without flagging thin but real ones.
constexpr double kDegenerateAreaRatio = 1e-7;

// OpenSubdiv's limit on the vertices of a face and the faces around a vertex (Vtr::VALENCE_LIMIT); its
// refiner factory fails on larger ones with only a console message.
constexpr std::size_t kMaxValence = (1u << 16) - 1;

std::string formatNumber(float value) {
    if (std::isnan(value)) {
        return "nan";
    }
    std::ostringstream out;
    out << value; // prints "inf" / "-inf" for infinities
    return out.str();
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

/// One face's use of an edge, kept to stitch face corners around shared vertices.
struct HalfEdge {
    std::uint32_t face = 0;
    std::uint32_t from = 0;       // vertex the face leaves the edge from
    std::uint32_t fromCorner = 0; // global corner ids (face-vertex slots) of both ends
    std::uint32_t toCorner = 0;
};

struct EdgeUses {
    std::uint32_t count = 0;
    HalfEdge first;
    HalfEdge second;
};

/// Disjoint sets over face corners; corners joined across shared edges form the fans around a vertex.
class CornerSets {
public:
    explicit CornerSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0u); }

    std::uint32_t find(std::uint32_t c) {
        while (parent_[c] != c) {
            parent_[c] = parent_[parent_[c]]; // path halving
            c = parent_[c];
        }
        return c;
    }

    void join(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

private:
    std::vector<std::uint32_t> parent_;
};

class Validator {
public:
    explicit Validator(const Cage& cage) : cage_(cage) {}

    void run() {
        if (cage_.faces.empty()) {
            fail("no faces");
        }
        checkPositions();
        checkFaces();
        collectEdges();
        checkEdges();
        checkVertices();
        checkCreases();
        checkCorners();
        if (cage_.scheme == Scheme::Loop) {
            checkTriangles();
        }
    }

private:
    [[noreturn]] void fail(const std::string& detail) const { throw ContentError(cage_.source, detail); }

    std::string vertex(std::uint32_t v) const { return std::to_string(std::uint64_t{v} + cage_.indexBase); }
    std::string face(std::size_t f) const { return std::to_string(f + cage_.indexBase); }
    std::string edge(std::uint32_t a, std::uint32_t b) const {
        return "(" + vertex(a) + "," + vertex(b) + ")";
    }

    void checkPositions() const {
        for (std::size_t v = 0; v < cage_.positions.size(); ++v) {
            for (int axis = 0; axis < 3; ++axis) {
                const float c = cage_.positions[v][axis];
                if (!std::isfinite(c)) {
                    fail("vertex " + vertex(static_cast<std::uint32_t>(v)) + " has non-finite coordinate (" +
                         formatNumber(c) + ")");
                }
            }
        }
    }

    void checkFaces() const {
        const std::size_t vertexCount = cage_.positions.size();
        std::vector<std::uint32_t> sorted;
        for (std::size_t f = 0; f < cage_.faces.size(); ++f) {
            const auto& fv = cage_.faces[f];
            if (fv.size() < 3) {
                fail("face " + face(f) + " has " + std::to_string(fv.size()) +
                     " vertices (at least 3 needed)");
            }
            if (fv.size() > kMaxValence) {
                fail("face " + face(f) + " has " + std::to_string(fv.size()) + " vertices (at most " +
                     std::to_string(kMaxValence) + " supported)");
            }
            for (const std::uint32_t v : fv) {
                if (v >= vertexCount) {
                    fail("face " + face(f) + " index " + vertex(v) + " is out of range (" +
                         std::to_string(vertexCount) + " vertices)");
                }
            }
            // Sorting finds repeats in O(n log n); comparing every pair stalls on faces of 10^5 vertices.
            sorted.assign(fv.begin(), fv.end());
            std::sort(sorted.begin(), sorted.end());
            if (const auto repeat = std::adjacent_find(sorted.begin(), sorted.end());
                repeat != sorted.end()) {
                fail("face " + face(f) + " is degenerate (vertex " + vertex(*repeat) + " repeated)");
            }
            if (hasZeroArea(fv)) {
                fail("face " + face(f) + " is degenerate (zero area)");
            }
        }
    }

    // Newell's method (Sutherland, Sproull & Schumacker 1974): the summed cross products of a polygon's
    // edges give twice its vector area, also for non-planar polygons. Done in double to keep tiny areas
    // exact.
    bool hasZeroArea(const std::vector<std::uint32_t>& fv) const {
        const glm::dvec3 origin(cage_.positions[fv[0]]);
        glm::dvec3 twiceArea(0.0);
        double longestEdge2 = 0.0;
        for (std::size_t i = 0; i < fv.size(); ++i) {
            const glm::dvec3 a = glm::dvec3(cage_.positions[fv[i]]) - origin;
            const glm::dvec3 b = glm::dvec3(cage_.positions[fv[(i + 1) % fv.size()]]) - origin;
            twiceArea += glm::cross(a, b);
            const glm::dvec3 e = b - a;
            longestEdge2 = std::max(longestEdge2, glm::dot(e, e));
        }
        return 0.5 * glm::length(twiceArea) <= kDegenerateAreaRatio * longestEdge2;
    }

    void collectEdges() {
        std::uint32_t corner = 0;
        for (std::size_t f = 0; f < cage_.faces.size(); ++f) {
            const auto& fv = cage_.faces[f];
            const auto n = static_cast<std::uint32_t>(fv.size());
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t next = (i + 1) % n;
                const HalfEdge half{static_cast<std::uint32_t>(f), fv[i], corner + i, corner + next};
                const std::uint64_t key = edgeKey(fv[i], fv[next]);
                auto [it, inserted] = edges_.try_emplace(key);
                if (inserted) {
                    edgeOrder_.push_back(key);
                }
                EdgeUses& uses = it->second;
                if (uses.count == 0) {
                    uses.first = half;
                } else if (uses.count == 1) {
                    uses.second = half;
                }
                ++uses.count;
            }
            corner += n;
        }
        cornerCount_ = corner;
    }

    void checkEdges() const {
        for (const std::uint64_t key : edgeOrder_) {
            const EdgeUses& uses = edges_.at(key);
            const auto a = static_cast<std::uint32_t>(key >> 32);
            const auto b = static_cast<std::uint32_t>(key & 0xffffffffu);
            if (uses.count > 2) {
                fail("edge " + edge(a, b) + " is non-manifold (" + std::to_string(uses.count) + " faces)");
            }
            // Two faces agreeing in orientation traverse a shared edge in opposite directions.
            if (uses.count == 2 && uses.first.from == uses.second.from) {
                fail("edge " + edge(a, b) + " has inconsistent orientation (faces " + face(uses.first.face) +
                     " and " + face(uses.second.face) + " traverse it in the same direction)");
            }
        }
    }

    void checkVertices() const {
        CornerSets fans(cornerCount_);
        for (const auto& [key, uses] : edges_) {
            if (uses.count == 2) {
                // Opposite directions (checked above): first's start meets second's end and vice versa.
                fans.join(uses.first.fromCorner, uses.second.toCorner);
                fans.join(uses.first.toCorner, uses.second.fromCorner);
            }
        }
        std::vector<std::vector<std::uint32_t>> fanRoots(cage_.positions.size());
        std::uint32_t corner = 0;
        for (const auto& fv : cage_.faces) {
            for (const std::uint32_t v : fv) {
                fanRoots[v].push_back(fans.find(corner++));
            }
        }
        for (std::size_t v = 0; v < fanRoots.size(); ++v) {
            auto& roots = fanRoots[v];
            if (roots.empty()) {
                fail("vertex " + vertex(static_cast<std::uint32_t>(v)) + " is not used by any face");
            }
            if (roots.size() > kMaxValence) {
                fail("vertex " + vertex(static_cast<std::uint32_t>(v)) + " is used by " +
                     std::to_string(roots.size()) + " faces (at most " + std::to_string(kMaxValence) +
                     " supported)");
            }
            std::sort(roots.begin(), roots.end());
            const auto fanCount = std::unique(roots.begin(), roots.end()) - roots.begin();
            if (fanCount > 1) {
                fail("vertex " + vertex(static_cast<std::uint32_t>(v)) + " is non-manifold (its faces form " +
                     std::to_string(fanCount) + " separate fans)");
            }
        }
    }

    void checkSharpness(const std::string& element, float sharpness) const {
        if (!std::isfinite(sharpness) || sharpness < 0.0f) {
            fail(element + " has invalid sharpness (" + formatNumber(sharpness) + ")");
        }
    }

    void checkCreases() const {
        const std::size_t vertexCount = cage_.positions.size();
        for (const EdgeCrease& crease : cage_.creases) {
            const std::string label = "crease " + edge(crease.v0, crease.v1);
            if (crease.v0 >= vertexCount || crease.v1 >= vertexCount) {
                fail(label + " is out of range (" + std::to_string(vertexCount) + " vertices)");
            }
            if (crease.v0 == crease.v1 || !edges_.contains(edgeKey(crease.v0, crease.v1))) {
                fail(label + " is not an edge of the cage");
            }
            checkSharpness(label, crease.sharpness);
        }
    }

    void checkCorners() const {
        const std::size_t vertexCount = cage_.positions.size();
        for (const VertexCorner& corner : cage_.corners) {
            const std::string label = "corner " + vertex(corner.vertex);
            if (corner.vertex >= vertexCount) {
                fail(label + " is out of range (" + std::to_string(vertexCount) + " vertices)");
            }
            checkSharpness(label, corner.sharpness);
        }
    }

    void checkTriangles() const {
        for (std::size_t f = 0; f < cage_.faces.size(); ++f) {
            if (cage_.faces[f].size() != 3) {
                fail("face " + face(f) + " has " + std::to_string(cage_.faces[f].size()) +
                     " vertices, but Loop subdivision needs triangles");
            }
        }
    }

    const Cage& cage_;
    std::unordered_map<std::uint64_t, EdgeUses> edges_;
    std::vector<std::uint64_t> edgeOrder_; // first-use order, so the first bad edge in the file is reported
    std::uint32_t cornerCount_ = 0;
};

} // namespace

void Cage::validate() const {
    Validator(*this).run();
}

bool Cage::isAllTriangles() const {
    return std::all_of(faces.begin(), faces.end(), [](const auto& f) { return f.size() == 3; });
}

} // namespace content
