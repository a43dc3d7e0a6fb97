#include "content/SubdivisionSurface.h"

#include "content/ContentError.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

namespace content {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// Limit tangents scale with the refined edges around a vertex, so |du x dv| is compared with the squared
// longest incident edge. Below this ratio the tangents are rounding noise or (nearly) parallel, as at a
// branch point of a folded cage, and the normal comes from the adjacent faces instead.
constexpr float kMinTangentArea = 1e-6f;

/// Primvar element in the form Far::PrimvarRefiner interpolates (Clear / AddWithWeight).
struct Point {
    glm::vec3 p{0.0f};

    void Clear() { p = glm::vec3(0.0f); }
    void AddWithWeight(const Point& src, float weight) { p += weight * src.p; }
};

std::unique_ptr<Far::TopologyRefiner> createRefiner(const Cage& cage,
                                                    const Far::TopologyDescriptor& descriptor) {
    Sdc::Options sdcOptions;
    sdcOptions.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    const Sdc::SchemeType scheme = cage.scheme == Scheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(descriptor, Factory::Options(scheme, sdcOptions)));
    if (!refiner) {
        // Cage::validate() rejects everything OpenSubdiv is known to refuse; this guards the remainder.
        throw ContentError(cage.source, "OpenSubdiv rejected the cage topology");
    }
    return refiner;
}

/// Writable view of a glm::vec3 array in the form PrimvarRefiner::Limit writes through, so limit results land
/// in their final arrays without an intermediate copy.
class Vec3Output {
public:
    struct Element {
        glm::vec3& value;

        void Clear() { value = glm::vec3(0.0f); }
        void AddWithWeight(const Point& src, float weight) { value += weight * src.p; }
    };

    explicit Vec3Output(std::vector<glm::vec3>& values) : values_(values) {}

    Element operator[](int index) { return Element{values_[static_cast<std::size_t>(index)]}; }

private:
    std::vector<glm::vec3>& values_;
};

/// Normalised sum of the area-weighted normals of the faces around `vertex` (Newell normals, whose length is
/// twice the area), measured on the limit positions.
glm::vec3 faceAverageNormal(const Far::TopologyLevel& level, int vertex,
                            const std::vector<glm::vec3>& positions) {
    glm::vec3 sum(0.0f);
    for (const int f : level.GetVertexFaces(vertex)) {
        const auto fv = level.GetFaceVertices(f);
        // Relative to the first corner, so that distance from the origin costs no precision.
        const glm::vec3 origin = positions[static_cast<std::size_t>(fv[0])];
        for (int i = 1; i + 1 < fv.size(); ++i) {
            sum += glm::cross(positions[static_cast<std::size_t>(fv[i])] - origin,
                              positions[static_cast<std::size_t>(fv[i + 1])] - origin);
        }
    }
    const float length = glm::length(sum);
    // Only a vertex whose every adjacent face collapsed on the limit surface has no direction at all; any
    // unit vector then keeps shading finite.
    return length > 0.0f ? sum / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

/// Squared length of the longest edge at `vertex`, measured on the limit positions.
float longestEdgeSquared(const Far::TopologyLevel& level, int vertex,
                         const std::vector<glm::vec3>& positions) {
    float longest = 0.0f;
    for (const int e : level.GetVertexEdges(vertex)) {
        const auto ev = level.GetEdgeVertices(e);
        const glm::vec3 d =
            positions[static_cast<std::size_t>(ev[0])] - positions[static_cast<std::size_t>(ev[1])];
        longest = std::max(longest, glm::dot(d, d));
    }
    return longest;
}

/// Unit normal from the limit tangents; empty where they do not span a plane on the scale of the surrounding
/// edges (`edgeScale2`, a squared length), in which case the caller falls back to the adjacent faces.
std::optional<glm::vec3> tangentNormal(const glm::vec3& du, const glm::vec3& dv, float edgeScale2) {
    const glm::vec3 n = glm::cross(du, dv);
    const float length = glm::length(n);
    if (!(length > kMinTangentArea * edgeScale2)) {
        return std::nullopt;
    }
    return n / length;
}

/// Appends the triangles of a refined face. Quads are split along their shorter diagonal, which stays closer
/// to a curved surface than the longer one.
void triangulate(const Far::ConstIndexArray& fv, const std::vector<glm::vec3>& positions,
                 std::vector<std::uint32_t>& indices) {
    auto emit = [&](int a, int b, int c) {
        indices.push_back(static_cast<std::uint32_t>(fv[a]));
        indices.push_back(static_cast<std::uint32_t>(fv[b]));
        indices.push_back(static_cast<std::uint32_t>(fv[c]));
    };
    if (fv.size() == 4) {
        auto at = [&](int corner) { return positions[static_cast<std::size_t>(fv[corner])]; };
        const float d02 = glm::distance(at(0), at(2));
        const float d13 = glm::distance(at(1), at(3));
        if (d02 <= d13) {
            emit(0, 1, 2);
            emit(0, 2, 3);
        } else {
            emit(0, 1, 3);
            emit(1, 2, 3);
        }
        return;
    }
    // Triangles, and the polygons of an unrefined (level 0) Catmull-Clark cage, fanned from their first
    // corner.
    for (int i = 1; i + 1 < fv.size(); ++i) {
        emit(0, i, i + 1);
    }
}

} // namespace

