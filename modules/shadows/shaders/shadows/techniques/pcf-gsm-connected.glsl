// pcf-gsm-connected: PCF over GSM, taps that continue the receiver's surface without a jump count as lit.
#include "shadows/pcf-gsm-taps.glsl"
#if defined(GS_SHADOW_PCF_GSM) && defined(GS_SHADOW_CORRECTION_CONNECTED)
uniform int gsTapNearestFirst[GS_MAX_TAPS];
uniform float gsTapLinkDistance;

GsShadowSample gsShadowSample_PcfGsmConnected(GsShadowLookup lookup) {
    float depths[GS_MAX_TAPS];
    mat2 rotation = gsPcfGsmFetch(lookup, depths);
    // The pattern's frame, as the other corrections' (rotation is orthonormal).
    float visibility = gsPcfGsmConnectedVisibility(
        depths, gsTapOffsets, gsTapNearestFirst, gsTapCount, gsTapLinkDistance, lookup.depth,
        transpose(rotation) * lookup.pointGradient, gsShadowFuzzyScale, gsShadowDepthStep);
    return gsShadowResult(visibility, depths[0], lookup);
}
#define gsShadowSample gsShadowSample_PcfGsmConnected
#endif
