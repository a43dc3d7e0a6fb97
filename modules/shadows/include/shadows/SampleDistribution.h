#pragma once

#include <shadows/LightFrustum.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

namespace shadows {

/// @file
/// @brief Sample Distribution Shadow Maps (Lauritzen, Salvi, Lefohn, I3D 2011): a directional light's maps
/// fitted to where the visible samples of the depth buffer lie, not to mesh bounds (a real asset often
/// arrives as one mesh whose box spans the whole view). The GPU reduces the depth image
/// (shaders/shadows/samples.comp); these functions are its CPU mirror and the rules the fit applies to the
/// result.

/// @brief Candidate slices: every cascade of every count 1..kMaxCascades (1 + 2 + 3 + 4), so the count can be
/// chosen from the result. The reduction measures slice 0 (one map over the whole range) with the depth
/// range, and the other nine in a second pass only where one map does not resolve the view
/// (oneMapResolvesView).
inline constexpr int kSampleSlices = kMaxCascades * (kMaxCascades + 1) / 2;

/// @brief Slice index of cascade `cascade` (0-based) when the light has `count` cascades.
[[nodiscard]] constexpr int sampleSliceIndex(int count, int cascade) {
    return count * (count - 1) / 2 + cascade;
}

/// @brief The light-space box of the samples in one slice: x, y across the light, z along it (the light looks
/// down -z, so max.z is the sample nearest the light).
struct LightRect {
    /// Smallest light-space coordinates of the samples.
    glm::vec3 min{std::numeric_limits<float>::max()};
    /// Largest light-space coordinates of the samples.
    glm::vec3 max{-std::numeric_limits<float>::max()};
    /// Samples in the slice.
    std::uint32_t samples = 0;

    /// @brief Whether no sample lies in the slice.
    [[nodiscard]] bool empty() const { return samples == 0; }
    /// @brief Adds a sample at light-space position `p`.
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
        ++samples;
    }
};

/// @brief `rect` cut to the light-space xy box `region` (shadowableRegion: only samples a caster can shadow
/// need texels; the rest of a ground in view is lit anyway); empty when they do not meet. The depths and the
/// count are kept: the cut box still holds what the map must, and the count only says it is not empty.
[[nodiscard]] LightRect clippedTo(const LightRect& rect, const Aabb& region);

/// @brief The view-depth bounds [near, far] of each candidate slice, for samples in [range.x, range.y]: the
/// practical split scheme of cascadeSplits with `weight`, each cascade after the first starting `blend` of
/// the previous one's span earlier (it also covers the band where the previous one fades into it).
[[nodiscard]] std::array<glm::vec2, kSampleSlices> sampleSliceDepths(glm::vec2 range, float weight,
                                                                     float blend);

/// @brief The visible samples' view-depth range: over every texel of `depth` (window depths in [0,1], rows
/// from the bottom; 1 is the far plane: no surface), the view depth (-z of `clipToView` times the texel's
/// clip position). nullopt when no texel holds a surface, or a depth is not finite (NaN, a degenerate
/// projection).
[[nodiscard]] std::optional<glm::vec2> sampleDepthRange(std::span<const float> depth, glm::ivec2 size,
                                                        const glm::mat4& clipToView);

/// @brief The light-space box of the samples in each slice (`sliceDepths`, view depths): each texel's world
/// position (`clipToWorld`), its view depth (`worldToView`) and its light-space position (`worldToLight`).
[[nodiscard]] std::array<LightRect, kSampleSlices>
sampleLightRects(std::span<const float> depth, glm::ivec2 size, const glm::mat4& clipToWorld,
                 const glm::mat4& worldToView, const glm::mat4& worldToLight,
                 const std::array<glm::vec2, kSampleSlices>& sliceDepths);

/// @brief The aliasing of a map of `resolution`² over `rect` at view depth `viewDepth` (its slice's nearest):
/// one texel's size over one pixel's there (Lloyd et al.'s m for a receiver facing the camera and the light;
/// a receiver the light grazes stretches texels further, which a fitted map cannot undo).
[[nodiscard]] float sliceTexelsPerPixel(const LightRect& rect, float viewDepth, int resolution,
                                        const glm::mat4& projection, int imageHeight);

/// @brief The side of the smallest map, a power of two from kSmallestMapSide up to `resolution`, on which
/// each of `count` cascades' slices (sampleSliceIndex) has a texel no larger than `texelPixels` pixels at its
/// near depth, with `marginTexels` of margin on each side; `resolution` when `texelPixels` is not positive or
/// a slice's pixel has no size. Empty slices ask for nothing.
[[nodiscard]] int viewResolution(const std::array<LightRect, kSampleSlices>& rects,
                                 const std::array<glm::vec2, kSampleSlices>& sliceDepths, int count,
                                 int resolution, float marginTexels, float texelPixels,
                                 const glm::mat4& projection, int imageHeight);

/// @brief Whether one map of `resolution`² over slice 0 (`rects[0]`, the whole range) has sliceTexelsPerPixel
/// <= 1 at its near depth: densityCascadeCount's first test, which needs no other slice.
[[nodiscard]] bool oneMapResolvesView(const std::array<LightRect, kSampleSlices>& rects,
                                      const std::array<glm::vec2, kSampleSlices>& sliceDepths, int resolution,
                                      const glm::mat4& projection, int imageHeight);

/// @brief The fewest cascades (1..kMaxCascades) whose slices each have sliceTexelsPerPixel <= 1 at their
/// near depth, or kMaxCascades when none does. Empty slices (no sample) need no map and pass.
[[nodiscard]] int densityCascadeCount(const std::array<LightRect, kSampleSlices>& rects,
                                      const std::array<glm::vec2, kSampleSlices>& sliceDepths, int resolution,
                                      const glm::mat4& projection, int imageHeight);

} // namespace shadows
