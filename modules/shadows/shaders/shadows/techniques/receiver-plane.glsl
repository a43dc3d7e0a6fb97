// receiver-plane: receiver-plane depth bias from screen derivatives (bias reference), per texel of a 2x2 bilinear
// footprint, or per PCF tap (GS_SHADOW_RPB_PER_TAP).
#ifdef GS_SHADOW_RECEIVER_PLANE
GsShadowSample gsShadowSample_ReceiverPlane(GsShadowLookup lookup) {
    vec2 texel = lookup.texel;
    float depth = lookup.depth;
    vec2 screenGradient = lookup.screenGradient;
    bool clampBias = gsShadowReceiverPlaneClamp != 0;
#if defined(GS_SHADOW_RPB_PER_TAP)
    mat2 rotation = gsShadowRotation();
    float sum = 0.0;
    for (int i = 0; i < gsTapCount; ++i) {
        vec2 centre = floor(texel + rotation * gsTapOffsets[i]) + 0.5;
        float tapDepth = gsReceiverPlaneTapDepth(depth, centre - texel, screenGradient, clampBias);
        sum += gsShadowCompare(lookup, centre * lookup.inverseSize, gsShadowReference(tapDepth));
    }
    return GsShadowSample(sum / float(max(gsTapCount, 1)), 1.0, 0.0, screenGradient, false);
#else
    float stored;
    float reference;
    float visibility = gsPlaneCompareBilinear(lookup, texel, screenGradient, clampBias, stored, reference);
    return GsShadowSample(visibility, stored, reference - depth, screenGradient, false);
#endif
}
#define gsShadowSample gsShadowSample_ReceiverPlane
#endif
