#version 450 core
// One direction of the separable box blur of the moments (VSM/MSM filtering), clamped at the map's edges: from
// layer uLayer of uSource into the bound target's layer, the target's pixel p reading the source around p +
// uSourceOffset (a virtual page's tile in the atlas and a tile-sized temporary; zero for whole maps).
uniform sampler2DArray uSource;
uniform int uLayer;
uniform ivec2 uDirection;
uniform int uRadius;
uniform ivec2 uSourceOffset;

layout(location = 0) out vec4 outValue;

void main() {
    ivec2 size = textureSize(uSource, 0).xy;
    ivec2 centre = ivec2(gl_FragCoord.xy) + uSourceOffset;
    vec4 sum = vec4(0.0);
    for (int k = -uRadius; k <= uRadius; ++k) {
        sum += texelFetch(uSource, ivec3(clamp(centre + k * uDirection, ivec2(0), size - 1), uLayer), 0);
    }
    outValue = sum / float(2 * uRadius + 1);
}
