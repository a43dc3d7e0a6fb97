#include <shadows/SampleDistribution.h>

#include <algorithm>
#include <cmath>

namespace shadows {

namespace {

/// Relative widening of the slices' outer ends (sampleSliceDepths).
constexpr float kSliceRounding = 1e-3f;

/// The clip-space position of texel (x, y) of a `size` depth image holding window depth `depth`.
glm::vec4 texelClip(int x, int y, glm::ivec2 size, float depth) {
    return {2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(size.x) - 1.0f,
            2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(size.y) - 1.0f, 2.0f * depth - 1.0f,
            1.0f};
}

/// Calls `visit(clip)` with the clip-space position of every texel of `depth` that holds a surface: below the
/// far plane's 1 (cleared), and a number.
template <typename Visit>
void forEachSample(std::span<const float> depth, glm::ivec2 size, const Visit& visit) {
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const float d = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) +
                                  static_cast<std::size_t>(x)];
            if (d < 1.0f && d >= 0.0f) {
                visit(texelClip(x, y, size, d));
            }
        }
    }
}

} // namespace

LightRect clippedTo(const LightRect& rect, const Aabb& region) {
    if (rect.empty() || region.empty()) {
        return {};
    }
    LightRect clipped = rect;
    clipped.min = glm::vec3(glm::max(glm::vec2(rect.min), glm::vec2(region.min)), rect.min.z);
    clipped.max = glm::vec3(glm::min(glm::vec2(rect.max), glm::vec2(region.max)), rect.max.z);
    if (!(clipped.min.x <= clipped.max.x && clipped.min.y <= clipped.max.y)) {
        return {};
    }
    return clipped;
}

std::array<glm::vec2, kSampleSlices> sampleSliceDepths(glm::vec2 range, float weight, float blend) {
    std::array<glm::vec2, kSampleSlices> slices{};
    for (int count = 1; count <= kMaxCascades; ++count) {
        const std::vector<float> splits = cascadeSplits(range.x, range.y, count, weight);
        for (int cascade = 0; cascade < count; ++cascade) {
            const auto c = static_cast<std::size_t>(cascade);
            const float near = splits[c] - (cascade > 0 ? blend * (splits[c] - splits[c - 1]) : 0.0f);
            slices[static_cast<std::size_t>(sampleSliceIndex(count, cascade))] = {near, splits[c + 1]};
        }
        // The outermost samples, whose view depth the second reduction recomputes by another product of
        // matrices, stay inside despite rounding.
        slices[static_cast<std::size_t>(sampleSliceIndex(count, 0))].x *= 1.0f - kSliceRounding;
        slices[static_cast<std::size_t>(sampleSliceIndex(count, count - 1))].y *= 1.0f + kSliceRounding;
    }
    return slices;
}

std::optional<glm::vec2> sampleDepthRange(std::span<const float> depth, glm::ivec2 size,
                                          const glm::mat4& clipToView) {
    glm::vec2 range(std::numeric_limits<float>::max(), -std::numeric_limits<float>::max());
    forEachSample(depth, size, [&](const glm::vec4& clip) {
        const glm::vec4 view = clipToView * clip;
        const float viewDepth = -view.z / view.w;
        range = {std::min(range.x, viewDepth), std::max(range.y, viewDepth)};
    });
    if (!(range.x <= range.y) || !std::isfinite(range.x) || !std::isfinite(range.y) || !(range.x > 0.0f)) {
        return std::nullopt;
    }
    return range;
}

