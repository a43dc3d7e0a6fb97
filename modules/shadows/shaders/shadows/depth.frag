#version 450 core
// Shadow pass. Beside the depth it may store, per texel:
// - GS_SHADOW_STORE_GRADIENT: the depth gradient per texel (GSM reference: "generated from derivative
//   instructions in the first pass and stored with the depth map");
// - GS_SHADOW_STORE_MOMENTS2 / 4: depth moments for VSM (z, z²) or MSM (z .. z⁴), optionally in the optimised
//   16-bit basis (GS_SHADOW_MSM_QUANTIZED).
#define GS_OUT(T) out T
#include "visibility.glsl"

#if defined(GS_SHADOW_STORE_GRADIENT) || defined(GS_SHADOW_STORE_MOMENTS2)
layout(location = 0) out vec2 outValue;
#elif defined(GS_SHADOW_STORE_MOMENTS4)
layout(location = 0) out vec4 outValue;
#endif

void main() {
#if defined(GS_SHADOW_STORE_GRADIENT)
    // One fragment is one texel, so these are dz per texel step.
    outValue = vec2(dFdxFine(gl_FragCoord.z), dFdyFine(gl_FragCoord.z));
#elif defined(GS_SHADOW_STORE_MOMENTS2)
    float z = gl_FragCoord.z;
    outValue = vec2(z, z * z);
#elif defined(GS_SHADOW_STORE_MOMENTS4)
    vec4 moments = gsMsmMoments(gl_FragCoord.z);
#ifdef GS_SHADOW_MSM_QUANTIZED
    moments = gsMsmQuantize(moments);
#endif
    outValue = moments;
#endif
}
