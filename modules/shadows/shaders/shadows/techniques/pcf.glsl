// pcf: the fraction of the pattern's hardware comparisons that pass (Reeves et al. 1987).
#ifdef GS_SHADOW_PCF
GsShadowSample gsShadowSample_Pcf(GsShadowLookup lookup) {
    mat2 rotation = gsShadowRotation();
    float sum = 0.0;
    for (int i = 0; i < gsTapCount; ++i) {
        vec2 tap = (lookup.texel + rotation * gsTapOffsets[i]) * gsShadowTexel[lookup.slot].y;
        sum += gsShadowCompare(lookup.slot, tap, gsShadowReference(lookup.depth));
    }
    return gsShadowResult(sum / float(max(gsTapCount, 1)), 1.0, lookup);
}
#define gsShadowSample gsShadowSample_Pcf
#endif
