// Shadow visibility in the lighting pass (forward.frag "declarations" slot). One variant per technique and
// option: the GS_SHADOW_* defines come from the shadow module's variant bits, so only what a scene uses compiles.
// The common part projects the receiver into the light's map (GsShadowLookup); the technique's function
// gsShadowSample_<Technique> (shaders/shadows/techniques/, each guarded by its own define, which also defines
// gsShadowSample to it) turns that into visibility and the debug views' values.
#define GS_OUT(T) out T
#include "visibility.glsl"

#include "block.glsl"

#ifdef GS_SHADOW_SAMPLER_COMPARE
uniform sampler2DShadow gsShadowMap[GS_SHADOW_MAX_MAPS];
#else
uniform sampler2D gsShadowMap[GS_SHADOW_MAX_MAPS];
#endif
#ifdef GS_SHADOW_GRADIENT_STORED
uniform sampler2D gsShadowGradientMap[GS_SHADOW_MAX_MAPS];
#endif
uniform vec2 gsTapOffsets[GS_MAX_TAPS];
uniform float gsTapFitRows[6 * GS_MAX_TAPS];

// Where a receiver lands in its light's map.
struct GsShadowLookup {
    int slot;
    vec2 coord;          // shadow texture coordinates
    vec2 texel;          // the same in texels
    float depth;         // receiver depth in the map's [0,1] range
    float momentDepth;   // the same as the moments store it (gsLinearDepth)
    vec2 pointGradient;  // the fragment's depth gradient per texel (GS_SHADOW_GRADIENT_*), else zero
    vec2 screenGradient; // receiver plane from screen derivatives, where a technique needs it
    vec2 tangentGradient; // depth per texel of the receiver's tangent plane (GS_SHADOW_TANGENT_PLANE), else zero
};

// What a technique returns: visibility, and what the debug views show.
struct GsShadowSample {
    float visibility;
    float stored;     // stored depth (or first moment) under the fragment
    float bias;       // receiver-plane bias
    vec2 gradient;    // the gradient the technique used
    bool fullKernel;  // jittered PCF took every tap
};

GsShadowSample gsShadowResult(float visibility, float stored, GsShadowLookup lookup) {
    return GsShadowSample(visibility, stored, 0.0, lookup.pointGradient, false);
}

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

// Every technique file (the module lists them when it registers its shaders), each compiled only under its
// own define.
#include "techniques.glsl"

float gsShadowVisibility(int lightIndex, vec3 worldPosition, vec3 normal, vec3 toLight) {
    GsShadowLookup lookup;
    lookup.slot = gsShadowSlots[lightIndex / 4][lightIndex % 4];
    int slot = lookup.slot;
    if (slot < 0) {
        return 1.0;
    }
    // One texel's world size at the receiver: constant for orthographic maps, growing with the distance along
    // the axis (clip w, whose row is the matrix's last) for spots. Biases are in these units, so one value holds
    // at any scene scale and map size.
    mat4 m = gsShadowMatrix[slot];
    vec4 wRow = vec4(m[0][3], m[1][3], m[2][3], m[3][3]);
    bool perspective = gsShadowTexel[slot].w > 0.5;
    float texelSize = gsShadowTexel[slot].z * (perspective ? abs(dot(wRow, vec4(worldPosition, 1.0))) : 1.0);
    vec3 position = worldPosition + toLight * (gsShadowConstantBiasTexels * texelSize);
#ifdef GS_SHADOW_NORMAL_OFFSET
    // A perspective map measures depth along its axis, so a receiver facing the light but not the axis still
    // slopes in depth there: offset for the steeper of the two angles.
    float cosine = abs(dot(normal, toLight));
    if (perspective) {
        cosine = min(cosine, abs(dot(normal, normalize(vec3(wRow)))));
    }
    position += normal * gsNormalOffset(gsShadowNormalOffset * texelSize, cosine);
#endif
    vec4 clip = m * vec4(position, 1.0);
    // Behind a spot light (w <= 0) nothing is mapped; the cone attenuation is zero there anyway.
    float w = clip.w > 1e-20 ? clip.w : 1e-20;
    vec3 coord = clip.xyz / w;
    lookup.coord = coord.xy;
    lookup.texel = coord.xy * gsShadowTexel[slot].x;
    lookup.depth = coord.z - gsShadowDepthBias;
    lookup.momentDepth = gsLinearDepth(lookup.depth, gsShadowDepthRange[slot].xy);
    // Screen derivatives must be taken before any per-pixel branch.
    lookup.screenGradient = vec2(0.0);
#if defined(GS_SHADOW_GRADIENT_SCREEN) || defined(GS_SHADOW_RECEIVER_PLANE)
    lookup.screenGradient = gsReceiverPlaneGradient(dFdxFine(lookup.texel), dFdyFine(lookup.texel),
                                                    dFdxFine(lookup.depth), dFdyFine(lookup.depth));
#endif
#ifdef GS_SHADOW_TANGENT_PLANE
    // The facet's own plane (derivatives of the interpolated position stay within one triangle), not the
    // interpolated normal, which bends across creases: the depths in the map come from facets.
    vec3 facetNormal = cross(dFdxFine(worldPosition), dFdyFine(worldPosition));
    facetNormal = dot(facetNormal, normal) < 0.0 ? -facetNormal : facetNormal;
#endif
    if (clip.w <= 0.0 || lookup.depth >= 1.0) {
        return 1.0; // outside the light's depth range: nothing can occlude
    }

    lookup.tangentGradient = vec2(0.0);
#ifdef GS_SHADOW_TANGENT_PLANE
    lookup.tangentGradient =
        gsTangentPlaneGradient(m, worldPosition, facetNormal, gsShadowTexel[slot].x);
#endif
    lookup.pointGradient = vec2(0.0);
#if defined(GS_SHADOW_GRADIENT_STORED)
    lookup.pointGradient = texture(gsShadowGradientMap[slot], lookup.coord).rg;
#elif defined(GS_SHADOW_GRADIENT_CENTRAL)
    vec2 texel = lookup.texel;
    lookup.pointGradient =
        0.5 * vec2(gsShadowDepthAt(slot, texel + vec2(1, 0)) - gsShadowDepthAt(slot, texel - vec2(1, 0)),
                   gsShadowDepthAt(slot, texel + vec2(0, 1)) - gsShadowDepthAt(slot, texel - vec2(0, 1)));
#elif defined(GS_SHADOW_GRADIENT_SCREEN)
    lookup.pointGradient = lookup.screenGradient;
#endif

    GsShadowSample result = gsShadowSample(lookup);
    gsDebugFullKernel = result.fullKernel;
    if (!gsDebugSet) {
        gsDebugSet = true;
        gsDebugVisibility = result.visibility;
        gsDebugGradient = length(result.gradient);
        gsDebugBias = result.bias;
        gsDebugStored = result.stored;
        gsDebugTexel = lookup.texel;
    }
    return gsSaturate(result.visibility);
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
