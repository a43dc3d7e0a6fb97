// msm-soft: moment soft shadows (Peters, Münstermann, Wetzstein, Klein, "Beyond Hard Shadows: Moment Shadow Maps
// for Single Scattering, Soft Shadows and Translucent Occluders", I3D 2016): PCSS's three steps on filtered
// moments, so each costs one fetch whatever the width. The blocker search reads the moments over the search
// region and takes the blockers from the bound's own distribution (gsMsmBlocker); the filter reads them over the
// penumbra and bounds visibility as `msm` does. The paper filters with summed-area tables; here the moments' mip
// chain does (ShadowPlan::momentLevels): a level's texel averages 2^L texels and the trilinear blend of its
// neighbours spreads that over a tent as wide, whose second moment (r^2/4 per axis at 2^L = r) is a disk's of
// radius r, the PCF disk `pcss` filters over. The sizes are `pcss`'s: world units at the receiver, turned into
// the texels of the map, cascade or page read.
#ifdef GS_SHADOW_MSM_SOFT
// A mip level's bilinear kernel reaches 1.5 of its texels from the lookup (kMomentKernelReach).
const float GS_MSM_SOFT_KERNEL_REACH = 1.5;

vec4 gsMsmSoftMoments(GsShadowLookup lookup, float radiusTexels) {
    vec4 moments = gsShadowMomentsOver(lookup, radiusTexels);
#ifdef GS_SHADOW_MSM_QUANTIZED
    moments = gsMsmDequantize(moments, gsShadowMsmDequantize);
#endif
    return moments;
}

// The depth, as the moments store it, a receiver is compared at over a footprint of `radiusTexels`: its
// tangent plane spreads its own depths by the gradient over the kernel's reach (|gx| + |gy| at a corner),
// which the bound would read as blockers at grazing light, so the comparison stands in front of the nearest.
float gsMsmSoftDepth(GsShadowLookup lookup, float radiusTexels) {
    vec2 gradient = abs(lookup.tangentGradient);
    float spread = (gradient.x + gradient.y) * GS_MSM_SOFT_KERNEL_REACH * max(radiusTexels, 1.0);
    return gsLinearDepth(lookup.depth - spread, gsShadowDepthRange[lookup.slot].xy);
}

// A moment depth (gsLinearDepth's) as a distance, as gsShadowDistance does for a stored depth.
float gsMsmSoftDistance(GsShadowLookup lookup, float momentDepth) {
    if (lookup.perspective) {
        vec2 range = gsShadowDepthRange[lookup.slot].xy;
        return range.x + momentDepth * (range.y - range.x);
    }
    return momentDepth / max(lookup.depthScale, 1e-30);
}

GsShadowSample gsShadowSample_MsmSoft(GsShadowLookup lookup) {
    float receiver = gsShadowDistance(lookup, lookup.depth);
    // The widest radius, texels (momentSoftRadiusLimit): the mip chain's last level.
    float limit = gsShadowTechniqueParameters.x;
    float searchTexels = gsSoftRadiusTexels(lookup, receiver, gsShadowDistance(lookup, 0.0), limit);
    float fraction = 0.0;
    float blockerDepth = 1.0;
    if (searchTexels >= 0.5) {
        blockerDepth = gsMsmBlocker(gsMsmSoftMoments(lookup, searchTexels), gsMsmSoftDepth(lookup, searchTexels),
                                    gsShadowMomentBias, fraction);
    }
    if (fraction < 1e-3) {
        // A light of no size, or no blocker in front of the search's comparison depth: none at all, or one too
        // near the receiver to stand out from the spread of its own plane (at a caster's foot), whose penumbra
        // is narrow. Either way `msm`'s one bilinear lookup decides, a hard shadow.
        vec4 moments = gsMsmSoftMoments(lookup, 0.0);
        return gsShadowResult(gsMsmVisibility(moments, lookup.momentDepth, gsShadowMomentBias), moments.x, lookup);
    }
    float filterTexels = gsSoftRadiusTexels(lookup, receiver, gsMsmSoftDistance(lookup, blockerDepth), limit);
    if (fraction > 0.999 && filterTexels <= searchTexels) {
        return gsShadowResult(0.0, blockerDepth, lookup); // the whole light hidden
    }
    vec4 moments = gsMsmSoftMoments(lookup, filterTexels);
    return gsShadowResult(gsMsmVisibility(moments, gsMsmSoftDepth(lookup, filterTexels), gsShadowMomentBias),
                          moments.x, lookup);
}
#define gsShadowSample gsShadowSample_MsmSoft
#endif
