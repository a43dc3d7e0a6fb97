#version 450 core
// The reduction of Sample Distribution Shadow Maps (Lauritzen, Salvi, Lefohn, I3D 2011, section 3): the
// visible samples of a depth image, reduced to their view-depth range and to the light-space box of the samples
// in each candidate slice. The CPU mirror is shadows::sampleDepthRange / sampleLightRects; floats are reduced
// as order-preserving unsigned integers, first within a work group in shared memory, then once per group in the
// buffer.
layout(local_size_x = 8, local_size_y = 8) in;

const int GS_SAMPLE_SLICES = 10;
// Per slice: min x, y, z, max x, y, z, then the sample count.
const int GS_SLICE_WORDS = 7;

layout(binding = 0) uniform sampler2D uDepth;
uniform ivec2 uSize;
// Window texel (x, y, depth, 1) to the light's view space, homogeneous (VisibleSamples: clip to world and world
// to light in one matrix, w the world point's), and to the view depth's numerator over that w.
uniform mat4 uTexelToLight;
uniform vec4 uTexelToViewDepth;
uniform vec2 uSliceDepths[GS_SAMPLE_SLICES];

layout(std430, binding = 0) buffer GsSampleBounds {
    uint depthRange[2]; // min, max view depth
    uint slices[GS_SAMPLE_SLICES * GS_SLICE_WORDS];
};

// GS_SAMPLES_WHOLE reduces the view-depth range and slice 0, the whole range's (every sample: its ends are
// widened past rounding, sampleSliceDepths); GS_SAMPLES_CASCADE_SLICES the other slices, which only a view
// that one map cannot resolve needs. The group's words: the buffer's, from GS_FIRST_WORD.
#if defined(GS_SAMPLES_WHOLE)
const int GS_FIRST_SLICE = 0;
const int GS_LAST_SLICE = 0;
const int GS_FIRST_WORD = 0;
const int GS_GROUP_WORDS = 2 + GS_SLICE_WORDS;
#else
const int GS_FIRST_SLICE = 1;
const int GS_LAST_SLICE = GS_SAMPLE_SLICES - 1;
const int GS_FIRST_WORD = 2 + GS_SLICE_WORDS;
const int GS_GROUP_WORDS = (GS_SAMPLE_SLICES - 1) * GS_SLICE_WORDS;
#endif
const int GS_SLICE_COUNT = GS_LAST_SLICE - GS_FIRST_SLICE + 1;
shared uint groupWords[GS_GROUP_WORDS];

