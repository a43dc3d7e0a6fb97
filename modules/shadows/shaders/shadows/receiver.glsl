// Shadow visibility in the lighting pass (forward.frag "declarations" slot). One variant per technique and
// option: the GS_SHADOW_* defines come from the shadow module's variant bits, so only what a scene uses compiles.
// The common part projects the receiver into the light's map (GsShadowLookup); the technique's function
// gsShadowSample_<Technique> (shaders/shadows/techniques/, each guarded by its own define, which also defines
// gsShadowSample to it) turns that into visibility and the debug views' values.
#define GS_OUT(T) out T
#include "visibility.glsl"

#include "block.glsl"
#include "vertex-projection.glsl"

#ifdef GS_SHADOW_VERTEX_PROJECTION
in vec4 vGsShadowClip[GS_LIGHT_COUNT]; // vertex.glsl
#endif

// Whether a debug view replaces the shaded colour.
#if defined(GS_SHADOW_DEBUG_TEXELS) || defined(GS_SHADOW_DEBUG_GRADIENT) || defined(GS_SHADOW_DEBUG_BIAS)
#define GS_SHADOW_DEBUG_VIEW
#elif defined(GS_SHADOW_DEBUG_VISIBILITY) || defined(GS_SHADOW_DEBUG_MAP) || defined(GS_SHADOW_DEBUG_KERNEL)
#define GS_SHADOW_DEBUG_VIEW
#elif defined(GS_SHADOW_DEBUG_MAPS) || defined(GS_SHADOW_DEBUG_DENSITY)
#define GS_SHADOW_DEBUG_VIEW
#elif defined(GS_SHADOW_DEBUG_PAGES) || defined(GS_SHADOW_DEBUG_SLOT)
#define GS_SHADOW_DEBUG_VIEW
#endif

// GS_SHADOW_KEEP_PERSPECTIVE exists for the test that shows the orthographic variant changes no image: the
// generic lookups then run on orthographic maps too.
#ifdef GS_SHADOW_KEEP_PERSPECTIVE
#undef GS_SHADOW_ORTHOGRAPHIC
#endif

// Every map of the frame is a layer (its slot) of one array: a fragment may pick its cascade or cube face
// itself, which a sampler array would not allow (its index must be uniform).
#ifdef GS_SHADOW_SAMPLER_COMPARE
uniform sampler2DArrayShadow gsShadowMaps;
#else
uniform sampler2DArray gsShadowMaps;
#endif
#ifdef GS_SHADOW_GRADIENT_STORED
uniform sampler2DArray gsShadowGradientMaps;
#endif
uniform vec2 gsTapOffsets[GS_MAX_TAPS];
uniform float gsTapFitRows[6 * GS_MAX_TAPS];

