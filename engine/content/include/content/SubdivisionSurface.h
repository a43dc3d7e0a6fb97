#pragma once

#include "content/Cage.h"

#include <engine/MeshData.h>

#include <vector>

namespace content {

/// @brief Uniformly refines a control cage with OpenSubdiv and samples its limit surface.
///
/// Boundaries use "edge and corner" interpolation (boundary edges and valence-2 corners stay sharp).
/// Output positions and normals lie on the limit surface at the vertices of the chosen refinement
/// level; the faces of that level are triangulated (quads along their shorter diagonal; the polygons
/// of an unrefined level-0 cage as fans, which assumes they are convex).
///
/// Normals are normalize(cross(du, dv)) of the limit tangents, outward for counter-clockwise cages.
/// Where the tangents degenerate they are the area-weighted average of the adjacent faces' normals.
/// On infinitely sharp creases and corners the limit surface has no single normal: OpenSubdiv's
/// tangents there give the normal of one side, so render such edges with split vertices if needed.
class SubdivisionSurface {
public:
    /// @brief Highest refinement level accepted (each level multiplies the face count by 4).
    static constexpr int kMaxLevel = 6;

    /// @brief Topology size of one refinement level.
    struct LevelCounts {
        int vertices = 0;
        int edges = 0;
        int faces = 0;
    };

    /// @brief A limit-surface mesh and the statistics of the refinement that produced it.
    struct Result {
        engine::MeshData mesh;
        /// @brief Refinement level of `mesh`.
        int level = 0;
        /// @brief Counts for levels 0 (the cage) to `level`.
        std::vector<LevelCounts> levels;
        /// @brief Longest edge of the refined faces, measured between limit positions (world units).
        float maxEdgeLength = 0.0f;
    };

    /// @brief Validates the cage (Cage::validate) and keeps it for evaluation.
    /// @throws ContentError if the cage is invalid.
    explicit SubdivisionSurface(Cage cage);

    /// @brief The cage being subdivided.
    [[nodiscard]] const Cage& cage() const { return cage_; }

    /// @brief Refines uniformly to `level` and evaluates limit positions and normals at its vertices.
    /// @throws std::out_of_range if `level` is outside [0, kMaxLevel].
    [[nodiscard]] Result evaluate(int level) const;

    /// @brief Evaluates the smallest level whose longest limit edge is at most `targetEdgeLength`,
    /// or kMaxLevel if none is.
    /// @throws std::invalid_argument if `targetEdgeLength` is not a positive finite number.
    [[nodiscard]] Result evaluateForEdgeLength(float targetEdgeLength) const;

private:
    Cage cage_;
    // Flattened copies of the cage in the form OpenSubdiv's TopologyDescriptor references.
    std::vector<int> faceSizes_;
    std::vector<int> faceVertices_;
    std::vector<int> creaseVertices_;
    std::vector<float> creaseWeights_;
    std::vector<int> cornerVertices_;
    std::vector<float> cornerWeights_;
};

} // namespace content
