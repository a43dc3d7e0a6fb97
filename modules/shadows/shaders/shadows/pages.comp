#version 450 core
// Page marking of the virtual maps: every visible pixel of the view's depth image asks for the pages, at the
// clipmap level (directional lights, gsVirtualLevel) or mip level (spot maps and point lights' faces,
// gsVirtualFaceLevel) whose texels span at most a pixel there, that its lookup and kernel read
// (gsVirtualPageSpan). The requests are bits, one per page of each request level's window, read back by the
// module (ShadowModule::markPages), which also mirrors the level choice on the CPU in its tests. Compiled for one
// kind of light, GS_PAGES_CLIPMAP or GS_PAGES_PERSPECTIVE (PageMarkPrograms).
layout(local_size_x = 8, local_size_y = 8) in;

#define GS_OUT(T) out T
#include "visibility.glsl"

const int GS_REQUEST_LEVELS = 64;

layout(binding = 0) uniform sampler2D uDepth;
uniform ivec2 uSize;
uniform mat4 uClipToWorld;
uniform vec3 uCamera;
uniform int uPageSize;
uniform int uPagesPerSide;
uniform float uReach;
uniform float uTexelPixels; // the m a page's level is chosen for (ShadowSettings::virtualTexelPixels)
#ifdef GS_PAGES_CLIPMAP
uniform mat4 uWorldToLight;
uniform vec3 uToLight;
uniform int uLevelBase;
// First page of each request level's window (ClipmapGeometry::windowOrigin), from the CPU so both agree.
uniform ivec2 uWindowOrigin[GS_REQUEST_LEVELS];
#else
// Spot and point lights: 1 or 6 perspective maps, each world -> shadow texture space, of uFaceLevels mip levels;
// faces not in uFaceMask have no visible receiver. A pixel beyond the light's range or outside a spot's cone
// (uConeCosine, -2 for a point light) gets none of its light and asks nothing.
uniform int uFaces;
uniform int uFaceMask;
uniform int uFaceLevels;
uniform mat4 uFaceToShadow[6];
uniform vec3 uLightPosition;
uniform vec3 uSpotDirection;
uniform float uConeCosine;
uniform float uRange;
uniform float uTexelScale; // a level-0 texel's world size per unit of distance along the face's axis
#endif

layout(std430, binding = 0) buffer GsPageRequests {
    uint requests[];
};

// The position at `texel`, whose depth is `depth`, and 1 in w where the depth image holds a surface there, else
// w 0.
vec4 gsSampleAt(ivec2 texel, float depth) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, uSize))) {
        return vec4(0.0);
    }
    if (!(depth < 1.0 && depth >= 0.0)) { // 1 is the cleared far plane: no surface
        return vec4(0.0);
    }
    vec4 world = uClipToWorld * vec4((vec2(texel) + 0.5) / vec2(uSize) * 2.0 - 1.0, 2.0 * depth - 1.0, 1.0);
    return vec4(world.xyz / world.w, 1.0);
}

// The depths of rows `row` and `row` + 1, columns -1 to 4, of the block at `origin`, three 2x2 texels to each
// vector: x (0, 1), y (1, 1), z (1, 0), w (0, 0) from its lower left texel, as textureGather orders them. Each
// gather's coordinate is the four texels' shared corner, which picks them however it rounds.
void gsGatherRows(ivec2 origin, int row, out vec4 depths0, out vec4 depths1, out vec4 depths2) {
    vec2 inverseSize = 1.0 / vec2(uSize);
    depths0 = textureGather(uDepth, vec2(origin + ivec2(0, row + 1)) * inverseSize);
    depths1 = textureGather(uDepth, vec2(origin + ivec2(2, row + 1)) * inverseSize);
    depths2 = textureGather(uDepth, vec2(origin + ivec2(4, row + 1)) * inverseSize);
}

// The screen derivative of the position at `centre` from its neighbours `behind` and `ahead` (left and right, or
// below and above): the shorter one-sided difference, so a pixel beside a silhouette measures its own surface,
// not the jump to the one behind.
bool gsDerivative(vec4 behind, vec4 centre, vec4 ahead, out vec3 derivative) {
    bool hasForward = ahead.w > 0.0;
    bool hasBackward = behind.w > 0.0;
    if (!hasForward && !hasBackward) {
        return false;
    }
    vec3 forward = ahead.xyz - centre.xyz;
    vec3 backward = centre.xyz - behind.xyz;
    derivative = !hasBackward || (hasForward && dot(forward, forward) <= dot(backward, backward)) ? forward : backward;
    return true;
}

uint gsLastMarked = 0xffffffffu;

void gsMark(int levelIndex, ivec2 page) {
    uint bit = uint(levelIndex) * uint(uPagesPerSide * uPagesPerSide) + uint(page.y * uPagesPerSide + page.x);
    if (bit != gsLastMarked) { // neighbouring pixels ask for the same page: one atomic for a run of them
        gsLastMarked = bit;
        atomicOr(requests[bit >> 5], 1u << (bit & 31u));
    }
}

