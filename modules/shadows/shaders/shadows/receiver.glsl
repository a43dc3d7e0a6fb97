// Shadow visibility in the lighting pass (forward.frag "declarations" slot). One variant per technique and
// option: the GS_SHADOW_* defines come from the shadow module's variant bits, so only what a scene uses compiles.
#define GS_OUT(T) out T
#include "visibility.glsl"

const int GS_SHADOW_MAX_MAPS = 4;

uniform int gsShadowSlot[GS_MAX_LIGHTS];              // shadow map of each engine light, -1 for none
uniform mat4 gsShadowMatrix[GS_SHADOW_MAX_MAPS];      // world -> shadow texture space (divide by w)
uniform vec4 gsShadowTexel[GS_SHADOW_MAX_MAPS];       // x resolution, y 1/resolution, z texel scale, w perspective
uniform float gsShadowConstantBias;                   // world units towards the light
uniform float gsShadowDepthStep;                      // depth format step (0 for float)
uniform float gsShadowFuzzyScale;                     // GSM band width in texels
uniform float gsShadowNormalOffset;                   // normal offset in texel sizes
uniform bool gsShadowReceiverPlaneClamp;

#ifdef GS_SHADOW_SAMPLER_COMPARE
uniform sampler2DShadow gsShadowMap[GS_SHADOW_MAX_MAPS];
#else
uniform sampler2D gsShadowMap[GS_SHADOW_MAX_MAPS];
#endif
#ifdef GS_SHADOW_GRADIENT_STORED
uniform sampler2D gsShadowGradientMap[GS_SHADOW_MAX_MAPS];
#endif

uniform float gsShadowMinimumVariance;               // VSM
uniform float gsShadowBleedingReduction;             // VSM
uniform float gsShadowMomentBias;                    // MSM
uniform mat4 gsShadowMsmDequantize;                  // MSM 16-bit: inverse of the optimised basis
#ifdef GS_SHADOW_JITTERED
uniform sampler3D gsShadowJitter;                    // two stratified offsets per texel (soft shadows reference)
uniform int gsJitterPairs;
uniform int gsEarlyOutPairs;                         // 0: always the full kernel
uniform float gsShadowJitterRadius;                  // texels
#endif

uniform int gsTapCount;
uniform vec2 gsTapOffsets[GS_MAX_TAPS];
uniform mat2 gsTapInverseCovariance;
uniform float gsTapFitRows[6 * GS_MAX_TAPS];
uniform float gsTapDisplace; // circular-8 d, texels

// What the debug views show: the values of the first shadowed light of this fragment.
float gsDebugVisibility = 1.0;
float gsDebugGradient = 0.0;
float gsDebugBias = 0.0;
float gsDebugStored = 1.0;
vec2 gsDebugTexel = vec2(0.0);
bool gsDebugSet = false;
bool gsDebugFullKernel = false;

// Reference (comparison) depth, floored to the format's step when requested (bias reference).
float gsShadowReference(float depth) {
#ifdef GS_SHADOW_FLOOR
    return gsFloorToStep(depth, gsShadowDepthStep);
#else
    return depth;
#endif
}

// Interleaved gradient noise (Jimenez 2014) as a per-pixel rotation angle.
mat2 gsShadowRotation() {
#ifdef GS_SHADOW_ROTATE
    float angle = 6.28318531 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    float s = sin(angle);
    float c = cos(angle);
    return mat2(c, s, -s, c);
#else
    return mat2(1.0);
#endif
}

#ifndef GS_SHADOW_SAMPLER_COMPARE
float gsShadowDepthAt(int slot, vec2 texel) {
    return texture(gsShadowMap[slot], texel * gsShadowTexel[slot].y).r;
}
#endif

