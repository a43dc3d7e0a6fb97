#version 450 core
// Forward lighting pass. Modules inject code at the two slots (contracts in docs/MODULES.md).
#include "lighting.glsl"

uniform vec3 uBaseColor;
uniform vec3 uSpecularColor;
uniform float uShininess;

in vec3 vWorldPosition;
in vec3 vWorldNormal;

layout(location = 0) out vec4 outColor;

#pragma gs_slot(declarations)

void main() {
#ifdef GS_FLAT_NORMALS
    // The mesh has no normals: use the triangle's own, from screen-space derivatives.
    vec3 normal = normalize(cross(dFdx(vWorldPosition), dFdy(vWorldPosition)));
#else
    vec3 normal = normalize(vWorldNormal);
#endif
    vec3 toCamera = normalize(gsCameraPosition.xyz - vWorldPosition);
    // Two-sided lighting: a back face seen by the camera is lit as its front.
    if (dot(normal, toCamera) < 0.0) {
        normal = -normal;
    }
    vec3 color = gsAmbient.rgb * uBaseColor;
    for (int lightIndex = 0; lightIndex < GS_LIGHT_COUNT; ++lightIndex) {
        vec3 toLight;
        float attenuation;
        gsLightIncidence(lightIndex, vWorldPosition, toLight, attenuation);
        float visibility = 1.0;
#pragma gs_slot(light_visibility)
        vec3 lightColor = gsLights[lightIndex].colorIntensity.rgb * gsLights[lightIndex].colorIntensity.a;
        color += visibility * attenuation *
                 gsBlinnPhong(normal, toLight, toCamera, lightColor, uBaseColor, uSpecularColor, uShininess);
    }
#pragma gs_slot(final_color)
#if defined(GS_OUTPUT_WORLD_POSITION)
    // Measurement pass (float target): where each pixel's surface is, alpha 1 marks covered pixels.
    outColor = vec4(vWorldPosition, 1.0);
#elif defined(GS_OUTPUT_WORLD_NORMAL)
    outColor = vec4(normal, 1.0);
#else
    // Linear output; the sRGB framebuffer encodes it (GL_FRAMEBUFFER_SRGB).
    outColor = vec4(color, 1.0);
#endif
}
