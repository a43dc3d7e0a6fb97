#pragma once

#include "SceneBuilder.h"

namespace contentgen {

/// @brief `room`: a closed 8 × 6 × 3 m room (floor, four walls, ceiling, normals facing in) with a table on
/// thin legs, chairs, crates, two pillars, a shelf and a ball, lit by two overlapping point lights (range
/// 10 m); the camera stands inside, looking at the furniture.
void buildRoom(SceneBuilder& b);

/// @brief `outdoor`: 4 × 4 km of gently rolling ground in 16 × 16 tiles, a few hundred buildings, trees,
/// posts and boulders from 0.5 m to 40 m tall spread over it (some beside the camera), a camera at eye
/// height (1.8 m) looking towards the horizon (near 0.3 m, far 5 km) and a sun 30° high.
void buildOutdoor(SceneBuilder& b);

} // namespace contentgen
