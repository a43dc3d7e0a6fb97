// pcf-gsm-average: PCF over GSM, taps follow the least-squares gradient of the taps' own depths; or the
// reference's unrolled circular-8 forms, whose closed-form average gradient then drives the point correction.
#include "shadows/pcf-gsm-taps.glsl"
#if defined(GS_SHADOW_PCF_GSM) && defined(GS_SHADOW_CORRECTION_AVERAGE)
GsShadowSample gsShadowSample_PcfGsmAverage(GsShadowLookup lookup) {
#if defined(GS_SHADOW_AVG_CIRCULAR8) || defined(GS_SHADOW_AVG_VEC4)
    float depths[GS_MAX_TAPS];
    gsPcfGsmFetch(lookup, depths);
    float eight[8];
    for (int i = 0; i < 8; ++i) {
        eight[i] = depths[i];
    }
#if defined(GS_SHADOW_AVG_VEC4)
    vec2 gradient = gsCircular8GradientVec4(vec4(eight[0], eight[1], eight[2], eight[3]),
                                            vec4(eight[4], eight[5], eight[6], eight[7]), gsTapDisplace);
#else
    vec2 gradient = gsCircular8Gradient(eight, gsTapDisplace);
#endif
    return gsPcfGsmSample(lookup, depths, gradient, GS_CORRECTION_POINT);
#else
    return gsPcfGsmSample(lookup, GS_CORRECTION_AVERAGE);
#endif
}
#define gsShadowSample gsShadowSample_PcfGsmAverage
#endif
