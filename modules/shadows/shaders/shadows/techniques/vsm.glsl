// vsm: variance shadow map, Chebyshev's bound on the filtered moments (z, z²).
#ifdef GS_SHADOW_STORE_MOMENTS2
#define GS_SHADOW_STORED_MOMENTS vec2
vec2 gsShadowStore(float depth) { return vec2(depth, depth * depth); }
#endif

#ifdef GS_SHADOW_VSM
GsShadowSample gsShadowSample_Vsm(GsShadowLookup lookup) {
    vec2 moments = gsShadowMoments(lookup).rg;
    float visibility =
        gsChebyshevVisibility(moments, lookup.momentDepth, gsShadowMinimumVariance, gsShadowBleedingReduction);
    return gsShadowResult(visibility, moments.x, lookup);
}
#define gsShadowSample gsShadowSample_Vsm
#endif
