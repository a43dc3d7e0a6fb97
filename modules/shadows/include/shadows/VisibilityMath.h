#pragma once

/// @file
/// @brief The shadow visibility functions of shaders/shadows/visibility.glsl compiled as C++ with GLM,
/// so CPU tests exercise exactly the code the lighting shader runs.

#include <glm/glm.hpp>

namespace shadows::glsl {

using namespace glm;

#define GS_OUT(T) T&
#include "../../shaders/shadows/visibility.glsl"
#undef GS_OUT

} // namespace shadows::glsl