#ifdef GS_PAGES_PERSPECTIVE
// The pages of a spot map or cube face the pixel at `position` (screen derivatives dPdx, dPdy, facet `normal`)
// reads.
void gsMarkPerspective(vec3 position, vec3 dPdx, vec3 dPdy, vec3 normal, float pixelSize) {
    vec3 toLight = uLightPosition - position;
    float distance = length(toLight);
    if (!(distance > 0.0) || (uRange > 0.0 && distance >= uRange)) {
        return;
    }
    toLight /= distance;
    if (dot(-toLight, uSpotDirection) < uConeCosine) {
        return;
    }
    int face = uFaces == 6 ? gsCubeFace(-toLight) : 0;
    if ((uFaceMask & (1 << face)) == 0) {
        return;
    }
    mat4 m = uFaceToShadow[face];
    vec4 clip = m * vec4(position, 1.0);
    if (!(clip.w > 0.0)) {
        return;
    }
    vec2 coord = clip.xy / clip.w;
    if (any(lessThan(coord, vec2(0.0))) || any(greaterThan(coord, vec2(1.0)))) {
        return;
    }
    // The derivative of the projection (clip.xy / clip.w) in level-0 texels; unlit, by the pixel's size alone.
    float resolution = float(uPageSize * uPagesPerSide);
    vec4 dx = m * vec4(dPdx, 0.0);
    vec4 dy = m * vec4(dPdy, 0.0);
    bool lit = dot(normal, toLight) > 0.0;
    vec2 texelDx = lit ? (dx.xy - coord * dx.w) / clip.w * resolution : vec2(0.0);
    vec2 texelDy = lit ? (dy.xy - coord * dy.w) / clip.w * resolution : vec2(0.0);
    int level = gsVirtualFaceLevel(texelDx, texelDy, pixelSize / (uTexelScale * clip.w), uTexelPixels,
                                   uFaceLevels);
    ivec2 low;
    ivec2 high;
    gsVirtualPageSpan(coord * exp2(-float(level)) * resolution, uReach, float(uPageSize), uPagesPerSide >> level,
                      low, high);
    for (int y = low.y; y <= high.y; ++y) {
        for (int x = low.x; x <= high.x; ++x) {
            gsMark(face * uFaceLevels + level, ivec2(x, y));
        }
    }
}
#else
// The pages of a directional light's clipmap the pixel at `position` (screen derivatives dPdx, dPdy, facet
// `normal`) reads.
void gsMarkClipmap(vec3 position, vec3 dPdx, vec3 dPdy, vec3 normal, float pixelSize) {
    mat3 toLight = mat3(uWorldToLight);
    bool lit = dot(normal, uToLight) > 0.0;
    float unitFootprint = lit ? gsTexelFootprintPixels((toLight * dPdx).xy, (toLight * dPdy).xy) : 0.0;
    // m grows with the texel: a texel uTexelPixels times as large spans uTexelPixels times the pixels.
    int level = gsVirtualLevel(unitFootprint / uTexelPixels, pixelSize * uTexelPixels, uLevelBase,
                               GS_REQUEST_LEVELS) -
                uLevelBase;
    vec2 light = (uWorldToLight * vec4(position, 1.0)).xy;
    // The finest level at or above the one asked for whose window holds the lookup and its reach.
    float windowTexels = float(uPageSize * uPagesPerSide);
    for (; level < GS_REQUEST_LEVELS; ++level) {
        // In floats: a clamped window origin of a level far too fine (ClipmapGeometry::windowOrigin) times
        // the page size may not fit an int.
        vec2 window = light * exp2(-float(uLevelBase + level)) - vec2(uWindowOrigin[level]) * float(uPageSize);
        if (all(greaterThanEqual(window, vec2(uReach))) && all(lessThan(window, vec2(windowTexels - uReach)))) {
            ivec2 low;
            ivec2 high;
            gsVirtualPageSpan(window, uReach, float(uPageSize), uPagesPerSide, low, high);
            for (int y = low.y; y <= high.y; ++y) {
                for (int x = low.x; x <= high.x; ++x) {
                    gsMark(level, ivec2(x, y));
                }
            }
            break;
        }
    }
}
#endif

// Marks the pages the pixel at `centre` asks for, from its four neighbours (w: 1 where a surface is).
void gsMarkPixel(vec4 centre, vec4 left, vec4 right, vec4 below, vec4 above) {
    vec3 dPdx;
    vec3 dPdy;
    if (!(centre.w > 0.0) || !gsDerivative(left, centre, right, dPdx) || !gsDerivative(below, centre, above, dPdy)) {
        return;
    }
    vec3 position = centre.xyz;
    // The facet, turned towards the camera: lit where it faces the light too.
    vec3 normal = cross(dPdx, dPdy);
    normal = dot(normal, uCamera - position) < 0.0 ? -normal : normal;
    float pixelSize = sqrt(min(dot(dPdx, dPdx), dot(dPdy, dPdy)));
#ifdef GS_PAGES_PERSPECTIVE
    gsMarkPerspective(position, dPdx, dPdy, normal, pixelSize);
#else
    gsMarkClipmap(position, dPdx, dPdy, normal, pixelSize);
#endif
}

