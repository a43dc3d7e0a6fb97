#version 450 core
// The reduction of Sample Distribution Shadow Maps (Lauritzen, Salvi, Lefohn, I3D 2011, section 3): the
// visible samples of a depth image, reduced to their view-depth range (GS_SAMPLES_DEPTH_RANGE) or to the
// light-space box of the samples in each candidate slice (GS_SAMPLES_LIGHT_RECTS). The CPU mirror is
// shadows::sampleDepthRange / sampleLightRects; floats are reduced as order-preserving unsigned integers,
// first within a work group in shared memory, then once per group in the buffer.
layout(local_size_x = 8, local_size_y = 8) in;

const int GS_SAMPLE_SLICES = 10;
// Per slice: min x, y, z, max x, y, z, then the sample count.
const int GS_SLICE_WORDS = 7;

layout(binding = 0) uniform sampler2D uDepth;
uniform ivec2 uSize;
uniform mat4 uClipToView;
uniform mat4 uClipToWorld;
uniform mat4 uWorldToView;
uniform mat4 uWorldToLight;
uniform vec2 uSliceDepths[GS_SAMPLE_SLICES];

layout(std430, binding = 0) buffer GsSampleBounds {
    uint depthRange[2]; // min, max view depth
    uint slices[GS_SAMPLE_SLICES * GS_SLICE_WORDS];
};

#if defined(GS_SAMPLES_DEPTH_RANGE)
shared uint groupWords[2];
const int GS_GROUP_WORDS = 2;
#else
shared uint groupWords[GS_SAMPLE_SLICES * GS_SLICE_WORDS];
const int GS_GROUP_WORDS = GS_SAMPLE_SLICES * GS_SLICE_WORDS;
#endif

// IEEE floats ordered as unsigned integers: negative ones reversed below the positive ones.
uint gsOrderedBits(float value) {
    uint bits = floatBitsToUint(value);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

// Whether word `i` of a bounds record holds a minimum (initialised to all ones) rather than a maximum or count.
bool gsIsMinimumWord(int i) {
#if defined(GS_SAMPLES_DEPTH_RANGE)
    return i == 0;
#else
    return i % GS_SLICE_WORDS < 3;
#endif
}

// Each invocation reduces a block of GS_BLOCK x GS_BLOCK texels in registers first: shared-memory atomics are
// slow on a software rasteriser, and an invocation's set of them (seventy for the slices) costs as much as many
// texels' arithmetic, so a block of 256 shares one set. VisibleSamples dispatches groups of 8x8 invocations.
const int GS_BLOCK = 16;

void main() {
    uint local = gl_LocalInvocationIndex;
    for (int i = int(local); i < GS_GROUP_WORDS; i += 64) {
        groupWords[i] = gsIsMinimumWord(i) ? 0xffffffffu : 0u;
    }
    barrier();
#if defined(GS_SAMPLES_DEPTH_RANGE)
    float nearest = 3.0e38;
    float farthest = -3.0e38;
#else
    vec3 low[GS_SAMPLE_SLICES];
    vec3 high[GS_SAMPLE_SLICES];
    uint count[GS_SAMPLE_SLICES];
    for (int s = 0; s < GS_SAMPLE_SLICES; ++s) {
        low[s] = vec3(3.0e38);
        high[s] = vec3(-3.0e38);
        count[s] = 0u;
    }
#endif
    ivec2 origin = ivec2(gl_GlobalInvocationID.xy) * GS_BLOCK;
    for (int dy = 0; dy < GS_BLOCK; ++dy) {
        for (int dx = 0; dx < GS_BLOCK; ++dx) {
            ivec2 texel = origin + ivec2(dx, dy);
            if (any(greaterThanEqual(texel, uSize))) {
                continue;
            }
            float depth = texelFetch(uDepth, texel, 0).r;
            if (!(depth < 1.0 && depth >= 0.0)) { // 1 is the cleared far plane: no surface
                continue;
            }
            vec4 clip = vec4((vec2(texel) + 0.5) / vec2(uSize) * 2.0 - 1.0, 2.0 * depth - 1.0, 1.0);
#if defined(GS_SAMPLES_DEPTH_RANGE)
            vec4 view = uClipToView * clip;
            float viewDepth = -view.z / view.w;
            nearest = min(nearest, viewDepth);
            farthest = max(farthest, viewDepth);
#else
            vec4 world = uClipToWorld * clip;
            vec4 point = vec4(world.xyz / world.w, 1.0);
            float viewDepth = -(uWorldToView * point).z;
            vec3 light = (uWorldToLight * point).xyz;
            for (int s = 0; s < GS_SAMPLE_SLICES; ++s) {
                if (viewDepth >= uSliceDepths[s].x && viewDepth <= uSliceDepths[s].y) {
                    low[s] = min(low[s], light);
                    high[s] = max(high[s], light);
                    count[s] += 1u;
                }
            }
#endif
        }
    }
#if defined(GS_SAMPLES_DEPTH_RANGE)
    if (nearest <= farthest) {
        atomicMin(groupWords[0], gsOrderedBits(nearest));
        atomicMax(groupWords[1], gsOrderedBits(farthest));
    }
#else
    for (int s = 0; s < GS_SAMPLE_SLICES; ++s) {
        if (count[s] > 0u) {
            int base = s * GS_SLICE_WORDS;
            for (int axis = 0; axis < 3; ++axis) {
                atomicMin(groupWords[base + axis], gsOrderedBits(low[s][axis]));
                atomicMax(groupWords[base + 3 + axis], gsOrderedBits(high[s][axis]));
            }
            atomicAdd(groupWords[base + 6], count[s]);
        }
    }
#endif
    barrier();
    for (int i = int(local); i < GS_GROUP_WORDS; i += 64) {
#if defined(GS_SAMPLES_DEPTH_RANGE)
        if (i == 0) {
            atomicMin(depthRange[0], groupWords[0]);
        } else {
            atomicMax(depthRange[1], groupWords[1]);
        }
#else
        int word = i % GS_SLICE_WORDS;
        if (word == 6) {
            atomicAdd(slices[i], groupWords[i]);
        } else if (word < 3) {
            atomicMin(slices[i], groupWords[i]);
        } else {
            atomicMax(slices[i], groupWords[i]);
        }
#endif
    }
}
