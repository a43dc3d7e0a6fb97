// pcf-gsm-naive: PCF over GSM, every tap compared at the fragment's depth (reproduces the reference's Fig. 4.2.3).
#include "shadows/pcf-gsm-taps.glsl"
#if defined(GS_SHADOW_PCF_GSM) && defined(GS_SHADOW_CORRECTION_NONE)
GsShadowSample gsShadowSample_PcfGsmNaive(GsShadowLookup lookup) {
    return gsPcfGsmSample(lookup, GS_CORRECTION_NONE);
}
#define gsShadowSample gsShadowSample_PcfGsmNaive
#endif
