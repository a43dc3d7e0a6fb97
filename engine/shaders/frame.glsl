// Per-frame data shared by every lighting-pass shader. Layout mirrors ForwardRenderer's FrameBlock (std140).
#ifndef GS_MAX_LIGHTS
#define GS_MAX_LIGHTS 8
#endif

const int GS_LIGHT_DIRECTIONAL = 0;
const int GS_LIGHT_SPOT = 1;

struct GsLight {
    vec4 colorIntensity; // rgb linear colour, a intensity
    vec4 position;       // xyz world position, w light type
    vec4 direction;      // xyz unit direction the light shines along
    vec4 spot;           // x cos(inner), y cos(outer), z range (0 = unlimited)
};

layout(std140, binding = 0) uniform FrameBlock {
    mat4 gsViewProjection;
    vec4 gsCameraPosition;
    vec4 gsAmbient;    // rgb ambient colour (linear)
    ivec4 gsLightCount; // x: number of lights in use
    GsLight gsLights[GS_MAX_LIGHTS];
};