// Where a receiver lands in one shadow map.
struct GsShadowLookup {
    int slot;            // the map (its projection in the block)
    int layer;           // the layer of gsShadowMaps its texels are in (the slot's, or a virtual page's)
    float inverseSize;   // texel coordinates -> texture coordinates of that layer
    vec2 coord;          // shadow texture coordinates
    vec2 texel;          // the coordinates in texels
    float depth;         // receiver depth in the map's [0,1] range
    float momentDepth;   // the same as the moments store it (gsLinearDepth)
    vec2 pointGradient;  // the fragment's depth gradient per texel (GS_SHADOW_GRADIENT_*), else zero
    vec2 screenGradient; // receiver plane from screen derivatives, where a technique needs it
    vec2 tangentGradient; // depth per texel of the receiver's tangent plane (GS_SHADOW_TANGENT_PLANE), else zero
    float texelWorld;    // a texel's world size at the receiver (of the level read)
    bool perspective;    // a spot map or cube face: depths from the light (near, far in gsShadowDepthRange)
    float depthScale;    // an orthographic map's stored depth per world unit along the light
    float lightSize;     // the light's size (ShadowModule: tan of a sun's angular radius, a local light's radius)
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

// A stored depth as a distance, for the soft shadows' similar triangles: from the light for a perspective map,
// along the light for an orthographic one.
float gsShadowDistance(GsShadowLookup lookup, float depth) {
    if (lookup.perspective) {
        vec2 range = gsShadowDepthRange[lookup.slot].xy;
        return range.x * range.y / max(range.y - depth * (range.y - range.x), range.x * 1e-6);
    }
    return depth / max(lookup.depthScale, 1e-30);
}

// The soft techniques' penumbra radius in the texels of the lookup's map (gsPcssRadius's, from the receiver's and
// the blocker's distances), up to `limitTexels`.
float gsSoftRadiusTexels(GsShadowLookup lookup, float receiver, float blocker, float limitTexels) {
    return gsPcssRadius(receiver, blocker, lookup.lightSize, lookup.perspective, limitTexels * lookup.texelWorld) /
           max(lookup.texelWorld, 1e-30);
}

// What the debug views show: the values of the first shadowed light of this fragment.
float gsDebugVisibility = 1.0;
float gsDebugGradient = 0.0;
float gsDebugBias = 0.0;
float gsDebugStored = 1.0;
vec2 gsDebugTexel = vec2(0.0);
float gsDebugDensity = -1.0; // Lloyd's m (gsTexelFootprintPixels); -1 where no map was read
int gsDebugSlot = -1;
int gsDebugPageLevel = -1;     // virtual maps: the clipmap level read
float gsDebugPageEdge = -1.0;  // virtual maps: texels from the lookup to its page's nearest edge
bool gsDebugPageBorder = false; // within a texel of its page's edge
bool gsDebugPageDrawn = false;  // the page was drawn this frame
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

#ifdef GS_SHADOW_SAMPLER_COMPARE
// The map's hardware comparison at `coord` (its sampler decides NEAREST or 2x2 LINEAR PCF).
float gsShadowCompare(GsShadowLookup lookup, vec2 coord, float reference) {
    return texture(gsShadowMaps, vec4(coord, float(lookup.layer), reference));
}
#else
float gsShadowDepthAt(GsShadowLookup lookup, vec2 texel) {
    return texture(gsShadowMaps, vec3(texel * lookup.inverseSize, float(lookup.layer))).r;
}

// The 2x2 depths around `coord` (textureGather order).
vec4 gsShadowGather(GsShadowLookup lookup, vec2 coord) {
    return textureGather(gsShadowMaps, vec3(coord, float(lookup.layer)));
}

// The 2x2 texels around `texel`, each compared at the depth of the receiver's plane of slope `gradient` (depth
// per texel) at that texel centre's offset from the receiver (gsReceiverPlaneTapDepth), blended bilinearly.
// `stored` and `reference` return the (-,-) texel's depth and the depth it was compared at.
float gsPlaneCompareBilinear(GsShadowLookup lookup, vec2 texel, vec2 gradient, bool clampToLit, out float stored,
                             out float reference) {
    // textureGather returns the 2x2 footprint's depths. The reference nudges the coordinate by 1/512 texel so
    // frac() and the gather agree on the footprint; we gather at the footprint's centre instead, which is half a
    // texel from any selection boundary, so the two agree on every implementation's sub-texel precision.
    vec2 footprint = floor(texel - 0.5);
    vec2 weights = texel - 0.5 - footprint;
    vec4 gathered = gsShadowGather(lookup, (footprint + 1.0) * lookup.inverseSize);
    // Gather order x (-,+), y (+,+), z (+,-), w (-,-): each texel centre's offset from the receiver.
    vec2 offset = texel - lookup.texel;
    vec4 references =
        vec4(gsReceiverPlaneTapDepth(lookup.depth, offset + vec2(-weights.x, 1.0 - weights.y), gradient, clampToLit),
             gsReceiverPlaneTapDepth(lookup.depth, offset + vec2(1.0 - weights.x, 1.0 - weights.y), gradient,
                                     clampToLit),
             gsReceiverPlaneTapDepth(lookup.depth, offset + vec2(1.0 - weights.x, -weights.y), gradient, clampToLit),
             gsReceiverPlaneTapDepth(lookup.depth, offset + vec2(-weights.x, -weights.y), gradient, clampToLit));
    vec4 lit = vec4(gsCompare(gathered.x, gsShadowReference(references.x)),
                    gsCompare(gathered.y, gsShadowReference(references.y)),
                    gsCompare(gathered.z, gsShadowReference(references.z)),
                    gsCompare(gathered.w, gsShadowReference(references.w)));
    stored = gathered.w;
    reference = references.w;
    return gsBilinear(lit, weights);
}

// Filtered moments under the lookup: bilinear at the one level the map has. The blur, where asked for, has
// filtered them over its width; a mip level as wide as the lookup's footprint mixes a caster's moments into
// receivers beside its shadow, which Chebyshev's and Hamburger's bounds read as partial occlusion or light. With
// the footprint capped at 2 texels `terrain` under a 1-5° sun still leaked (`vsm` 58 pixels in 4 of 126 Defaults
// views, `msm` 30 in 3), uncapped the spheres' lit ground darkened 3.7e-4; at one texel, where no level but the
// first is read, none (docs/SHADOWS.md, "No mip chain for the moments").
vec4 gsShadowMoments(GsShadowLookup lookup) {
    return textureLod(gsShadowMaps, vec3(lookup.coord, float(lookup.layer)), 0.0);
}

// The moments filtered over a `width`-texel footprint from their mip chain, for the soft shadows that ask for
// that width (ShadowPlan::momentLevels): trilinear between the levels around log2(width).
vec4 gsShadowMomentsOver(GsShadowLookup lookup, float width) {
    return textureLod(gsShadowMaps, vec3(lookup.coord, float(lookup.layer)), log2(max(width, 1.0)));
}
#endif

// Every technique file (the module lists them when it registers its shaders), each compiled only under its
// own define.
#include "techniques.glsl"

// The image of a clip-space offset `dClip` at `clip` in map coordinates and depth: the derivative of the
// projection (clip.xyz / clip.w), exact for perspective maps too.
vec3 gsShadowDerivative(vec4 clip, vec4 dClip) {
#ifdef GS_SHADOW_ORTHOGRAPHIC
    return dClip.xyz; // w is 1 and its derivative 0
#else
    return (dClip.xyz - clip.xyz * (dClip.w / clip.w)) / clip.w;
#endif
}

// The screen derivatives a fragment's lookups need, taken once before any per-fragment choice of map.
struct GsShadowFragment {
    vec3 position;
    vec3 normal; // the facet's (gsFacetNormal)
    vec3 toLight;
    vec3 dPdx; // world position per pixel
    vec3 dPdy;
};

// A receiver's unbiased position in one map's clip space, and its screen derivatives.
struct GsShadowProjection {
    vec4 clip;
    vec4 dx; // per pixel
    vec4 dy;
};

GsShadowProjection gsShadowProjectFragment(int slot, GsShadowFragment fragment) {
    mat4 m = gsShadowMatrix[slot];
    return GsShadowProjection(m * vec4(fragment.position, 1.0), m * vec4(fragment.dPdx, 0.0),
                              m * vec4(fragment.dPdy, 0.0));
}

// A cascade's projection from its light's first cascade's (orthographic: w is 1, its derivatives 0).
GsShadowProjection gsShadowCascadeProjection(int slot, GsShadowProjection first) {
    vec3 scale = gsShadowCascadeScale[slot].xyz;
    return GsShadowProjection(vec4(first.clip.xyz * scale + gsShadowCascadeOffset[slot].xyz, 1.0),
                              vec4(first.dx.xyz * scale, 0.0), vec4(first.dy.xyz * scale, 0.0));
}

#if defined(GS_SHADOW_LAYOUT_VIRTUAL) || defined(GS_SHADOW_LAYOUT_VIRTUAL_FACES)
#define GS_SHADOW_VIRTUAL_PAGES
// Virtual maps (ShadowModule, docs/SHADOWS.md "Virtual maps"): every resident page is a tile of the atlas that
// gsShadowMaps then is, found through the light's page table. A directional light's clipmap has a slot per
// level and a page-table layer per level; a spot map or cube face has one slot and one layer, its levels the
// layer's mip levels. While gsShadowMapVisibility reads a level, gsVirtualPageLayer and gsVirtualTableLevel
// name its table, gsVirtualLevelIndex the level, and gsVirtualLevelScale its texels per level-0 texel (1 for a
// clipmap, whose level slots carry their own sizes). When the receiver's page holds no texels of the level it
// returns -1 and names the level that does (gsVirtualNextLevel).
uniform usampler2DArray gsShadowPageTable;
int gsVirtualPageLayer = -1;
int gsVirtualTableLevel = 0;
int gsVirtualLevelIndex = 0;
float gsVirtualLevelScale = 1.0;
bool gsVirtualFaceMaps = false; // outside a perspective map nothing is mapped, no coarser level holds it
int gsVirtualNextLevel = 0;

// The page under window texel `window` of a level, and the level index a page-table entry names
// (pageTableEntry: bits 24-29).
ivec2 gsVirtualPageAt(vec2 window) { return ivec2(floor(window / gsVirtualPage.x)); }
int gsVirtualEntryLevel(uint entry) { return int((entry >> 24) & 63u); }
#endif

// Visibility of the fragment in map `slot` (drawn), where it projects to `projected`.
float gsShadowMapVisibilityAt(int slot, GsShadowFragment fragment, GsShadowProjection projected) {
    GsShadowLookup lookup;
    lookup.slot = slot;
    lookup.layer = slot;
    lookup.inverseSize = gsShadowTexel[slot].y;
    // One texel's world size at the receiver: constant for orthographic maps, growing with the distance along
    // the axis (clip w) for perspective ones. Biases are in these units, so one value holds at any scene scale,
    // map size and cascade.
    mat4 m = gsShadowMatrix[slot];
    // Texels per side, and a texel's world size (per unit of distance in a perspective map), of the level read.
    float resolution = gsShadowTexel[slot].x;
    float texelScale = gsShadowTexel[slot].z;
#ifdef GS_SHADOW_VIRTUAL_PAGES
    if (gsVirtualPageLayer >= 0) {
        resolution *= gsVirtualLevelScale;
        texelScale /= gsVirtualLevelScale;
    }
#endif
#ifdef GS_SHADOW_ORTHOGRAPHIC
    // Every map of the frame is orthographic (ShadowModule::layoutKey): their matrices' last row is exactly
    // (0, 0, 0, 1), so clip w is exactly 1 and the perspective terms drop out of the variant.
    const bool perspective = false;
#else
    bool perspective = gsShadowTexel[slot].w > 0.5;
#endif
    float texelSize = texelScale * (perspective ? abs(projected.clip.w) : 1.0);
    lookup.depthScale = length(vec3(m[0][2], m[1][2], m[2][2]));
    // The receiver moves towards the light and, with a normal offset, along its normal: in clip space, the
    // images of those offsets.
    float towardsLight = gsShadowConstantBiasTexels * texelSize;
#ifdef GS_SHADOW_NORMAL_OFFSET
    // A perspective map measures depth along its axis, so a receiver facing the light but not the axis still
    // slopes in depth there: offset for the steeper of the two angles.
    float cosine = abs(dot(fragment.normal, fragment.toLight));
    if (perspective) {
        cosine = min(cosine, abs(dot(fragment.normal, normalize(vec3(m[0][3], m[1][3], m[2][3])))));
    }
    vec3 alongNormal = fragment.normal * gsNormalOffset(gsShadowNormalOffset * texelSize, cosine);
#endif
#ifdef GS_SHADOW_ORTHOGRAPHIC
    // A sun's map looks along the light: towards it only depth changes, by the depth per world unit.
    vec4 clip = projected.clip - vec4(0.0, 0.0, towardsLight * lookup.depthScale, 0.0);
#ifdef GS_SHADOW_NORMAL_OFFSET
    clip.xyz += mat3(m) * alongNormal;
#endif
#else
    vec3 offset = fragment.toLight * towardsLight;
#ifdef GS_SHADOW_NORMAL_OFFSET
    offset += alongNormal;
#endif
    vec4 clip = projected.clip + m * vec4(offset, 0.0);
#endif
#ifdef GS_SHADOW_ORTHOGRAPHIC
    vec3 coord = clip.xyz;
#else
    if (clip.w <= 0.0) {
        return 1.0; // behind a perspective map's light: nothing is mapped (the light's falloff is zero there)
    }
    vec3 coord = clip.xyz / clip.w;
#endif
    float layerSize = gsShadowTexel[slot].x;
#ifdef GS_SHADOW_VIRTUAL_PAGES
    if (gsVirtualPageLayer >= 0) {
        // A level of a virtual map: read the texels of the page under the receiver where they live in the
        // atlas, or name the coarser level that holds them.
        vec2 window = coord.xy * resolution;
        ivec2 page = gsVirtualPageAt(window);
        int pages = int(float(gsVirtualPages.x) * gsVirtualLevelScale);
        if (any(lessThan(page, ivec2(0))) || any(greaterThanEqual(page, ivec2(pages)))) {
            if (gsVirtualFaceMaps) {
                return 1.0; // beyond a spot map or a face's margin: the light reaches nothing there
            }
            gsVirtualNextLevel = gsVirtualLevelIndex + 1;
            return -1.0;
        }
        uint entry = texelFetch(gsShadowPageTable, ivec3(page, gsVirtualPageLayer), gsVirtualTableLevel).r;
        if (entry == 0u) {
            return 1.0; // nothing resident at any level here: the module warned that the budget fell short
        }
        int resident = gsVirtualEntryLevel(entry);
        if (resident != gsVirtualLevelIndex) {
            gsVirtualNextLevel = resident;
            return -1.0;
        }
        int tile = int(entry & 0xffffffu);
#if defined(GS_SHADOW_DEBUG_PAGES) || defined(GS_SHADOW_DEBUG_SLOT)
        if (!gsDebugSet) {
            vec2 inPage = window - vec2(page) * gsVirtualPage.x;
            vec2 toEdge = min(inPage, gsVirtualPage.x - inPage);
            gsDebugPageEdge = min(toEdge.x, toEdge.y);
            gsDebugPageLevel = resident;
            gsDebugPageBorder = any(lessThan(min(inPage, gsVirtualPage.x - inPage), vec2(1.0)));
            gsDebugPageDrawn = (entry & 0x40000000u) != 0u;
        }
#endif
        int tilesPerLayer = gsVirtualPages.y * gsVirtualPages.y;
        // The tile's layer, row and column by float division: x86 has no vector integer division, so a software
        // rasteriser divides each lane's integers in turn. Exact: (n + 0.5) / d lies 0.5 / d or more from an
        // integer, beyond the division's rounding while n < 2^23 (the largest pool, 4096 MiB of 32-texel pages,
        // holds 2^20 tiles).
        float layerTiles = float(tilesPerLayer);
        float rowTiles = float(gsVirtualPages.y);
        float layer = floor((float(tile) + 0.5) / layerTiles);
        float inLayer = float(tile) - layer * layerTiles;
        float row = floor((inLayer + 0.5) / rowTiles);
        vec2 cell = vec2(inLayer - row * rowTiles, row);
        vec2 atlasTexel = cell * gsVirtualPage.y + gsVirtualPage.z + (window - vec2(page) * gsVirtualPage.x);
        lookup.layer = int(layer);
        lookup.inverseSize = gsVirtualPage.w;
        layerSize = float(gsVirtualPages.z);
        coord.xy = atlasTexel * gsVirtualPage.w;
    } else
#endif
    // Outside the map, or in a fitted directional map's lit border: no caster can shadow the receiver there,
    // and its kernel would read across the map's edge (a fit or central difference over the border's far
    // depth predicts taps far behind the receiver, which then look shadowed).
    if (any(greaterThan(abs(coord.xy - 0.5), vec2(0.5 - gsShadowDepthRange[slot].z * gsShadowTexel[slot].y)))) {
        return 1.0;
    }
    lookup.coord = coord.xy;
    lookup.texel = coord.xy * layerSize;
    lookup.texelWorld = texelSize;
    lookup.perspective = perspective;
    lookup.lightSize = gsShadowDepthRange[slot].w;
    // The depth bias: format steps of the stored depth, but no less than the arithmetic floor, which is a
    // distance along the light's axis (a fraction of the map's depth range). A perspective map's depth changes
    // by near·far/w² per unit of that range at distance w: as a fixed depth offset the floor would span a
    // growing distance, w²/near, and at far/near 1000 it reached 0.27 m at a room's wall, past thin casters
    // standing near it (every technique leaked there).
    float biasFloor = gsShadowDepthBiasFloor;
    if (perspective) {
        biasFloor *= gsShadowDepthRange[slot].x * gsShadowDepthRange[slot].y / (clip.w * clip.w);
    }
    lookup.depth = coord.z - max(gsShadowDepthBias, biasFloor);
    if (lookup.depth >= 1.0) {
        return 1.0; // beyond the map's depth range: nothing can occlude
    }
#ifdef GS_SHADOW_ORTHOGRAPHIC
    lookup.momentDepth = lookup.depth; // gsLinearDepth's identity for an orthographic map
#else
    lookup.momentDepth = gsLinearDepth(lookup.depth, gsShadowDepthRange[slot].xy);
#endif
    lookup.screenGradient = vec2(0.0);
#if defined(GS_SHADOW_GRADIENT_SCREEN) || defined(GS_SHADOW_RECEIVER_PLANE)
    vec3 dx = gsShadowDerivative(clip, projected.dx);
    vec3 dy = gsShadowDerivative(clip, projected.dy);
    lookup.screenGradient = gsReceiverPlaneGradient(dx.xy * resolution, dy.xy * resolution, dx.z, dy.z);
#endif
    lookup.tangentGradient = vec2(0.0);
#ifdef GS_SHADOW_TANGENT_PLANE
    lookup.tangentGradient = gsTangentPlaneGradient(m, fragment.position, fragment.normal, resolution);
#endif
    lookup.pointGradient = vec2(0.0);
#if defined(GS_SHADOW_GRADIENT_STORED)
    lookup.pointGradient = textureLod(gsShadowGradientMaps, vec3(lookup.coord, float(lookup.layer)), 0.0).rg;
#elif defined(GS_SHADOW_GRADIENT_CENTRAL)
    vec2 texel = lookup.texel;
    lookup.pointGradient =
        0.5 * vec2(gsShadowDepthAt(lookup, texel + vec2(1, 0)) - gsShadowDepthAt(lookup, texel - vec2(1, 0)),
                   gsShadowDepthAt(lookup, texel + vec2(0, 1)) - gsShadowDepthAt(lookup, texel - vec2(0, 1)));
#elif defined(GS_SHADOW_GRADIENT_SCREEN)
    lookup.pointGradient = lookup.screenGradient;
#endif

    GsShadowSample result = gsShadowSample(lookup);
    gsDebugFullKernel = result.fullKernel;
    if (!gsDebugSet) {
        gsDebugSet = true;
        gsDebugSlot = slot;
#ifdef GS_SHADOW_DEBUG_DENSITY
        vec3 texelDx = gsShadowDerivative(clip, projected.dx) * resolution;
        vec3 texelDy = gsShadowDerivative(clip, projected.dy) * resolution;
        gsDebugDensity = gsTexelFootprintPixels(texelDx.xy, texelDy.xy);
#endif
        gsDebugGradient = length(result.gradient);
        gsDebugBias = result.bias;
        gsDebugStored = result.stored;
        gsDebugTexel = lookup.texel;
    }
    return gsSaturate(result.visibility);
}

// Visibility of the fragment in map `slot` projected here; -1 (no map drawn) is lit.
float gsShadowMapVisibility(int slot, GsShadowFragment fragment) {
    if (slot < 0) {
        return 1.0;
    }
    return gsShadowMapVisibilityAt(slot, fragment, gsShadowProjectFragment(slot, fragment));
}

#ifdef GS_SHADOW_LAYOUT_VIRTUAL
// A clipmap level's projection of the fragment: the finest level's (`finest`) scaled and offset, as the levels
// share the light's rotation and depth range; under GS_SHADOW_FRAGMENT_PROJECTION the level's own product.
GsShadowProjection gsClipmapLevelProjection(int slot, GsShadowFragment fragment, GsShadowProjection finest) {
#ifdef GS_SHADOW_VERTEX_PROJECTION
    return gsShadowCascadeProjection(slot, finest);
#else
    return gsShadowProjectFragment(slot, fragment);
#endif
}
#endif

// Which map of light `lightIndex` was read, for the maps debug view: cascade index or cube face, -1 for none.
int gsDebugMap = -1;

float gsShadowLightVisibility(int lightIndex, vec3 worldPosition, vec3 normal, vec3 toLight) {
    // Screen derivatives must be taken before any per-pixel branch (a quad's fragments may pick other maps).
    vec3 dPdx = dFdxFine(worldPosition);
    vec3 dPdy = dFdyFine(worldPosition);
#ifdef GS_SHADOW_VERTEX_PROJECTION
    vec4 vertexClip = vGsShadowClip[lightIndex];
    GsShadowProjection fromVertex = GsShadowProjection(vertexClip, dFdxFine(vertexClip), dFdyFine(vertexClip));
#endif
#if !defined(GS_SHADOW_DEBUG_VIEW) && !defined(GS_SHADOW_KEEP_FACING_AWAY)
    // A receiver facing away from the light gets none of it whatever the map says (gsBlinnPhong's Lambert and
    // specular terms are 0 for this normal): no fetch. Debug views show the map's answer there too;
    // GS_SHADOW_KEEP_FACING_AWAY exists for the test that shows this changes no image.
    if (dot(normal, toLight) <= 0.0) {
        return 1.0;
    }
#endif
    GsShadowFragment fragment =
        GsShadowFragment(worldPosition, gsFacetNormal(dPdx, dPdy, normal), toLight, dPdx, dPdy);
    GsShadowLightMaps maps = gsShadowLights[lightIndex];
    int kind = maps.kind.x;
    // Each layout only where a light of this frame uses it (GS_SHADOW_LAYOUT_*, ShadowModule::layoutKey).
#ifdef GS_SHADOW_LAYOUT_CUBE
    if (kind == GS_SHADOW_LIGHT_CUBE) {
        int face = gsCubeFace(worldPosition - gsLights[lightIndex].position.xyz);
        gsDebugMap = gsDebugMap < 0 ? face : gsDebugMap;
        return gsShadowMapVisibility(face < 4 ? maps.slots[face] : maps.faceSlots[face - 4], fragment);
    }
#endif
#ifdef GS_SHADOW_LAYOUT_CASCADES
    if (kind == GS_SHADOW_LIGHT_CASCADES) {
        float depth = dot(gsShadowViewDepth, vec4(worldPosition, 1.0));
        int count = maps.kind.y;
        int cascade = gsCascadeIndex(depth, maps.splitFar, count);
        gsDebugMap = gsDebugMap < 0 ? cascade : gsDebugMap;
        float weight = cascade + 1 < count ? gsCascadeBlendWeight(depth, maps.splitNear[cascade],
                                                                    maps.splitFar[cascade], gsShadowCascadeBlend)
                                           : 0.0;
        // The next cascade fades in over the blend band. One lookup written once, in a loop of one or two
        // iterations rather than two inlined lookups: llvmpipe runs a branch's code for every fragment, but
        // leaves a loop once no fragment of its group continues, so only groups in a band pay twice. It checks
        // that only at the loop's end, so the test is there (do-while): a for loop's test at the top ran the
        // body once more, masked off, for every group.
        float visibility = 0.0;
        int last = weight > 0.0 ? cascade + 1 : cascade;
        int c = cascade;
        do {
            int slot = maps.slots[c];
#ifdef GS_SHADOW_VERTEX_PROJECTION
            float inCascade =
                slot < 0 ? 1.0
                         : gsShadowMapVisibilityAt(slot, fragment, gsShadowCascadeProjection(slot, fromVertex));
#else
            float inCascade = gsShadowMapVisibility(slot, fragment);
#endif
            visibility += (c == cascade ? 1.0 - weight : weight) * inCascade;
            ++c;
        } while (c <= last);
        return visibility;
    }
#endif
#ifdef GS_SHADOW_LAYOUT_VIRTUAL
    if (kind == GS_SHADOW_LIGHT_VIRTUAL) {
        int levels = maps.kind.y;
        int firstSlot = maps.kind.z;
#ifdef GS_SHADOW_VERTEX_PROJECTION
        GsShadowProjection finest = fromVertex;
#else
        GsShadowProjection finest = gsShadowProjectFragment(firstSlot, fragment);
#endif
        // Start at the finest level whose window holds the receiver: the windows double in radius around the
        // camera (up to a page off centre), so from the finest level's coordinates.
        vec2 centred = finest.clip.xy - 0.5;
        float reach = max(abs(centred.x), abs(centred.y)) / (0.5 - 1.0 / float(gsVirtualPages.x));
        int level = min(reach > 1.0 ? int(ceil(log2(reach))) : 0, levels - 1);
        // That level's entry under the receiver names the finest resident level over it: go there at once
        // rather than through a whole lookup that would only name it.
        vec2 window =
            gsClipmapLevelProjection(firstSlot + level, fragment, finest).clip.xy * gsShadowTexel[firstSlot + level].x;
        ivec2 page = clamp(gsVirtualPageAt(window), ivec2(0), ivec2(gsVirtualPages.x - 1));
        uint entry = texelFetch(gsShadowPageTable, ivec3(page, maps.kind.w + level), 0).r;
        level = entry != 0u ? gsVirtualEntryLevel(entry) : level;
        // Each try lands on the finest resident page over the receiver, or names its level: one but where the
        // receiver's offsets cross into a page another level holds.
        float visibility = 1.0;
        for (int attempt = 0; attempt < levels && level < levels; ++attempt) {
            gsVirtualPageLayer = maps.kind.w + level;
            gsVirtualLevelIndex = level;
            visibility = gsShadowMapVisibilityAt(firstSlot + level, fragment,
                                                 gsClipmapLevelProjection(firstSlot + level, fragment, finest));
            if (visibility >= 0.0) {
                gsDebugMap = gsDebugMap < 0 ? level : gsDebugMap;
                break;
            }
            level = max(gsVirtualNextLevel, level + 1);
        }
        gsVirtualPageLayer = -1;
        return visibility < 0.0 ? 1.0 : visibility;
    }
#endif
#ifdef GS_SHADOW_LAYOUT_VIRTUAL_FACES
    if (kind == GS_SHADOW_LIGHT_VIRTUAL_FACES) {
        int face = maps.kind.z == 6 ? gsCubeFace(worldPosition - gsLights[lightIndex].position.xyz) : 0;
        int slot = face < 4 ? maps.slots[face] : maps.faceSlots[face - 4];
        if (slot < 0) {
            return 1.0;
        }
        gsDebugMap = gsDebugMap < 0 ? face : gsDebugMap;
        int levels = maps.kind.y;
        gsVirtualPageLayer = maps.kind.w + face;
        gsVirtualFaceMaps = true;
        // Level 0's entry under the receiver names the finest resident level over it.
        vec4 clip = gsShadowMatrix[slot] * vec4(worldPosition, 1.0);
        int level = 0;
        if (clip.w > 0.0) {
            ivec2 page = clamp(gsVirtualPageAt(clip.xy / clip.w * gsShadowTexel[slot].x), ivec2(0),
                               ivec2(gsVirtualPages.x - 1));
            uint entry = texelFetch(gsShadowPageTable, ivec3(page, gsVirtualPageLayer), 0).r;
            level = entry != 0u ? gsVirtualEntryLevel(entry) : 0;
        }
        float visibility = 1.0;
        for (int attempt = 0; attempt < levels && level < levels; ++attempt) {
            gsVirtualLevelIndex = level;
            gsVirtualTableLevel = level;
            gsVirtualLevelScale = exp2(-float(level));
            visibility = gsShadowMapVisibility(slot, fragment);
            if (visibility >= 0.0) {
                break;
            }
            level = max(gsVirtualNextLevel, level + 1);
        }
        gsVirtualPageLayer = -1;
        gsVirtualTableLevel = 0;
        gsVirtualLevelScale = 1.0;
        gsVirtualFaceMaps = false;
        return visibility < 0.0 ? 1.0 : visibility;
    }
#endif
#ifdef GS_SHADOW_LAYOUT_SINGLE
    if (kind == GS_SHADOW_LIGHT_SINGLE) {
#ifdef GS_SHADOW_ONE_MAP
        // The frame's only map is slot 0 (ShadowModule::layoutKey): a constant index into the block's arrays.
        const int slot = 0;
#else
        int slot = maps.slots.x;
#endif
#ifdef GS_SHADOW_VERTEX_PROJECTION
        return slot < 0 ? 1.0 : gsShadowMapVisibilityAt(slot, fragment, fromVertex);
#else
        return gsShadowMapVisibility(slot, fragment);
#endif
    }
#endif
    return 1.0;
}

// Visibility of light `lightIndex` at the fragment, as the shading uses it. The visibility debug view shows the
// first shadowed light's, across a cascade blend band too (a map's own lookup is only one of its two terms).
float gsShadowVisibility(int lightIndex, vec3 worldPosition, vec3 normal, vec3 toLight) {
    bool first = !gsDebugSet;
    float visibility = gsShadowLightVisibility(lightIndex, worldPosition, normal, toLight);
    if (first && gsDebugSet) {
        gsDebugVisibility = visibility;
    }
    return visibility;
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
#elif defined(GS_SHADOW_DEBUG_DENSITY)
    // Lloyd's m, one texel's largest extent in pixels: green m <= 1 (a texel per pixel or finer), yellow <= 2,
    // red beyond, darkened in shadow; grey where no map was read.
    vec3 density = gsDebugDensity < 0.0    ? vec3(0.5)
                   : gsDebugDensity <= 1.0 ? vec3(0.2, 0.9, 0.2)
                   : gsDebugDensity <= 2.0 ? vec3(1.0, 0.9, 0.15)
                                           : vec3(1.0, 0.2, 0.15);
    color = density * (0.35 + 0.65 * gsDebugVisibility);
#elif defined(GS_SHADOW_DEBUG_SLOT)
    color = vec3(float(gsDebugSlot), gsDebugPageEdge, float(gsDebugPageLevel));
#elif defined(GS_SHADOW_DEBUG_PAGES)
    const vec3 levels[6] = vec3[6](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.3, 0.45, 1.0),
                                   vec3(1.0, 0.9, 0.2), vec3(1.0, 0.3, 1.0), vec3(0.2, 1.0, 1.0));
    color = gsDebugPageLevel < 0 ? vec3(0.5) : levels[gsDebugPageLevel % 6] * (gsDebugPageDrawn ? 1.0 : 0.6);
    color *= gsDebugPageBorder ? 0.25 : 1.0;
    color *= 0.35 + 0.65 * gsDebugVisibility;
#elif defined(GS_SHADOW_DEBUG_MAPS)
    // Cascade 0..3 or cube face 0..5 as a hue, darkened in shadow; grey where no map was read.
    const vec3 palette[6] = vec3[6](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.3, 0.45, 1.0),
                                    vec3(1.0, 0.9, 0.2), vec3(1.0, 0.3, 1.0), vec3(0.2, 1.0, 1.0));
    color = (gsDebugMap < 0 ? vec3(0.5) : palette[gsDebugMap % 6]) * (0.35 + 0.65 * gsDebugVisibility);
#endif
}
