#pragma once

/// @file
/// @brief shaders/shadows/visibility.glsl compiled once more in double precision, as the reference the float
/// mirror (and so the shader) is measured against in the stability sweep. The GLSL's float literals stay
/// float, so the mixed float/double calls they create are given double overloads first.

#include <glm/glm.hpp>

namespace shadows::glsl_double {

using namespace glm;
/// @{
/// @brief GLSL's vector and matrix types, in double precision.
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using mat2 = glm::dmat2;
using mat4 = glm::dmat4;
/// @}

/// @{
/// @brief The built-in (or operator) for a float literal of the GLSL meeting a double: computed in double.
inline double clamp(double x, float low, float high) {
    return glm::clamp(x, double(low), double(high));
}
inline int clamp(int x, int low, int high) {
    return glm::clamp(x, low, high);
}
inline double max(double a, float b) {
    return glm::max(a, double(b));
}
inline double max(float a, double b) {
    return glm::max(double(a), b);
}
inline double max(double a, double b) {
    return glm::max(a, b);
}
inline int max(int a, int b) {
    return glm::max(a, b);
}
inline double min(double a, float b) {
    return glm::min(a, double(b));
}
inline double min(float a, double b) {
    return glm::min(double(a), b);
}
inline double min(double a, double b) {
    return glm::min(a, b);
}
template <int N>
glm::vec<N, double> operator*(const glm::vec<N, double>& v, float s) {
    return v * double(s);
}
template <int N>
glm::vec<N, double> operator*(float s, const glm::vec<N, double>& v) {
    return double(s) * v;
}
/// @}

// Internal linkage, as in VisibilityMath.h.
namespace {
// A translation unit uses only some of the shader's functions, like a shader variant does.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
/// GLSL's `out T` parameters become references.
#define GS_OUT(T) T&
/// Every float of the GLSL becomes double.
#define float double
#include "../../shaders/shadows/visibility.glsl"
#undef float
#undef GS_OUT
#pragma GCC diagnostic pop
} // namespace

} // namespace shadows::glsl_double