SubdivisionSurface::SubdivisionSurface(Cage cage) : cage_(std::move(cage)) {
    cage_.validate();
    for (const auto& face : cage_.faces) {
        faceSizes_.push_back(static_cast<int>(face.size()));
        faceVertices_.insert(faceVertices_.end(), face.begin(), face.end());
    }
    for (const EdgeCrease& crease : cage_.creases) {
        creaseVertices_.push_back(static_cast<int>(crease.v0));
        creaseVertices_.push_back(static_cast<int>(crease.v1));
        creaseWeights_.push_back(crease.sharpness);
    }
    for (const VertexCorner& corner : cage_.corners) {
        cornerVertices_.push_back(static_cast<int>(corner.vertex));
        cornerWeights_.push_back(corner.sharpness);
    }
}

SubdivisionSurface::Result SubdivisionSurface::evaluate(int level) const {
    if (level < 0 || level > kMaxLevel) {
        throw std::out_of_range("SubdivisionSurface::evaluate: level " + std::to_string(level) +
                                " is outside [0, " + std::to_string(kMaxLevel) + "]");
    }

    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = static_cast<int>(cage_.positions.size());
    descriptor.numFaces = static_cast<int>(faceSizes_.size());
    descriptor.numVertsPerFace = faceSizes_.data();
    descriptor.vertIndicesPerFace = faceVertices_.data();
    descriptor.numCreases = static_cast<int>(creaseWeights_.size());
    descriptor.creaseVertexIndexPairs = creaseVertices_.data();
    descriptor.creaseWeights = creaseWeights_.data();
    descriptor.numCorners = static_cast<int>(cornerWeights_.size());
    descriptor.cornerVertexIndices = cornerVertices_.data();
    descriptor.cornerWeights = cornerWeights_.data();
    const auto refiner = createRefiner(cage_, descriptor);
    if (level > 0) {
        Far::TopologyRefiner::UniformOptions uniform(level);
        // Limit masks need each last-level vertex's edges and faces, which are omitted by default.
        uniform.fullTopologyInLastLevel = true;
        refiner->RefineUniform(uniform);
    }

    // Only two levels are alive at a time: each level is interpolated from the previous one.
    std::vector<Point> points(cage_.positions.size());
    std::transform(cage_.positions.begin(), cage_.positions.end(), points.begin(),
                   [](const glm::vec3& p) { return Point{p}; });
    const Far::PrimvarRefiner primvarRefiner(*refiner);
    std::vector<Point> refined;
    for (int l = 1; l <= level; ++l) {
        refined.resize(static_cast<std::size_t>(refiner->GetLevel(l).GetNumVertices()));
        primvarRefiner.Interpolate(l, points, refined);
        std::swap(points, refined);
    }
    refined = {}; // release the next-to-last level before the limit buffers are allocated

    const std::size_t vertexCount = points.size();
    const Far::TopologyLevel& last = refiner->GetLevel(level);
    Result result;
    result.level = level;
    engine::MeshData& mesh = result.mesh;
    mesh.name = std::filesystem::path(cage_.source).stem().string();
    mesh.positions.resize(vertexCount);
    mesh.normals.resize(vertexCount);

    // Limit positions and the two limit tangents (first derivatives) at every vertex of the last level. The
    // first tangent is parked in the normals array, each entry being replaced by the normal it yields, which
    // saves a 12-byte-per-vertex buffer.
    std::vector<glm::vec3> dv(vertexCount);
    Vec3Output positionOutput(mesh.positions);
    Vec3Output duOutput(mesh.normals);
    Vec3Output dvOutput(dv);
    primvarRefiner.Limit(points, positionOutput, duOutput, dvOutput);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        // cross(du, dv) faces outward for counter-clockwise faces in OpenSubdiv's (right-handed) convention.
        const int vertex = static_cast<int>(v);
        const std::optional<glm::vec3> normal =
            tangentNormal(mesh.normals[v], dv[v], longestEdgeSquared(last, vertex, mesh.positions));
        mesh.normals[v] = normal ? *normal : faceAverageNormal(last, vertex, mesh.positions);
    }

    // Each face of n corners yields n - 2 triangles.
    mesh.indices.reserve(3 * static_cast<std::size_t>(last.GetNumFaceVertices() - 2 * last.GetNumFaces()));
    for (int f = 0; f < last.GetNumFaces(); ++f) {
        triangulate(last.GetFaceVertices(f), mesh.positions, mesh.indices);
    }
    for (int e = 0; e < last.GetNumEdges(); ++e) {
        const auto ev = last.GetEdgeVertices(e);
        result.maxEdgeLength =
            std::max(result.maxEdgeLength, glm::distance(mesh.positions[ev[0]], mesh.positions[ev[1]]));
    }
    for (int l = 0; l <= level; ++l) {
        const Far::TopologyLevel& counts = refiner->GetLevel(l);
        result.levels.push_back({counts.GetNumVertices(), counts.GetNumEdges(), counts.GetNumFaces()});
    }
    return result;
}

SubdivisionSurface::Result SubdivisionSurface::evaluateForEdgeLength(float targetEdgeLength) const {
    if (!std::isfinite(targetEdgeLength) || targetEdgeLength <= 0.0f) {
        throw std::invalid_argument("SubdivisionSurface::evaluateForEdgeLength: target edge length must be "
                                    "positive and finite");
    }
    // Each level costs about 4x the previous one, so trying levels in turn costs at most ~4/3 of the chosen
    // one.
    for (int level = 0;; ++level) {
        Result result = evaluate(level);
        if (result.maxEdgeLength <= targetEdgeLength || level == kMaxLevel) {
            return result;
        }
    }
}

} // namespace content
