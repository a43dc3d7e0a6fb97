#pragma once

#include <engine/MeshData.h>

namespace contentgen {

/// @brief Closed cylinder around +Y from y = 0 to y = `height`: `segments` sides with smooth normals, flat
/// caps.
engine::MeshData cylinder(float radius, float height, int segments);

/// @brief Closed cone around +Y with smooth sides: base disc of `radius` at y = 0, apex at y = `height`.
engine::MeshData cone(float radius, float height, int segments);

/// @brief Closed square pyramid with flat faces: base [-0.5, 0.5]² at y = 0, apex at (0, 1, 0) (a hipped roof
/// once scaled to a building's footprint).
engine::MeshData pyramid();

} // namespace contentgen
