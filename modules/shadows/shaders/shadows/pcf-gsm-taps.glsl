// PCF over GSM, shared by its corrections (techniques/pcf-gsm-*.glsl): the taps' depths around the fragment, and
// the fuzzy comparisons at the receiver depths a correction predicts.
#ifdef GS_SHADOW_PCF_GSM

// Fetches the pattern's depths; returns the pattern's rotation.
mat2 gsPcfGsmFetch(GsShadowLookup lookup, out float depths[GS_MAX_TAPS]) {
    mat2 rotation = gsShadowRotation();
    for (int i = 0; i < gsTapCount; ++i) {
        depths[i] = gsShadowDepthAt(lookup, lookup.texel + rotation * gsTapOffsets[i]);
    }
    return rotation;
}

// `gradient` is in the pattern's frame (the fits run there).
GsShadowSample gsPcfGsmSample(GsShadowLookup lookup, float depths[GS_MAX_TAPS], vec2 gradient, int correction) {
    float visibility = gsPcfGsmVisibility(depths, gsTapOffsets, gsTapCount, lookup.depth, gradient, correction,
                                          gsTapInverseCovariance, gsTapFitRows, gsShadowFuzzyScale,
                                          gsShadowDepthStep);
    return gsShadowResult(visibility, depths[0], lookup);
}

// The corrections that need no more than the fragment's own gradient.
GsShadowSample gsPcfGsmSample(GsShadowLookup lookup, int correction) {
    float depths[GS_MAX_TAPS];
    mat2 rotation = gsPcfGsmFetch(lookup, depths);
    // The fits run in the pattern's frame: bring the point gradient into it (rotation is orthonormal).
    return gsPcfGsmSample(lookup, depths, transpose(rotation) * lookup.pointGradient, correction);
}
#endif
