#version 450 core
// Shadow pass. Beside the depth it may store, per texel:
// - GS_SHADOW_STORE_GRADIENT: the depth gradient per texel (GSM reference: "generated from derivative
//   instructions in the first pass and stored with the depth map");
// - filtered moments: the technique's file defines gsShadowStore(depth) and its type GS_SHADOW_STORED_MOMENTS
//   under the define of its MomentStore (ShadowTechniqueTraits).
#define GS_OUT(T) out T
#include "frame.glsl"
#include "block.glsl"
#include "visibility.glsl"
#include "techniques.glsl"

// Near and far of a perspective map, zero for orthographic ones (gsLinearDepth).
uniform vec2 uDepthRange;

#if defined(GS_SHADOW_STORE_GRADIENT)
layout(location = 0) out vec2 outValue;
#elif defined(GS_SHADOW_STORED_MOMENTS)
layout(location = 0) out GS_SHADOW_STORED_MOMENTS outValue;
#endif

void main() {
#if defined(GS_SHADOW_STORE_GRADIENT)
    // One fragment is one texel, so these are dz per texel step.
    outValue = vec2(dFdxFine(gl_FragCoord.z), dFdyFine(gl_FragCoord.z));
#elif defined(GS_SHADOW_STORED_MOMENTS)
    outValue = gsShadowStore(gsLinearDepth(gl_FragCoord.z, uDepthRange));
#endif
}