float gsShadowVisibility(int lightIndex, vec3 worldPosition, vec3 normal, vec3 toLight) {
    int slot = gsShadowSlot[lightIndex];
    if (slot < 0) {
        return 1.0;
    }
    vec3 position = worldPosition + toLight * gsShadowConstantBias;
#ifdef GS_SHADOW_NORMAL_OFFSET
    // One texel's world size at the receiver: constant for orthographic maps, growing with distance for spots.
    vec4 lightSpace = gsShadowMatrix[slot] * vec4(worldPosition, 1.0);
    float texelSize = gsShadowTexel[slot].w > 0.5 ? gsShadowTexel[slot].z * abs(lightSpace.w) : gsShadowTexel[slot].z;
    position += normal * (gsShadowNormalOffset * texelSize);
#endif
    vec4 clip = gsShadowMatrix[slot] * vec4(position, 1.0);
    // Behind a spot light (w <= 0) nothing is mapped; the cone attenuation is zero there anyway.
    float w = clip.w > 1e-20 ? clip.w : 1e-20;
    vec3 coord = clip.xyz / w;
    vec2 texel = coord.xy * gsShadowTexel[slot].x;
    float depth = coord.z;
    // Screen derivatives must be taken before any per-pixel branch.
#if defined(GS_SHADOW_GRADIENT_SCREEN) || defined(GS_SHADOW_RECEIVER_PLANE)
    vec2 screenGradient = gsReceiverPlaneGradient(dFdxFine(texel), dFdyFine(texel), dFdxFine(depth), dFdyFine(depth));
#endif
    if (clip.w <= 0.0 || depth >= 1.0) {
        return 1.0; // outside the light's depth range: nothing can occlude
    }

    vec2 pointGradient = vec2(0.0);
#if defined(GS_SHADOW_GRADIENT_STORED)
    pointGradient = texture(gsShadowGradientMap[slot], coord.xy).rg;
#elif defined(GS_SHADOW_GRADIENT_CENTRAL)
    pointGradient = 0.5 * vec2(gsShadowDepthAt(slot, texel + vec2(1, 0)) - gsShadowDepthAt(slot, texel - vec2(1, 0)),
                               gsShadowDepthAt(slot, texel + vec2(0, 1)) - gsShadowDepthAt(slot, texel - vec2(0, 1)));
#elif defined(GS_SHADOW_GRADIENT_SCREEN)
    pointGradient = screenGradient;
#endif

    float visibility = 1.0;
    float bias = 0.0;
    float stored = 1.0;

#if defined(GS_SHADOW_SINGLE_COMPARE)
    // Techniques 1, 2, 3, 11: one hardware comparison (the sampler decides NEAREST or 2x2 LINEAR PCF).
    visibility = texture(gsShadowMap[slot], vec3(coord.xy, gsShadowReference(depth)));
    stored = visibility;
#elif defined(GS_SHADOW_PCF)
    mat2 rotation = gsShadowRotation();
    float sum = 0.0;
    for (int i = 0; i < gsTapCount; ++i) {
        vec2 tap = (texel + rotation * gsTapOffsets[i]) * gsShadowTexel[slot].y;
        sum += texture(gsShadowMap[slot], vec3(tap, gsShadowReference(depth)));
    }
    visibility = sum / float(max(gsTapCount, 1));
#elif defined(GS_SHADOW_GSM)
    stored = gsShadowDepthAt(slot, texel);
    visibility = gsFuzzyVisibility(stored, depth, length(pointGradient), gsShadowFuzzyScale, gsShadowDepthStep);
#elif defined(GS_SHADOW_PCF_GSM)
    mat2 rotation = gsShadowRotation();
    float depths[GS_MAX_TAPS];
    for (int i = 0; i < gsTapCount; ++i) {
        depths[i] = gsShadowDepthAt(slot, texel + rotation * gsTapOffsets[i]);
    }
    stored = depths[0];
    // The fits run in the pattern's frame: bring the point gradient into it (rotation is orthonormal).
    vec2 patternGradient = transpose(rotation) * pointGradient;
    int correction = GS_CORRECTION_NONE;
#if defined(GS_SHADOW_CORRECTION_POINT)
    correction = GS_CORRECTION_POINT;
#elif defined(GS_SHADOW_CORRECTION_AVERAGE) && (defined(GS_SHADOW_AVG_CIRCULAR8) || defined(GS_SHADOW_AVG_VEC4))
    // The reference's unrolled forms: the closed-form average gradient then drives the point correction.
    float eight[8];
    for (int i = 0; i < 8; ++i) {
        eight[i] = depths[i];
    }
#if defined(GS_SHADOW_AVG_VEC4)
    patternGradient = gsCircular8GradientVec4(vec4(eight[0], eight[1], eight[2], eight[3]),
                                              vec4(eight[4], eight[5], eight[6], eight[7]), gsTapDisplace);
#else
    patternGradient = gsCircular8Gradient(eight, gsTapDisplace);
#endif
    correction = GS_CORRECTION_POINT;
#elif defined(GS_SHADOW_CORRECTION_AVERAGE)
    correction = GS_CORRECTION_AVERAGE;
#elif defined(GS_SHADOW_CORRECTION_QUADRATIC)
    correction = GS_CORRECTION_QUADRATIC;
#endif
    visibility = gsPcfGsmVisibility(depths, gsTapOffsets, gsTapCount, depth, patternGradient, correction,
                                    gsTapInverseCovariance, gsTapFitRows, gsShadowFuzzyScale, gsShadowDepthStep);
#elif defined(GS_SHADOW_VSM)
    vec2 moments = texture(gsShadowMap[slot], coord.xy).rg;
    visibility = gsChebyshevVisibility(moments, depth, gsShadowMinimumVariance, gsShadowBleedingReduction);
    stored = moments.x;
#elif defined(GS_SHADOW_MSM)
    vec4 moments = texture(gsShadowMap[slot], coord.xy);
#ifdef GS_SHADOW_MSM_QUANTIZED
    moments = gsMsmDequantize(moments, gsShadowMsmDequantize);
#endif
    visibility = gsMsmVisibility(moments, depth, gsShadowMomentBias);
    stored = moments.x;
#elif defined(GS_SHADOW_JITTERED)
    // Soft shadows reference: pairs of stratified offsets from the jitter texture, tiled over the screen. With
    // early-out, the first pairs are test taps; when they agree the pixel is not in a penumbra and the rest are
    // skipped. The result averages every tap actually taken (the reference's pseudo-code divides by the full
    // count either way, which darkens skipped pixels).
    ivec2 tile = ivec2(mod(gl_FragCoord.xy, 32.0));
    float reference = gsShadowReference(depth);
    float lit = 0.0;
    int taken = 0;
    for (int pair = 0; pair < gsJitterPairs; ++pair) {
#ifdef GS_SHADOW_EARLY_OUT
        if (pair == gsEarlyOutPairs && gsTestTapsAgree(lit, float(taken))) {
            break;
        }
#endif
        vec4 offsets = (texelFetch(gsShadowJitter, ivec3(tile, pair), 0) * 2.0 - 1.0) * gsShadowJitterRadius;
        lit += texture(gsShadowMap[slot], vec3((texel + offsets.xy) * gsShadowTexel[slot].y, reference));
        lit += texture(gsShadowMap[slot], vec3((texel + offsets.zw) * gsShadowTexel[slot].y, reference));
        taken += 2;
    }
    visibility = lit / float(max(taken, 1));
    gsDebugFullKernel = taken == 2 * gsJitterPairs;
#elif defined(GS_SHADOW_RECEIVER_PLANE)
    pointGradient = screenGradient;
#if defined(GS_SHADOW_RPB_PER_TAP)
    mat2 rotation = gsShadowRotation();
    float sum = 0.0;
    for (int i = 0; i < gsTapCount; ++i) {
        vec2 centre = floor(texel + rotation * gsTapOffsets[i]) + 0.5;
        float tapDepth = gsReceiverPlaneTapDepth(depth, centre - texel, screenGradient, gsShadowReceiverPlaneClamp);
        sum += texture(gsShadowMap[slot], vec3(centre * gsShadowTexel[slot].y, gsShadowReference(tapDepth)));
    }
    visibility = sum / float(max(gsTapCount, 1));
#else
    // textureGather returns the 2x2 footprint's depths. The reference nudges the coordinate by 1/512 texel so
    // frac() and the gather agree on the footprint; we gather at the footprint's centre instead, which is half a
    // texel from any selection boundary, so the two agree on every implementation's sub-texel precision.
    vec2 footprint = floor(texel - 0.5);
    vec2 weights = texel - 0.5 - footprint;
    vec2 gatherAt = (footprint + 1.0) * gsShadowTexel[slot].y;
    vec4 gathered = textureGather(gsShadowMap[slot], gatherAt);
    // Gather order x (-,+), y (+,+), z (+,-), w (-,-): distances from the pixel to each texel centre.
    vec2 toCentre0 = vec2(-weights.x, 1.0 - weights.y);
    vec2 toCentre1 = vec2(1.0 - weights.x, 1.0 - weights.y);
    vec2 toCentre2 = vec2(1.0 - weights.x, -weights.y);
    vec2 toCentre3 = vec2(-weights.x, -weights.y);
    bool clampBias = gsShadowReceiverPlaneClamp;
    vec4 references = vec4(gsReceiverPlaneTapDepth(depth, toCentre0, screenGradient, clampBias),
                           gsReceiverPlaneTapDepth(depth, toCentre1, screenGradient, clampBias),
                           gsReceiverPlaneTapDepth(depth, toCentre2, screenGradient, clampBias),
                           gsReceiverPlaneTapDepth(depth, toCentre3, screenGradient, clampBias));
    vec4 lit = vec4(gsCompare(gathered.x, gsShadowReference(references.x)),
                    gsCompare(gathered.y, gsShadowReference(references.y)),
                    gsCompare(gathered.z, gsShadowReference(references.z)),
                    gsCompare(gathered.w, gsShadowReference(references.w)));
    visibility = gsBilinear(lit, weights);
    bias = references.w - depth;
    stored = gathered.w;
#endif
#endif

    if (!gsDebugSet) {
        gsDebugSet = true;
        gsDebugVisibility = visibility;
        gsDebugGradient = length(pointGradient);
        gsDebugBias = bias;
        gsDebugStored = stored;
        gsDebugTexel = texel;
    }
    return gsSaturate(visibility);
}