// The positions of columns -1 to 4 of row `row` of the block at `origin`, from the gathers of the two rows it
// belongs to (`upper`: it is their second). Without `ends`, columns -1 and 4 are left out (w 0).
void gsSampleRow(ivec2 origin, int row, vec4 depths0, vec4 depths1, vec4 depths2, bool upper, bool ends,
                 out vec4 column0, out vec4 column1, out vec4 column2, out vec4 column3, out vec4 column4,
                 out vec4 column5) {
    column0 = ends ? gsSampleAt(origin + ivec2(-1, row), upper ? depths0.x : depths0.w) : vec4(0.0);
    column1 = gsSampleAt(origin + ivec2(0, row), upper ? depths0.y : depths0.z);
    column2 = gsSampleAt(origin + ivec2(1, row), upper ? depths1.x : depths1.w);
    column3 = gsSampleAt(origin + ivec2(2, row), upper ? depths1.y : depths1.z);
    column4 = gsSampleAt(origin + ivec2(3, row), upper ? depths2.x : depths2.w);
    column5 = ends ? gsSampleAt(origin + ivec2(4, row), upper ? depths2.y : depths2.z) : vec4(0.0);
}

// Marks the current row's four pixels (columns 0 to 3 of `at`), then moves up: `at` becomes the row below and
// `above` the current row.
void gsMarkRow(inout vec4 below1, inout vec4 below2, inout vec4 below3, inout vec4 below4, inout vec4 at0,
               inout vec4 at1, inout vec4 at2, inout vec4 at3, inout vec4 at4, inout vec4 at5, vec4 above0,
               vec4 above1, vec4 above2, vec4 above3, vec4 above4, vec4 above5) {
    gsMarkPixel(at1, at0, at2, below1, above1);
    gsMarkPixel(at2, at1, at3, below2, above2);
    gsMarkPixel(at3, at2, at4, below3, above3);
    gsMarkPixel(at4, at3, at5, below4, above4);
    below1 = at1;
    below2 = at2;
    below3 = at3;
    below4 = at4;
    at0 = above0;
    at1 = above1;
    at2 = above2;
    at3 = above3;
    at4 = above4;
    at5 = above5;
}

// Each invocation marks a block of 4x4 pixels (neighbours mostly ask for the same page, so one atomic serves a run
// of them), row by row, holding the rows below, at and above in registers: every position of the block and its
// border is reconstructed once, not once for each pixel that reads it, and no array is indexed (a software
// rasteriser keeps an invocation's indexed arrays in memory). The depths come two rows at a time by 2x2 gathers,
// a quarter of the fetches of one texel each, and the rows are written out rather than looped over: on llvmpipe
// each made the marking markedly cheaper (docs/SHADOWS.md, "Virtual maps"). VirtualShadowMaps dispatches groups
// of 8x8.
void main() {
    ivec2 origin = ivec2(gl_GlobalInvocationID.xy) * 4;
    vec4 depths0, depths1, depths2;
    // Rows -1 and 0: the row below the first needs only columns 0-3.
    gsGatherRows(origin, -1, depths0, depths1, depths2);
    vec4 unused, below1, below2, below3, below4;
    gsSampleRow(origin, -1, depths0, depths1, depths2, false, false, unused, below1, below2, below3, below4, unused);
    vec4 at0, at1, at2, at3, at4, at5;
    gsSampleRow(origin, 0, depths0, depths1, depths2, true, true, at0, at1, at2, at3, at4, at5);
    // Rows 1 to 4, each the row above the current one; the block's top border, row 4, needs no ends.
    vec4 above0, above1, above2, above3, above4, above5;
    gsGatherRows(origin, 1, depths0, depths1, depths2);
    gsSampleRow(origin, 1, depths0, depths1, depths2, false, true, above0, above1, above2, above3, above4, above5);
    gsMarkRow(below1, below2, below3, below4, at0, at1, at2, at3, at4, at5, above0, above1, above2, above3, above4,
              above5);
    gsSampleRow(origin, 2, depths0, depths1, depths2, true, true, above0, above1, above2, above3, above4, above5);
    gsMarkRow(below1, below2, below3, below4, at0, at1, at2, at3, at4, at5, above0, above1, above2, above3, above4,
              above5);
    gsGatherRows(origin, 3, depths0, depths1, depths2);
    gsSampleRow(origin, 3, depths0, depths1, depths2, false, true, above0, above1, above2, above3, above4, above5);
    gsMarkRow(below1, below2, below3, below4, at0, at1, at2, at3, at4, at5, above0, above1, above2, above3, above4,
              above5);
    gsSampleRow(origin, 4, depths0, depths1, depths2, true, false, above0, above1, above2, above3, above4, above5);
    gsMarkRow(below1, below2, below3, below4, at0, at1, at2, at3, at4, at5, above0, above1, above2, above3, above4,
              above5);
}
