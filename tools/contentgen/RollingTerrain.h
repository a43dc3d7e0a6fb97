#pragma once

#include <engine/MeshData.h>

#include <glm/glm.hpp>

namespace contentgen {

/// @brief Gently rolling ground: a smooth analytic height field sampled on a regular grid centred at the
/// origin, cut into square tiles (one mesh each, so the renderer can cull them).
///
/// height() answers for the triangulated surface itself, so objects stood on it neither float nor sink.
class RollingTerrain {
public:
    /// @brief `size` × `size` world units in `tiles` × `tiles` tiles of `quadsPerTile`² quads.
    RollingTerrain(float size, int tiles, int quadsPerTile);

    /// @brief Height of the triangulated ground at (x, z) (clamped to its extent).
    [[nodiscard]] float height(float x, float z) const;
    /// @brief Lowest height of the ground under the square of half-width `halfWidth` around (x, z): where a
    /// footing must reach so no gap shows on a slope.
    [[nodiscard]] float lowestUnder(float x, float z, float halfWidth) const;

    [[nodiscard]] int tiles() const { return tiles_; }
    /// @brief Centre of tile (column, row) on the XZ plane (y = 0): the tile mesh's origin.
    [[nodiscard]] glm::vec3 tileCentre(int column, int row) const;
    /// @brief The mesh of tile (column, row), positions relative to tileCentre(), normals of the analytic
    /// field (smooth across tiles).
    [[nodiscard]] engine::MeshData tile(int column, int row) const;

private:
    /// The analytic field: long sine waves (±28 m) and three hills up to 110 m high; slopes below ~10°.
    [[nodiscard]] static float field(float x, float z);
    [[nodiscard]] static glm::vec3 fieldNormal(float x, float z);
    /// Grid vertex (i, j) in world space.
    [[nodiscard]] glm::vec3 gridPoint(int i, int j) const;

    float size_;
    int tiles_;
    int quadsPerTile_;
    float cell_;
};

} // namespace contentgen
