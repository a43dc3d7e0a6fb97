// pcf-gsm-quadratic: PCF over GSM, taps follow a least-squares quadric of the taps' depths.
#include "shadows/pcf-gsm-taps.glsl"
#if defined(GS_SHADOW_PCF_GSM) && defined(GS_SHADOW_CORRECTION_QUADRATIC)
GsShadowSample gsShadowSample_PcfGsmQuadratic(GsShadowLookup lookup) {
    return gsPcfGsmSample(lookup, GS_CORRECTION_QUADRATIC);
}
#define gsShadowSample gsShadowSample_PcfGsmQuadratic
#endif
