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
    // textureGather returns the 2x2 footprint's depths. The reference nudges the coordinate by 1/512 texel so
    // frac() and the gather agree on the footprint; we gather at the footprint's centre instead, which is half a
    // texel from any selection boundary, so the two agree on every implementation's sub-texel precision.
    vec2 footprint = floor(texel - 0.5);
    vec2 weights = texel - 0.5 - footprint;
    vec2 gatherAt = (footprint + 1.0) * lookup.inverseSize;
    vec4 gathered = gsShadowGather(lookup, gatherAt);
    // Gather order x (-,+), y (+,+), z (+,-), w (-,-): distances from the pixel to each texel centre.
    vec2 toCentre0 = vec2(-weights.x, 1.0 - weights.y);
    vec2 toCentre1 = vec2(1.0 - weights.x, 1.0 - weights.y);
    vec2 toCentre2 = vec2(1.0 - weights.x, -weights.y);
    vec2 toCentre3 = vec2(-weights.x, -weights.y);
    vec4 references = vec4(gsReceiverPlaneTapDepth(depth, toCentre0, screenGradient, clampBias),
                           gsReceiverPlaneTapDepth(depth, toCentre1, screenGradient, clampBias),
                           gsReceiverPlaneTapDepth(depth, toCentre2, screenGradient, clampBias),
                           gsReceiverPlaneTapDepth(depth, toCentre3, screenGradient, clampBias));
    vec4 lit = vec4(gsCompare(gathered.x, gsShadowReference(references.x)),
                    gsCompare(gathered.y, gsShadowReference(references.y)),
                    gsCompare(gathered.z, gsShadowReference(references.z)),
                    gsCompare(gathered.w, gsShadowReference(references.w)));
    return GsShadowSample(gsBilinear(lit, weights), gathered.w, references.w - depth, screenGradient, false);
#endif
}
#define gsShadowSample gsShadowSample_ReceiverPlane
#endif
