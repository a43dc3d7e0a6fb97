#pragma once

#include <engine/MeshData.h>

namespace engine::primitives {

/// @brief Axis-aligned cube centred at the origin with edge length `size`; flat normals, 24 vertices.
MeshData cube(float size = 1.0f);
/// @brief Square in the XZ plane, normal +Y, side `size`, split into `divisions`² quads.
MeshData plane(float size = 10.0f, int divisions = 1);
/// @brief UV sphere of `radius`, `rings` latitude bands and `segments` longitude bands, smooth normals.
MeshData sphere(float radius = 1.0f, int rings = 16, int segments = 32);

} // namespace engine::primitives
