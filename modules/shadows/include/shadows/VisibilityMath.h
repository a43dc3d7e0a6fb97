#pragma once

/// @file
/// @brief The shadow visibility functions of shaders/shadows/visibility.glsl compiled as C++ with GLM,
/// so CPU tests exercise exactly the code the lighting shader runs.

#include <glm/glm.hpp>

namespace shadows::glsl {

// Internal linkage: every translation unit that includes this gets its own copy, like a shader does.
namespace {
// A translation unit uses only some of the shader's functions, like a shader variant does.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"

using namespace glm;

/// GLSL's `out T` parameters become references.
#define GS_OUT(T) T&
#include "../../shaders/shadows/visibility.glsl"
#undef GS_OUT

#pragma GCC diagnostic pop
} // namespace
} // namespace shadows::glsl
