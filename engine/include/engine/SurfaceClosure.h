#pragma once

#include <engine/Bounds.h>
#include <engine/MeshData.h>

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace engine {

/// @brief Whether a connected part of a mesh bounds a solid, and which way its triangles wind around it.
enum class SurfaceClosure : std::uint8_t {
    /// Some edge of the part is not matched by one of opposite direction (a boundary, a crack, a T-junction,
    /// a
    /// flipped triangle), or the part encloses no volume: seen from anywhere, either face may be the nearest.
    Open,
    /// Closed, wound counter-clockwise seen from outside (right-handed normals point out).
    Outward,
    /// Closed, wound the other way.
    Inward,
};

/// @brief A mesh's connected parts (triangles sharing a corner, positions welded where their coordinates are
/// equal: a vertex split for its normals is one point) and each one's closure.
struct SurfaceParts {
    struct Part {
        SurfaceClosure closure = SurfaceClosure::Open;
        /// Bounds of the part's corners, local space.
        Aabb bounds;
    };
    /// The part of each triangle; degenerate triangles (two corners at one point) belong to an Open part of
    /// their own, since they cover nothing.
    std::vector<std::uint32_t> triangleParts;
    std::vector<Part> parts;
};

/// @brief Finds `mesh`'s parts and classifies each. A part is closed when every edge is used as often in one
/// direction as in the other, and its winding is the sign of its enclosed volume (none: Open). From a point
/// outside a closed part, the nearest of its surfaces along any ray is one turned towards that point: the
/// winding number only rises from 0 where the ray enters the part. Malformed input (an index out of range, a
/// position not finite) makes every part Open.
[[nodiscard]] SurfaceParts surfaceParts(const MeshData& mesh);

/// @brief The face (GL_BACK or GL_FRONT, for GL's counter-clockwise front faces) that a pass through
/// `clipFromModel` may leave out of triangles of a `closure` part whose parts lie in `closedBounds` (local
/// space) without changing the nearest depth at any pixel, or GL_NONE. Only where the whole box lies in front
/// of the near plane: the viewpoint is then outside every part, and no part is cut open by the near plane.
/// The winding the projection turns front follows the sign of det(clipFromModel) (a projective map's Jacobian
/// determinant has the sign of its matrix's), so a mirroring model or view swaps the face.
[[nodiscard]] GLenum hiddenFace(SurfaceClosure closure, const Aabb& closedBounds,
                                const glm::mat4& clipFromModel);

} // namespace engine