std::array<LightRect, kSampleSlices>
sampleLightRects(std::span<const float> depth, glm::ivec2 size, const glm::mat4& clipToWorld,
                 const glm::mat4& worldToView, const glm::mat4& worldToLight,
                 const std::array<glm::vec2, kSampleSlices>& sliceDepths) {
    std::array<LightRect, kSampleSlices> rects{};
    forEachSample(depth, size, [&](const glm::vec4& clip) {
        const glm::vec4 world = clipToWorld * clip;
        const glm::vec4 point(glm::vec3(world) / world.w, 1.0f);
        const float viewDepth = -(worldToView * point).z;
        const glm::vec3 light(worldToLight * point);
        for (std::size_t s = 0; s < rects.size(); ++s) {
            if (viewDepth >= sliceDepths[s].x && viewDepth <= sliceDepths[s].y) {
                rects[s].extend(light);
            }
        }
    });
    return rects;
}

float sliceTexelsPerPixel(const LightRect& rect, float viewDepth, int resolution, const glm::mat4& projection,
                          int imageHeight) {
    if (rect.empty()) {
        return 0.0f;
    }
    const float extent = std::max(rect.max.x - rect.min.x, rect.max.y - rect.min.y);
    // One pixel's world size across the view ray: 2/(P[1][1]·H) per unit of depth for a perspective
    // projection (P[2][3] = -1), that alone for an orthographic one.
    const bool perspective = projection[2][3] != 0.0f;
    const float perUnit = 2.0f / (std::abs(projection[1][1]) * static_cast<float>(std::max(imageHeight, 1)));
    const float pixel = perUnit * (perspective ? std::max(viewDepth, 0.0f) : 1.0f);
    const float texel = extent / static_cast<float>(std::max(resolution, 1));
    return pixel > 0.0f ? texel / pixel : std::numeric_limits<float>::infinity();
}

int viewResolution(const std::array<LightRect, kSampleSlices>& rects,
                   const std::array<glm::vec2, kSampleSlices>& sliceDepths, int count, int resolution,
                   float marginTexels, float texelPixels, const glm::mat4& projection, int imageHeight) {
    if (!(texelPixels > 0.0f) || !std::isfinite(texelPixels)) {
        return resolution;
    }
    float texelsAcross = 0.0f;
    for (int cascade = 0; cascade < count; ++cascade) {
        const auto s = static_cast<std::size_t>(sampleSliceIndex(count, cascade));
        // sliceTexelsPerPixel at one texel across the rect is the rect's extent in pixels.
        const float pixels = sliceTexelsPerPixel(rects[s], sliceDepths[s].x, 1, projection, imageHeight);
        if (!std::isfinite(pixels)) {
            return resolution;
        }
        texelsAcross = std::max(texelsAcross, pixels / texelPixels);
    }
    const float needed = texelsAcross + 2.0f * (std::max(marginTexels, 0.0f) + 1.0f);
    int side = std::min(kSmallestMapSide, resolution);
    while (side < resolution && static_cast<float>(side) < needed) {
        side *= 2;
    }
    return std::min(side, resolution);
}

bool oneMapResolvesView(const std::array<LightRect, kSampleSlices>& rects,
                        const std::array<glm::vec2, kSampleSlices>& sliceDepths, int resolution,
                        const glm::mat4& projection, int imageHeight) {
    return sliceTexelsPerPixel(rects[0], sliceDepths[0].x, resolution, projection, imageHeight) <= 1.0f;
}

int densityCascadeCount(const std::array<LightRect, kSampleSlices>& rects,
                        const std::array<glm::vec2, kSampleSlices>& sliceDepths, int resolution,
                        const glm::mat4& projection, int imageHeight) {
    if (oneMapResolvesView(rects, sliceDepths, resolution, projection, imageHeight)) {
        return 1;
    }
    for (int count = 2; count < kMaxCascades; ++count) {
        bool fine = true;
        for (int cascade = 0; cascade < count && fine; ++cascade) {
            const auto s = static_cast<std::size_t>(sampleSliceIndex(count, cascade));
            fine =
                sliceTexelsPerPixel(rects[s], sliceDepths[s].x, resolution, projection, imageHeight) <= 1.0f;
        }
        if (fine) {
            return count;
        }
    }
    return kMaxCascades;
}

} // namespace shadows
