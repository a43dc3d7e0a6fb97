// Where the lighting pass projects receivers into the maps. A light with one map, with cascades or with a
// virtual clipmap is projected in the vertex stage (vertex.glsl): clip coordinates are affine in the world
// position, so the interpolated ones are the fragment's own, and a light's cascades or clipmap levels differ from
// its first's by a scale and an offset (gsShadowCascadeScale). Cube faces and virtual perspective maps project in
// the fragment: a vertex would need every face's position, which costs more to interpolate than one product
// costs. GS_SHADOW_FRAGMENT_PROJECTION exists for the test that shows the two give the same lookups.
#if (defined(GS_SHADOW_LAYOUT_SINGLE) || defined(GS_SHADOW_LAYOUT_CASCADES) || defined(GS_SHADOW_LAYOUT_VIRTUAL)) && \
    !defined(GS_SHADOW_FRAGMENT_PROJECTION)
#define GS_SHADOW_VERTEX_PROJECTION
#endif
