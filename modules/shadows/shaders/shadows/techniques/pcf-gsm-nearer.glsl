// pcf-gsm-nearer: PCF over GSM, each tap compared at the nearer of the point- and average-gradient predictions.
#include "shadows/pcf-gsm-taps.glsl"
#if defined(GS_SHADOW_PCF_GSM) && defined(GS_SHADOW_CORRECTION_NEARER)
GsShadowSample gsShadowSample_PcfGsmNearer(GsShadowLookup lookup) {
    return gsPcfGsmSample(lookup, GS_CORRECTION_NEARER);
}
#define gsShadowSample gsShadowSample_PcfGsmNearer
#endif
