// pcf-gsm-point: PCF over GSM, taps follow the fragment's own gradient.
#include "shadows/pcf-gsm-taps.glsl"
#if defined(GS_SHADOW_PCF_GSM) && defined(GS_SHADOW_CORRECTION_POINT)
GsShadowSample gsShadowSample_PcfGsmPoint(GsShadowLookup lookup) {
    return gsPcfGsmSample(lookup, GS_CORRECTION_POINT);
}
#define gsShadowSample gsShadowSample_PcfGsmPoint
#endif
