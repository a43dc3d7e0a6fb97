// Per-frame data shared by every lighting-pass shader. Layout mirrors ForwardRenderer's FrameBlock (std140).
#ifndef GS_MAX_LIGHTS
#define GS_MAX_LIGHTS 8
#endif

// The number of lights is part of the variant (GS_LIGHT_COUNT_BIT0..3, binary), so lighting loops have a
// constant trip count: llvmpipe runs a dynamically bounded loop over a dynamically indexed block 2-3x slower.
#ifdef GS_LIGHT_COUNT_BIT0
#define GS_LIGHT_COUNT_1 1
#else
#define GS_LIGHT_COUNT_1 0
#endif
#ifdef GS_LIGHT_COUNT_BIT1
#define GS_LIGHT_COUNT_2 2
#else
#define GS_LIGHT_COUNT_2 0
#endif
#ifdef GS_LIGHT_COUNT_BIT2
#define GS_LIGHT_COUNT_4 4
#else
#define GS_LIGHT_COUNT_4 0
#endif
#ifdef GS_LIGHT_COUNT_BIT3
#define GS_LIGHT_COUNT_8 8
#else
#define GS_LIGHT_COUNT_8 0
#endif
#define GS_LIGHT_COUNT (GS_LIGHT_COUNT_1 + GS_LIGHT_COUNT_2 + GS_LIGHT_COUNT_4 + GS_LIGHT_COUNT_8)

const int GS_LIGHT_DIRECTIONAL = 0;
const int GS_LIGHT_SPOT = 1;
const int GS_LIGHT_POINT = 2;

struct GsLight {
    vec4 colorIntensity; // rgb linear colour, a intensity
    vec4 position;       // xyz world position (spot and point), w light type (GS_LIGHT_*)
    vec4 direction;      // xyz unit direction the light shines along (directional and spot)
    vec4 spot;           // x cos(inner), y cos(outer) (spot); z range (spot and point; 0 = unlimited)
};

layout(std140, binding = 0) uniform FrameBlock {
    mat4 gsViewProjection;
    vec4 gsCameraPosition;
    vec4 gsAmbient;    // rgb ambient colour (linear)
    ivec4 gsLightCount; // x: number of lights in use
    GsLight gsLights[GS_MAX_LIGHTS];
};
