#pragma once

#include <engine/Bounds.h>
#include <engine/MeshChunks.h>

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace engine {

/// @brief A mesh's chunks where the scene places them.
struct PlacedChunks {
    glm::mat4 model{1.0f};
    /// The bounds of every chunk, local space.
    Aabb bounds;
    std::span<const MeshChunk> chunks;
};

/// @brief Whether a flat surface on `plane` (world space, unit normal: n·p + w = 0) shadows no point of
/// `receivers` (world space) from a light at homogeneous `light` (w = 0: the direction towards a directional
/// light). A ray from a point towards the light crosses the plane only where the point and the light lie on
/// opposite sides of it (for a direction: where the point lies on the side the direction leaves), so none
/// does when every point lies on the light's side, or on the plane within `tolerance`; nor when the light
/// lies on the plane itself (or shines along it).
[[nodiscard]] bool castsNoShadow(const glm::vec4& plane, const glm::vec4& light,
                                 std::span<const glm::vec3> receivers, float tolerance);

/// @brief The flat chunks (MeshChunk::plane) of `meshes` that shadow nothing of `meshes` from `light`:
/// every chunk of every mesh lies on the light's side of the flat chunk's plane, judged by its bounds'
/// corners (conservative: a box wholly on one side holds all it bounds), or is flat on that same plane. A
/// shadow pass may leave them out: no receiver lies behind them. Points on the plane count as the light's
/// side within a relative 1e-5 of the flat chunk's size. Chunks of a model that cannot be inverted are kept.
[[nodiscard]] std::vector<const MeshChunk*> chunksCastingNoShadow(std::span<const PlacedChunks> meshes,
                                                                  const glm::vec4& light);

} // namespace engine
