#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace content {

/// @brief Subdivision rules applied to a cage.
enum class Scheme {
    CatmullClark, ///< Quads and arbitrary polygons (Catmull & Clark 1978).
    Loop,         ///< Triangle-only cages (Loop 1987).
};

/// @brief Semi-sharp crease on the cage edge between two vertices.
///
/// Sharpness follows the DeRose/Kass/Truong (SIGGRAPH 1998) convention: the edge is refined with the
/// sharp rule for `sharpness` levels, then smoothly; 0 is smooth, 10 or more is effectively infinitely sharp.
struct EdgeCrease {
    std::uint32_t v0 = 0;
    std::uint32_t v1 = 0;
    float sharpness = 0.0f;
};

/// @brief Semi-sharp corner at a cage vertex (same sharpness convention as EdgeCrease).
struct VertexCorner {
    std::uint32_t vertex = 0;
    float sharpness = 0.0f;
};

/// @brief Polygonal control cage of a subdivision surface.
///
/// Faces list vertex indices counter-clockwise when seen from outside (right-handed, outward normals).
/// Indices are 0-based; `indexBase` only affects how indices are printed in error messages.
struct Cage {
    /// @brief Where the cage came from (a file path, or a label for cages built in code); prefixes every
    /// error.
    std::string source = "<in-memory cage>";
    /// @brief Added to vertex and face indices in diagnostics so they match the source's own numbering
    /// (1 for OBJ, whose indices are 1-based; 0 for OFF and cages built in code).
    std::uint32_t indexBase = 0;
    /// @brief Subdivision rules; Loop requires every face to be a triangle.
    Scheme scheme = Scheme::CatmullClark;
    /// @brief Control point positions.
    std::vector<glm::vec3> positions;
    /// @brief One vertex-index list per face; any valence of at least 3.
    std::vector<std::vector<std::uint32_t>> faces;
    /// @brief Semi-sharp edges; each must join two vertices that are adjacent in some face.
    std::vector<EdgeCrease> creases;
    /// @brief Semi-sharp vertices.
    std::vector<VertexCorner> corners;

    /// @brief Checks that the cage is a valid input for subdivision, throwing ContentError on the first
    /// problem.
    ///
    /// Rejects: no faces; non-finite coordinates; faces with fewer than 3 or more than 65535 vertices
    /// (OpenSubdiv's valence limit), out-of-range or repeated indices, or zero area; edges shared by more
    /// than two faces or traversed the same way by two faces; vertices used by no face or by more than 65535
    /// faces, or whose faces form more than one fan (non-manifold vertices); creases that are not cage edges;
    /// corners out of range; negative or non-finite sharpness; non-triangles under Loop. Runs in O(n log n)
    /// of the cage's size.
    void validate() const;

    /// @brief True when every face is a triangle.
    [[nodiscard]] bool isAllTriangles() const;
};

} // namespace content
