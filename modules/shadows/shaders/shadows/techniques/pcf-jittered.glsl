// pcf-jittered: soft shadows reference: pairs of stratified offsets from the jitter texture, tiled over the screen.
// With early-out, the first pairs are test taps; when they agree the pixel is not in a penumbra and the rest are
// skipped. The result averages every tap actually taken (the reference's pseudo-code divides by the full count
// either way, which darkens skipped pixels). Each tap is compared at the receiver's tangent plane under it, never
// deeper than the fragment, as in pcf.glsl.
#ifdef GS_SHADOW_JITTERED
uniform sampler3D gsShadowJitter; // two stratified offsets per texel

float gsJitteredTap(GsShadowLookup lookup, vec2 offset) {
    float reference = gsReceiverPlaneTapDepth(lookup.depth, offset, lookup.tangentGradient, true);
    return gsShadowCompare(lookup, (lookup.texel + offset) * lookup.inverseSize,
                           gsShadowReference(reference));
}

GsShadowSample gsShadowSample_Jittered(GsShadowLookup lookup) {
    ivec2 tile = ivec2(mod(gl_FragCoord.xy, 32.0));
    float lit = 0.0;
    int taken = 0;
    for (int pair = 0; pair < gsJitterPairs; ++pair) {
        vec4 offsets = (texelFetch(gsShadowJitter, ivec3(tile, pair), 0) * 2.0 - 1.0) * gsShadowJitterRadius;
        lit += gsJitteredTap(lookup, offsets.xy);
        lit += gsJitteredTap(lookup, offsets.zw);
        taken += 2;
#ifdef GS_SHADOW_EARLY_OUT
        // At the pair's end, not the next one's start: llvmpipe leaves a loop only at its end, once no fragment
        // of its group continues, so a test at the start ran one more pair, masked off, for every group.
        if (pair + 1 == gsEarlyOutPairs && gsTestTapsAgree(lit, float(taken))) {
            break;
        }
#endif
    }
    GsShadowSample result = gsShadowResult(lit / float(max(taken, 1)), 1.0, lookup);
    result.fullKernel = taken == 2 * gsJitterPairs;
    return result;
}
#define gsShadowSample gsShadowSample_Jittered
#endif
