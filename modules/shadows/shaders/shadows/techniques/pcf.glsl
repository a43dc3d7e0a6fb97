// pcf: the fraction of the pattern's hardware comparisons that pass (Reeves et al. 1987). Each tap is compared
// at the depth of the receiver's tangent plane under it (receiver-plane bias per tap, from the facet: Dou et al.,
// JCGT 3(4) 2014; Ehm et al., WSCG 2015), never deeper than the fragment's own (gsNoDeeperThanFragment), so the
// normal offset need not reach the whole kernel: one texel diagonal (docs/SHADOWS.md, "Automatic bias").
#ifdef GS_SHADOW_PCF
GsShadowSample gsShadowSample_Pcf(GsShadowLookup lookup) {
    mat2 rotation = gsShadowRotation();
    float sum = 0.0;
    for (int i = 0; i < gsTapCount; ++i) {
        vec2 offset = rotation * gsTapOffsets[i];
        float reference = gsReceiverPlaneTapDepth(lookup.depth, offset, lookup.tangentGradient, true);
        vec2 tap = (lookup.texel + offset) * lookup.inverseSize;
        sum += gsShadowCompare(lookup, tap, gsShadowReference(reference));
    }
    return gsShadowResult(sum / float(max(gsTapCount, 1)), 1.0, lookup);
}
#define gsShadowSample gsShadowSample_Pcf
#endif
