// evsm: exponential variance shadow map: two warped depths and their squares, filtered like VSM's moments,
// Chebyshev's bound on each warp, the smaller one wins (gsEvsmVisibility). Exponents in
// gsShadowTechniqueParameters.xy.
#ifdef GS_SHADOW_STORE_EVSM
#define GS_SHADOW_STORED_MOMENTS vec4
vec4 gsShadowStore(float depth) { return gsEvsmMoments(depth, gsShadowTechniqueParameters.xy); }
#endif

#ifdef GS_SHADOW_EVSM
GsShadowSample gsShadowSample_Evsm(GsShadowLookup lookup) {
    vec2 exponents = gsShadowTechniqueParameters.xy;
    vec4 moments = gsShadowMoments(lookup);
    float visibility =
        gsEvsmVisibility(moments, lookup.momentDepth, exponents, gsShadowMinimumVariance, gsShadowBleedingReduction);
    // The shadow-map view shows the filtered depth the positive warp's mean stands for.
    float stored = log(max(moments.x, 1e-30)) / max(exponents.x, 1e-6);
    return gsShadowResult(visibility, stored, lookup);
}
#define gsShadowSample gsShadowSample_Evsm
#endif
