// The shadow module's per-frame scalars, read by the lighting pass and by the shadow pass (the technique's
// parameters). Mirrors ShadowBlock (modules/shadows/src/ShadowBlock.h); binding 0 is the engine's FrameBlock,
// whose GS_MAX_LIGHTS (frame.glsl) sizes the light slots.
const int GS_SHADOW_MAX_MAPS = 48;

// How a light's maps are laid out (LightMapsKind).
const int GS_SHADOW_LIGHT_NONE = 0;
const int GS_SHADOW_LIGHT_SINGLE = 1;
const int GS_SHADOW_LIGHT_CASCADES = 2;
const int GS_SHADOW_LIGHT_CUBE = 3;
const int GS_SHADOW_LIGHT_VIRTUAL = 4;
const int GS_SHADOW_LIGHT_VIRTUAL_FACES = 5;

struct GsShadowLightMaps {
    ivec4 kind;      // x: GS_SHADOW_LIGHT_*, y: cascade count, clipmap or mip levels; CASCADES: z first drawn
                     // cascade's slot; VIRTUAL: z first level's slot, w its page-table layer; VIRTUAL_FACES: z 1
                     // (spot) or 6 (cube), w first face's layer
    ivec4 slots;     // map slot of the single map (x), of each cascade, or of cube faces 0-3; -1: none
    ivec4 faceSlots; // cube faces 4, 5 (xy)
    vec4 splitNear;  // cascades: view depth each starts at
    vec4 splitFar;   // cascades: view depth each ends at
};

layout(std140, binding = 1) uniform GsShadowBlock {
    mat4 gsShadowMatrix[GS_SHADOW_MAX_MAPS];    // world -> shadow texture space (divide by w)
    vec4 gsShadowTexel[GS_SHADOW_MAX_MAPS];     // x resolution, y 1/resolution, z texel scale, w perspective
    vec4 gsShadowDepthRange[GS_SHADOW_MAX_MAPS]; // xy near, far of a perspective map (zero for orthographic);
                                                 // z the lit border in texels (LightProjection); w the light's
                                                 // size (tan of a sun's angular radius, a local light's radius)
    GsShadowLightMaps gsShadowLights[GS_MAX_LIGHTS];
    vec4 gsShadowViewDepth;                     // view depth of p = dot(gsShadowViewDepth, vec4(p, 1))
    mat4 gsShadowMsmDequantize;                 // MSM 16-bit: inverse of the optimised basis
    mat2 gsTapInverseCovariance;
    vec4 gsShadowTechniqueParameters;           // the technique's own (ShadowTechniqueTraits::shaderParameters)
    float gsShadowConstantBiasTexels;           // texel sizes towards the light
    float gsShadowDepthStep;                    // depth format step (0 for float)
    float gsShadowFuzzyScale;                   // GSM band width in texels
    float gsShadowNormalOffset;                 // texel sizes along the normal, times sin(normal, light)
    float gsShadowMinimumVariance;              // VSM
    float gsShadowBleedingReduction;            // VSM
    float gsShadowMomentBias;                   // MSM
    float gsShadowJitterRadius;                 // texels
    int gsShadowReceiverPlaneClamp;
    int gsJitterPairs;
    int gsEarlyOutPairs;                        // 0: always the full kernel
    int gsTapCount;
    float gsTapDisplace;                        // circular-8 d, texels
    float gsShadowDepthBias;                    // depth units the comparison depth is lowered by
    float gsShadowCascadeBlend;                 // fraction of a cascade's span blended into the next
    float gsShadowDepthBiasFloor;               // the depth bias's arithmetic floor, orthographic depth units
    ivec4 gsVirtualPages; // x pages per side of a level, y atlas tiles per row, z atlas side (texels)
    vec4 gsVirtualPage;   // x page side, y tile side, z border (texels), w 1 / atlas side
    vec4 gsShadowSoftReachTexels[GS_SHADOW_MAX_MAPS / 4]; // the soft techniques' widest radius per map, four a vector
    // A cascade's or clipmap level's map coordinates from its light's first cascade's or finest level's,
    // coord = first * scale + offset (xyz): they share the light's rotation, so the vertex stage projects into
    // the first alone.
    vec4 gsShadowCascadeScale[GS_SHADOW_MAX_MAPS];
    vec4 gsShadowCascadeOffset[GS_SHADOW_MAX_MAPS];
};

