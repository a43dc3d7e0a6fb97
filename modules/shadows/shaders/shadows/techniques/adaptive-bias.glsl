// adaptive-bias, pcf-adaptive-bias: adaptive depth bias (Dou, Yan, Kerzner, Dai, Wyman, JCGT 3(4), 2014): each
// comparison at the depth the receiver's tangent plane has on the light's ray through the centre of the texel
// compared, lowered by the depth bias (depthBiasSteps steps of the format: the paper's epsilon from the depth
// precision); with the tap pattern, the same for every PCF tap (Ehm et al., WSCG 2015). Never deeper than the
// fragment's own depth (gsNoDeeperThanFragment): a tangent plane extrapolated downhill past a crease or limb
// meets other surfaces, and nothing behind the fragment can occlude it (the single comparison met the floor in
// 118 of 126 Defaults views without this, 125 with it: docs/SHADOWS.md, "Never deeper than the fragment").
#if defined(GS_SHADOW_ADAPTIVE) || defined(GS_SHADOW_ADAPTIVE_PCF)
GsShadowSample gsShadowSample_AdaptiveBias(GsShadowLookup lookup) {
#ifdef GS_SHADOW_ADAPTIVE_PCF
    mat2 rotation = gsShadowRotation();
    int count = gsTapCount;
#else
    int count = 1;
#endif
    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
#ifdef GS_SHADOW_ADAPTIVE_PCF
        vec2 centre = floor(lookup.texel + rotation * gsTapOffsets[i]) + 0.5;
#else
        vec2 centre = floor(lookup.texel) + 0.5;
#endif
        float reference =
            gsReceiverPlaneTapDepth(lookup.depth, centre - lookup.texel, lookup.tangentGradient, true);
        sum += gsShadowCompare(lookup, centre * lookup.inverseSize, gsShadowReference(reference));
    }
    return GsShadowSample(sum / float(max(count, 1)), 1.0, 0.0, lookup.tangentGradient, false);
}
#define gsShadowSample gsShadowSample_AdaptiveBias
#endif
