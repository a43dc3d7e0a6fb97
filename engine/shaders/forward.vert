#version 450 core
// Forward lighting pass and depth pre-pass. Modules inject code at the two vertex slots (docs/MODULES.md).
#include "frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
// The depth pre-pass and the lighting pass must produce bit-identical depth for their EQUAL test.
invariant gl_Position;

#pragma gs_slot(vertex_declarations)

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalMatrix * inNormal;
    gl_Position = gsViewProjection * world;
#pragma gs_slot(vertex_outputs)
}
