// hard, slope-scaled, hw-pcf, normal-offset: one hardware comparison; the sampler decides NEAREST or 2x2 LINEAR
// PCF, the casters' polygon offset and the lookup's normal offset happen before.
#ifdef GS_SHADOW_SINGLE_COMPARE
GsShadowSample gsShadowSample_SingleCompare(GsShadowLookup lookup) {
    float visibility = gsShadowCompare(lookup, lookup.coord, gsShadowReference(lookup.depth));
    return gsShadowResult(visibility, visibility, lookup);
}
#define gsShadowSample gsShadowSample_SingleCompare
#endif