// Debug views replace the shaded colour (final_color slot).
void gsShadowDebug(inout vec3 color) {
#if defined(GS_SHADOW_DEBUG_VISIBILITY)
    color = vec3(gsDebugVisibility);
#elif defined(GS_SHADOW_DEBUG_TEXELS)
    vec2 cell = floor(gsDebugTexel);
    color *= mod(cell.x + cell.y, 2.0) < 0.5 ? 1.0 : 0.6;
#elif defined(GS_SHADOW_DEBUG_GRADIENT)
    // log scale: 1e-7 .. 1e-1 depth per texel maps to black .. white
    color = vec3(clamp((log(max(gsDebugGradient, 1e-12)) / log(10.0) + 7.0) / 6.0, 0.0, 1.0));
#elif defined(GS_SHADOW_DEBUG_BIAS)
    float scaled = gsDebugBias / max(gsShadowDepthStep * 64.0, 1e-7);
    color = vec3(max(scaled, 0.0), max(-scaled, 0.0), 0.0);
#elif defined(GS_SHADOW_DEBUG_MAP)
    color = vec3(gsDebugStored);
#elif defined(GS_SHADOW_DEBUG_KERNEL)
    // Red where the full kernel ran (early-out undecided: a penumbra candidate); visibility in green.
    color = vec3(gsDebugFullKernel ? 1.0 : 0.0, gsDebugVisibility, 0.0);
#endif
}
