// pcss: percentage-closer soft shadows (Fernando, SIGGRAPH 2005 sketch). A blocker search over the part of the
// map through which the light's disk reaches the receiver, the penumbra's width from the average blocker's
// distance by similar triangles (gsPcssRadius), then PCF of that width. The sizes are world units at the
// receiver, turned into the texels of whatever map, cascade or page the lookup reads, so a penumbra keeps its
// width across a cascade's or a level's seam. Every tap is compared at the receiver's tangent plane (never
// deeper than the fragment), not at a plane from screen derivatives, which break at grazing angles and
// silhouettes; both disks are Vogel disks turned per pixel by interleaved gradient noise (Jimenez 2014), so
// undersampling shows as fine noise rather than ghost copies of the blocker.
#if defined(GS_SHADOW_PCSS) || defined(GS_SHADOW_PCSS_SCREEN_PLANE)
// pcss-screen-plane (naive) compares at the plane from screen derivatives instead, as Filament, HDRP and MJP's
// sample do, biased both ways.
#ifdef GS_SHADOW_PCSS_SCREEN_PLANE
#define GS_PCSS_PLANE(lookup) lookup.screenGradient
const bool GS_PCSS_NEVER_DEEPER = false;
#else
#define GS_PCSS_PLANE(lookup) lookup.tangentGradient
const bool GS_PCSS_NEVER_DEEPER = true;
#endif
// Mirrored by kPcssSearchTaps and kPcssFilterTaps (ShadowTechniqueTraits.h), which the cost model counts.
const int GS_PCSS_SEARCH_TAPS = 16;
const int GS_PCSS_FILTER_TAPS = 24;

// One filter tap: the 2x2 texels around `texel`, each compared at the receiver's plane there, blended
// bilinearly.
float gsPcssTap(GsShadowLookup lookup, vec2 texel) {
    float stored;
    float reference;
    return gsPlaneCompareBilinear(lookup, texel, GS_PCSS_PLANE(lookup), GS_PCSS_NEVER_DEEPER, stored, reference);
}

GsShadowSample gsShadowSample_Pcss(GsShadowLookup lookup) {
    float receiver = gsShadowDistance(lookup, lookup.depth);
    float nearest = gsShadowDistance(lookup, 0.0);
    // The widest radius searched or filtered, texels: the margin this map or page keeps (softReachTexels, or
    // the wider one a directional map's fit holds for its light's penumbrae).
    float limit = gsShadowSoftReachTexels[lookup.slot / 4][lookup.slot % 4];
    float searchTexels = gsSoftRadiusTexels(lookup, receiver, nearest, limit);
    if (searchTexels < 0.5) {
        // A light of no size (or a receiver at the map's near plane): one comparison, a hard shadow.
        vec2 centre = floor(lookup.texel) + 0.5;
        float stored = gsShadowDepthAt(lookup, centre);
        float reference =
            gsReceiverPlaneTapDepth(lookup.depth, centre - lookup.texel, GS_PCSS_PLANE(lookup), GS_PCSS_NEVER_DEEPER);
        return gsShadowResult(gsCompare(stored, gsShadowReference(reference)), stored, lookup);
    }
    float angle = 6.28318531 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    // Blocker search: the mean depth of the taps nearer than the receiver's plane there.
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < GS_PCSS_SEARCH_TAPS; ++i) {
        vec2 offset = gsVogelTap(i, GS_PCSS_SEARCH_TAPS, angle) * searchTexels;
        vec2 centre = floor(lookup.texel + offset) + 0.5;
        float stored = gsShadowDepthAt(lookup, centre);
        float reference =
            gsReceiverPlaneTapDepth(lookup.depth, centre - lookup.texel, GS_PCSS_PLANE(lookup), GS_PCSS_NEVER_DEEPER);
        if (stored < gsShadowReference(reference)) {
            blockerSum += stored;
            ++blockers;
        }
    }
    if (blockers == 0) {
        return gsShadowResult(1.0, 1.0, lookup); // nothing between the receiver and any part of the light
    }
    float blocker = gsShadowDistance(lookup, blockerSum / float(blockers));
    float filterTexels = gsSoftRadiusTexels(lookup, receiver, blocker, limit);
    if (blockers == GS_PCSS_SEARCH_TAPS && filterTexels <= searchTexels) {
        return gsShadowResult(0.0, blockerSum / float(blockers), lookup); // the whole light hidden
    }
    float sum = 0.0;
    for (int i = 0; i < GS_PCSS_FILTER_TAPS; ++i) {
        sum += gsPcssTap(lookup, lookup.texel + gsVogelTap(i, GS_PCSS_FILTER_TAPS, angle + 1.0) *
                                                      max(filterTexels, 0.5));
    }
    return gsShadowResult(sum / float(GS_PCSS_FILTER_TAPS), blockerSum / float(blockers), lookup);
}
#define gsShadowSample gsShadowSample_Pcss
#endif
