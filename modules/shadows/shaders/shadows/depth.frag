#version 450 core
// Shadow pass. With GS_SHADOW_STORE_GRADIENT the depth gradient per texel is stored beside the depth
// (GSM reference: "generated from derivative instructions in the first pass and stored with the depth map").
#ifdef GS_SHADOW_STORE_GRADIENT
layout(location = 0) out vec2 outGradient;
#endif

void main() {
#ifdef GS_SHADOW_STORE_GRADIENT
    // One fragment is one texel, so these are dz per texel step.
    outGradient = vec2(dFdxFine(gl_FragCoord.z), dFdyFine(gl_FragCoord.z));
#endif
}
