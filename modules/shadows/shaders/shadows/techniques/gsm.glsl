// gsm: one linear-filtered depth, fuzzy comparison over a band as wide as the fragment's gradient.
#ifdef GS_SHADOW_GSM
GsShadowSample gsShadowSample_Gsm(GsShadowLookup lookup) {
    float stored = gsShadowDepthAt(lookup, lookup.texel);
    float visibility = gsFuzzyVisibility(stored, lookup.depth, length(lookup.pointGradient), gsShadowFuzzyScale,
                                         gsShadowDepthStep);
    return gsShadowResult(visibility, stored, lookup);
}
#define gsShadowSample gsShadowSample_Gsm
#endif
