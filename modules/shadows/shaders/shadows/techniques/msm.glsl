// msm: moment shadow map, Hamburger bound on four filtered moments, optionally stored in the 16-bit basis.
#ifdef GS_SHADOW_STORE_MOMENTS4
#define GS_SHADOW_STORED_MOMENTS vec4
vec4 gsShadowStore(float depth) {
    vec4 moments = gsMsmMoments(depth);
#ifdef GS_SHADOW_MSM_QUANTIZED
    moments = gsMsmQuantize(moments);
#endif
    return moments;
}
#endif

#ifdef GS_SHADOW_MSM
GsShadowSample gsShadowSample_Msm(GsShadowLookup lookup) {
    vec4 moments = gsShadowMoments(lookup);
#ifdef GS_SHADOW_MSM_QUANTIZED
    moments = gsMsmDequantize(moments, gsShadowMsmDequantize);
#endif
    return gsShadowResult(gsMsmVisibility(moments, lookup.momentDepth, gsShadowMomentBias), moments.x, lookup);
}
#define gsShadowSample gsShadowSample_Msm
#endif
