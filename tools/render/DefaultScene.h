#pragma once

#include <engine/Scene.h>

/// @brief The built-in default scene: a cube and a sphere on a ground plane, one directional light, one
/// camera.
engine::Scene makeDefaultScene();