// IEEE floats ordered as unsigned integers: negative ones reversed below the positive ones.
uint gsOrderedBits(float value) {
    uint bits = floatBitsToUint(value);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

// What buffer word `word` holds: 0 a minimum (initialised to all ones), 1 a maximum, 2 a count.
int gsWordKind(int word) {
    if (word < 2) {
        return word;
    }
    int inSlice = (word - 2) % GS_SLICE_WORDS;
    return inSlice < 3 ? 0 : inSlice < 6 ? 1 : 2;
}

// Each invocation reduces GS_BLOCK x GS_BLOCK texels in registers first: shared-memory atomics are slow on a
// software rasteriser, and an invocation's set of them (sixty-three for the cascades' slices) costs as much as
// many texels' arithmetic, so 256 texels share one set. It reads them 2x2 at a time by gathers, a quarter of the
// fetches of one texel each. A group of 8x8 invocations covers 8 * GS_BLOCK texels square, its invocations
// interleaved (2x2 texels at group origin + 2 * (invocation + 8 * step)), so neighbouring invocations, which a
// SIMD rasteriser runs side by side, read neighbouring texels. VisibleSamples dispatches the groups.
const int GS_BLOCK = 16;
const int GS_GROUP_SIDE = 8;

float gsNearest = 3.0e38;
float gsFarthest = -3.0e38;
vec3 gsLow[GS_SLICE_COUNT];
vec3 gsHigh[GS_SLICE_COUNT];
uint gsCount[GS_SLICE_COUNT];

// Adds the sample at `texel` of depth `depth`, `light` being its window texel (x, y, 0, 1) in the light's view
// and `viewDepth` the view depth's numerator there, both before the depth's part and the divide by w.
void gsAddSample(ivec2 texel, float depth, vec4 light, float viewDepth) {
    if (any(greaterThanEqual(texel, uSize)) || !(depth < 1.0 && depth >= 0.0)) { // 1: the cleared far plane
        return;
    }
    light += depth * uTexelToLight[2];
    float perW = 1.0 / light.w;
    vec3 point = light.xyz * perW;
    viewDepth = (viewDepth + depth * uTexelToViewDepth.z) * perW;
#if defined(GS_SAMPLES_WHOLE)
    gsNearest = min(gsNearest, viewDepth);
    gsFarthest = max(gsFarthest, viewDepth);
    gsLow[0] = min(gsLow[0], point);
    gsHigh[0] = max(gsHigh[0], point);
    gsCount[0] += 1u;
#else
    for (int s = 0; s < GS_SLICE_COUNT; ++s) {
        vec2 slice = uSliceDepths[GS_FIRST_SLICE + s];
        if (viewDepth >= slice.x && viewDepth <= slice.y) {
            gsLow[s] = min(gsLow[s], point);
            gsHigh[s] = max(gsHigh[s], point);
            gsCount[s] += 1u;
        }
    }
#endif
}

void main() {
    uint local = gl_LocalInvocationIndex;
    for (int i = int(local); i < GS_GROUP_WORDS; i += 64) {
        groupWords[i] = gsWordKind(GS_FIRST_WORD + i) == 0 ? 0xffffffffu : 0u;
    }
    barrier();
    for (int s = 0; s < GS_SLICE_COUNT; ++s) {
        gsLow[s] = vec3(3.0e38);
        gsHigh[s] = vec3(-3.0e38);
        gsCount[s] = 0u;
    }
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * (GS_GROUP_SIDE * GS_BLOCK) + 2 * ivec2(gl_LocalInvocationID.xy);
    vec2 inverseSize = 1.0 / vec2(uSize);
    // The window texel (x, y, depth, 1) enters both products linearly: a row's part (x = origin's, depth 0) is
    // taken once, then each texel adds its x step and its depth, not a whole matrix product per texel.
    vec4 lightPerX = uTexelToLight[0];
    float viewDepthPerX = uTexelToViewDepth.x;
    for (int row = 0; row < GS_BLOCK; row += 2) {
        int y = origin.y + row * GS_GROUP_SIDE;
        vec4 rowStart = vec4(vec2(origin.x, y), 0.0, 1.0);
        vec4 rowLight = uTexelToLight * rowStart;
        float rowViewDepth = dot(uTexelToViewDepth, rowStart);
        vec4 nextRowLight = rowLight + uTexelToLight[1];
        float nextRowViewDepth = rowViewDepth + uTexelToViewDepth.y;
        for (int column = 0; column < GS_BLOCK; column += 2) {
            int x = origin.x + column * GS_GROUP_SIDE;
            // x (0, 1), y (1, 1), z (1, 0), w (0, 0) from (x, y); the coordinate is the four texels' shared corner.
            vec4 depths = textureGather(uDepth, vec2(x + 1, y + 1) * inverseSize);
            float dx = float(column * GS_GROUP_SIDE);
            gsAddSample(ivec2(x, y), depths.w, rowLight + dx * lightPerX, rowViewDepth + dx * viewDepthPerX);
            gsAddSample(ivec2(x + 1, y), depths.z, rowLight + (dx + 1.0) * lightPerX,
                        rowViewDepth + (dx + 1.0) * viewDepthPerX);
            gsAddSample(ivec2(x, y + 1), depths.x, nextRowLight + dx * lightPerX,
                        nextRowViewDepth + dx * viewDepthPerX);
            gsAddSample(ivec2(x + 1, y + 1), depths.y, nextRowLight + (dx + 1.0) * lightPerX,
                        nextRowViewDepth + (dx + 1.0) * viewDepthPerX);
        }
    }
#if defined(GS_SAMPLES_WHOLE)
    if (gsNearest <= gsFarthest) {
        atomicMin(groupWords[0], gsOrderedBits(gsNearest));
        atomicMax(groupWords[1], gsOrderedBits(gsFarthest));
    }
#endif
    for (int s = 0; s < GS_SLICE_COUNT; ++s) {
        if (gsCount[s] > 0u) {
            int base = 2 + (GS_FIRST_SLICE + s) * GS_SLICE_WORDS - GS_FIRST_WORD;
            for (int axis = 0; axis < 3; ++axis) {
                atomicMin(groupWords[base + axis], gsOrderedBits(gsLow[s][axis]));
                atomicMax(groupWords[base + 3 + axis], gsOrderedBits(gsHigh[s][axis]));
            }
            atomicAdd(groupWords[base + 6], gsCount[s]);
        }
    }
    barrier();
    for (int i = int(local); i < GS_GROUP_WORDS; i += 64) {
        int word = GS_FIRST_WORD + i;
        int kind = gsWordKind(word);
        if (word < 2) {
            if (kind == 0) {
                atomicMin(depthRange[word], groupWords[i]);
            } else {
                atomicMax(depthRange[word], groupWords[i]);
            }
        } else if (kind == 0) {
            atomicMin(slices[word - 2], groupWords[i]);
        } else if (kind == 1) {
            atomicMax(slices[word - 2], groupWords[i]);
        } else {
            atomicAdd(slices[word - 2], groupWords[i]);
        }
    }
}
