// The shadow module's part of the lighting pass's vertex stage (forward.vert "vertex_declarations" slot).
#include "block.glsl"
#include "vertex-projection.glsl"

#ifdef GS_SHADOW_VERTEX_PROJECTION
// Per light, the vertex in its single map, first drawn cascade or finest clipmap level, unbiased (zero for other
// layouts).
out vec4 vGsShadowClip[GS_LIGHT_COUNT];
#endif

void gsShadowVertexOutputs(vec4 world) {
#ifdef GS_SHADOW_VERTEX_PROJECTION
    for (int lightIndex = 0; lightIndex < GS_LIGHT_COUNT; ++lightIndex) {
        GsShadowLightMaps maps = gsShadowLights[lightIndex];
        int kind = maps.kind.x;
        int slot = kind == GS_SHADOW_LIGHT_SINGLE                                              ? maps.slots.x
                   : kind == GS_SHADOW_LIGHT_CASCADES || kind == GS_SHADOW_LIGHT_VIRTUAL ? maps.kind.z
                                                                                         : -1;
        vGsShadowClip[lightIndex] = slot >= 0 ? gsShadowMatrix[slot] * world : vec4(0.0);
    }
#endif
}
