#include <shadows/LightFrustum.h>
#include <shadows/SampleDistribution.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace shadows {

namespace {

/// A rotation whose -Z axis is `direction`, with any stable up vector.
glm::mat4 lightRotation(const glm::vec3& direction) {
    const glm::vec3 forward = glm::normalize(direction);
    const glm::vec3 up = std::abs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    return glm::lookAt(glm::vec3(0.0f), forward, up);
}

// Maps clip space [-1,1]³ to texture space [0,1]³.
const glm::mat4 kClipToTexture =
    glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));

/// A perspective map with light view `view` and square field of view `fov`: near and far bound the boxes in
/// front of the light (and `range` when positive).
LightProjection perspectiveMap(const glm::mat4& view, float fov, float range, std::span<const Aabb> boxes,
                               int resolution) {
    LightProjection result;
    result.perspective = true;
    result.view = view;
    float nearest = std::numeric_limits<float>::max();
    float farthest = 0.0f;
    for (const Aabb& box : boxes) {
        if (box.empty()) {
            continue;
        }
        const Aabb light = box.transformed(result.view);
        if (light.min.z >= 0.0f) {
            continue; // entirely behind the light
        }
        nearest = std::min(nearest, std::max(-light.max.z, 0.0f));
        farthest = std::max(farthest, -light.min.z);
    }
    if (range > 0.0f) {
        farthest = std::min(farthest, range);
    }
    if (!(farthest > 0.0f)) {
        return result;
    }
    // Depth precision of a perspective map falls with far/near: keep near at least 1/1000 of far.
    nearest = std::clamp(nearest * 0.99f, farthest * 1e-3f, farthest * 0.5f);
    result.projection = glm::perspective(fov, 1.0f, nearest, farthest * 1.01f);
    result.depthRange = {nearest, farthest * 1.01f};
    result.worldToShadow = kClipToTexture * result.projection * result.view;
    result.texelScale = 2.0f * std::tan(0.5f * fov) / static_cast<float>(resolution);
    result.valid = true;
    return result;
}

/// The world-space corners of the view volume of `viewProjection` between clip depths `zLow` and `zHigh`.
std::array<glm::vec3, 8> volumeCorners(const glm::mat4& viewProjection, float zLow, float zHigh) {
    const glm::mat4 clipToWorld = glm::inverse(viewProjection);
    std::array<glm::vec3, 8> corners{};
    std::size_t i = 0;
    for (const float z : {zLow, zHigh}) {
        for (const float x : {-1.0f, 1.0f}) {
            for (const float y : {-1.0f, 1.0f}) {
                const glm::vec4 p = clipToWorld * glm::vec4(x, y, z, 1.0f);
                corners[i++] = glm::vec3(p) / p.w;
            }
        }
    }
    return corners;
}

/// Whether `box` meets the view volume of `viewProjection`, by separating planes of either: the volume's six
/// (engine::intersectsClipVolume) and the box's six, which reject a large box beside a small volume that no
/// single plane of the volume separates.
bool meetsVolume(const Aabb& box, const glm::mat4& viewProjection) {
    if (box.empty() || !engine::intersectsClipVolume(box, viewProjection)) {
        return false;
    }
    const std::array<glm::vec3, 8> corners = volumeCorners(viewProjection, -1.0f, 1.0f);
    for (int axis = 0; axis < 3; ++axis) {
        bool allBelow = true;
        bool allAbove = true;
        for (const glm::vec3& corner : corners) {
            allBelow = allBelow && corner[axis] < box.min[axis];
            allAbove = allAbove && corner[axis] > box.max[axis];
        }
        if (allBelow || allAbove) {
            return false;
        }
    }
    return true;
}

/// The part of `box` the view volume of `viewProjection` can see, bounded by a box: `box` cut to the bounds
/// of the volume's slice between the nearest and farthest clip depths of the box's corners. Empty when the
/// volume does not meet the box. A ground plane under a camera looking down is then the patch in view, not
/// the whole plane.
Aabb visiblePart(const Aabb& box, const glm::mat4& viewProjection) {
    if (!meetsVolume(box, viewProjection)) {
        return {};
    }
    float zLow = 1.0f;
    float zHigh = -1.0f;
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec4 clip = viewProjection * glm::vec4(corner, 1.0f);
        if (clip.w > 0.0f) {
            zLow = std::min(zLow, clip.z / clip.w);
            zHigh = std::max(zHigh, clip.z / clip.w);
        } else {
            zLow = -1.0f; // the box reaches behind the eye: its nearest visible depth is the near plane
        }
    }
    zLow = std::clamp(zLow, -1.0f, 1.0f);
    zHigh = std::clamp(zHigh, -1.0f, 1.0f);
    if (zLow > zHigh) {
        return {};
    }
    Aabb slice;
    for (const glm::vec3& corner : volumeCorners(viewProjection, zLow, zHigh)) {
        slice.extend(corner);
    }
    Aabb part;
    const glm::vec3 low = glm::max(box.min, slice.min);
    const glm::vec3 high = glm::min(box.max, slice.max);
    if (glm::all(glm::lessThanEqual(low, high))) {
        part.extend(low);
        part.extend(high);
    }
    return part;
}

/// A flat box (thickness below 1e-5 of its size along one axis) holds coplanar surfaces, which cannot shadow
/// one another.
bool isPlanar(const Aabb& box) {
    const glm::vec3 size = box.max - box.min;
    const float largest = std::max({size.x, size.y, size.z});
    return std::min({size.x, size.y, size.z}) <= 1e-5f * largest;
}

/// Clips a convex polygon to the half-space where `sign` · (point[axis] - bound) ≥ 0 (Sutherland-Hodgman).
std::vector<glm::vec3> clipPolygon(const std::vector<glm::vec3>& polygon, int axis, float bound, float sign) {
    std::vector<glm::vec3> kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::vec3& a = polygon[i];
        const glm::vec3& b = polygon[(i + 1) % polygon.size()];
        const float da = sign * (a[axis] - bound);
        const float db = sign * (b[axis] - bound);
        if (da >= 0.0f) {
            kept.push_back(a);
        }
        if ((da >= 0.0f) != (db >= 0.0f)) {
            kept.push_back(a + (b - a) * (da / (da - db)));
        }
    }
    return kept;
}

/// The light-space depths (min, max z) of the part of world box `box` over the rectangle [low, high] of light
/// space (`view` a rotation), or nothing when none of it lies over the rectangle. A vertex of that part lies
/// on a face of the box inside the rectangle's prism, so clipping the six faces finds every extreme.
std::optional<glm::vec2> depthSpanOver(const Aabb& box, const glm::mat4& view, glm::vec2 low,
                                       glm::vec2 high) {
    if (box.empty()) {
        return std::nullopt;
    }
    // Most boxes lie wholly beside or inside the rectangle: their light-space bounds answer without clipping.
    const Aabb bounds = box.transformed(view);
    if (bounds.max.x < low.x || bounds.min.x > high.x || bounds.max.y < low.y || bounds.min.y > high.y) {
        return std::nullopt;
    }
    if (bounds.min.x >= low.x && bounds.max.x <= high.x && bounds.min.y >= low.y && bounds.max.y <= high.y) {
        return glm::vec2(bounds.min.z, bounds.max.z);
    }
    const auto corner = [&](int bits) {
        const glm::vec3 world((bits & 1) != 0 ? box.max.x : box.min.x,
                              (bits & 2) != 0 ? box.max.y : box.min.y,
                              (bits & 4) != 0 ? box.max.z : box.min.z);
        return glm::vec3(view * glm::vec4(world, 1.0f));
    };
    glm::vec2 span(std::numeric_limits<float>::max(), -std::numeric_limits<float>::max());
    for (int axis = 0; axis < 3; ++axis) {
        const int u = 1 << ((axis + 1) % 3);
        const int v = 1 << ((axis + 2) % 3);
        for (const int side : {0, 1 << axis}) {
            std::vector<glm::vec3> face = {corner(side), corner(side | u), corner(side | u | v),
                                           corner(side | v)};
            face = clipPolygon(face, 0, low.x, 1.0f);
            face = clipPolygon(face, 0, high.x, -1.0f);
            face = clipPolygon(face, 1, low.y, 1.0f);
            face = clipPolygon(face, 1, high.y, -1.0f);
            for (const glm::vec3& point : face) {
                span = glm::vec2(std::min(span.x, point.z), std::max(span.y, point.z));
            }
        }
    }
    if (span.x > span.y) {
        return std::nullopt;
    }
    return span;
}

/// Quantises a square map's `extent` up to 1/8-octave steps, so it changes rarely, then its `centre` to whole
/// texels of `resolution`, so its texel grid stays put in world space.
void snapSquare(float& extent, glm::vec2& centre, int resolution) {
    const float unit = std::exp2(std::floor(std::log2(extent)) - 3.0f);
    extent = std::ceil(extent / unit) * unit;
    const float texel = extent / static_cast<float>(resolution);
    centre = glm::floor(centre / texel) * texel;
}

/// Completes an orthographic map of `result.view` over the square at `centre`, `extent` wide, between
/// light-space depths `farthest` and `nearest` widened by `depthMargin`: its projection, texel scale and lit
/// border, the whole texels from the region it must hold (`held`, light-space xy) to the map's edge, less
/// `borderSlack`.
void completeOrthographicMap(LightProjection& result, glm::vec2 centre, float extent, float nearest,
                             float farthest, float depthMargin, int resolution, const Aabb& held,
                             float borderSlack) {
    const glm::vec2 half(0.5f * extent);
    result.projection = glm::ortho(centre.x - half.x, centre.x + half.x, centre.y - half.y, centre.y + half.y,
                                   -nearest - depthMargin, -farthest + depthMargin);
    result.worldToShadow = kClipToTexture * result.projection * result.view;
    result.texelScale = extent / static_cast<float>(resolution);
    const glm::vec2 below = glm::vec2(held.min) - (centre - half);
    const glm::vec2 above = (centre + half) - glm::vec2(held.max);
    const float toEdge = std::min({below.x, below.y, above.x, above.y});
    result.litBorderTexels = std::max(std::floor(toEdge / result.texelScale) - borderSlack, 0.0f);
    result.valid = true;
}

/// The corners of a projection's view volume in view space, and its near and far view depths.
struct FrustumCorners {
    std::array<glm::vec3, 4> nearPoints{};
    std::array<glm::vec3, 4> farPoints{};
    float near = 0.0f;
    float far = 0.0f;
};

FrustumCorners frustumCorners(const glm::mat4& projection) {
    const glm::mat4 clipToView = glm::inverse(projection);
    FrustumCorners corners;
    std::size_t i = 0;
    for (const float x : {-1.0f, 1.0f}) {
        for (const float y : {-1.0f, 1.0f}) {
            const glm::vec4 near = clipToView * glm::vec4(x, y, -1.0f, 1.0f);
            const glm::vec4 far = clipToView * glm::vec4(x, y, 1.0f, 1.0f);
            corners.nearPoints[i] = glm::vec3(near) / near.w;
            corners.farPoints[i] = glm::vec3(far) / far.w;
            ++i;
        }
    }
    corners.near = -corners.nearPoints[0].z;
    corners.far = -corners.farPoints[0].z;
    return corners;
}

} // namespace

Aabb shadowableRegion(const glm::vec3& direction, const glm::mat4& cameraViewProjection,
                      std::span<const Aabb> boxes) {
    const glm::mat4 view = lightRotation(direction);
    Aabb frustum; // the camera frustum in light space
    const glm::mat4 clipToLight = view * glm::inverse(cameraViewProjection);
    for (const float x : {-1.0f, 1.0f}) {
        for (const float y : {-1.0f, 1.0f}) {
            for (const float z : {-1.0f, 1.0f}) {
                const glm::vec4 p = clipToLight * glm::vec4(x, y, z, 1.0f);
                frustum.extend(glm::vec3(p) / p.w);
            }
        }
    }
    // The part of each receiver in view (clipped to the camera frustum's light-space extent) under some
    // caster that reaches nearer the light than the receiver's far side (the light looks down -z). A
    // directional light's shadow falls within its caster's light-space extent, so a model on a large ground
    // plane gets the texels of its own footprint, not of the ground in view.
    std::vector<Aabb> lightBoxes;
    lightBoxes.reserve(boxes.size());
    for (const Aabb& box : boxes) {
        lightBoxes.push_back(box.empty() ? Aabb{} : box.transformed(view));
    }
    Aabb covered;
    for (std::size_t r = 0; r < boxes.size(); ++r) {
        const Aabb visible = visiblePart(boxes[r], cameraViewProjection);
        if (visible.empty()) {
            continue;
        }
        const Aabb receiver = visible.transformed(view);
        const glm::vec2 receiverLow = glm::max(glm::vec2(receiver.min), glm::vec2(frustum.min));
        const glm::vec2 receiverHigh = glm::min(glm::vec2(receiver.max), glm::vec2(frustum.max));
        for (std::size_t c = 0; c < boxes.size(); ++c) {
            const Aabb& caster = lightBoxes[c];
            if (caster.empty() || caster.max.z <= receiver.min.z || (c == r && isPlanar(boxes[r]))) {
                continue;
            }
            const glm::vec2 low = glm::max(receiverLow, glm::vec2(caster.min));
            const glm::vec2 high = glm::min(receiverHigh, glm::vec2(caster.max));
            if (low.x <= high.x && low.y <= high.y) {
                covered.extend(glm::vec3(low, 0.0f));
                covered.extend(glm::vec3(high, 0.0f));
            }
        }
    }
    return covered;
}

LightProjection fitDirectionalLight(const glm::vec3& direction, const glm::mat4& cameraViewProjection,
                                    std::span<const Aabb> boxes, int resolution, bool snapToTexels) {
    LightProjection result;
    result.view = lightRotation(direction);
    // Receivers outside the region are lit (the lighting pass reads nothing there).
    const Aabb covered = shadowableRegion(direction, cameraViewProjection, boxes);
    if (covered.empty()) {
        return result;
    }
    if (covered.min.x >= covered.max.x && covered.min.y >= covered.max.y) {
        return result;
    }
    // A margin of 8 texels keeps the kernels, gathers and central differences of receivers at the region's
    // edge inside the map (the border reads as lit).
    const float margin = 8.0f * std::max(covered.max.x - covered.min.x, covered.max.y - covered.min.y) /
                         static_cast<float>(resolution);
    const glm::vec2 low = glm::vec2(covered.min) - margin;
    const glm::vec2 high = glm::vec2(covered.max) + margin;

    float extent = std::max(high.x - low.x, high.y - low.y);
    glm::vec2 centre = 0.5f * (low + high);
    if (snapToTexels) {
        snapSquare(extent, centre, resolution);
    }
    const glm::vec2 half(0.5f * extent);
    // Depth: the parts of the boxes over the map, towards the light and beyond the receivers. Only
    // those parts: a large ground plane tilted in light space would otherwise stretch the range over all of
    // itself, and filtered moments lose the depth differences of small casters in a long range.
    float nearest = -std::numeric_limits<float>::max();
    float farthest = std::numeric_limits<float>::max();
    for (const Aabb& box : boxes) {
        if (const std::optional<glm::vec2> span =
                depthSpanOver(box, result.view, centre - half, centre + half)) {
            farthest = std::min(farthest, span->x);
            nearest = std::max(nearest, span->y);
        }
    }
    if (farthest > nearest) {
        return result;
    }
    const float depthMargin = 0.01f * std::max(nearest - farthest, 1e-3f);
    completeOrthographicMap(result, centre, extent, nearest, farthest, depthMargin, resolution, covered,
                            0.0f);
    return result;
}

glm::mat4 lightView(const glm::vec3& direction) {
    return lightRotation(direction);
}

glm::dmat4 textureRectClip(glm::dvec2 low, glm::dvec2 size) {
    // x' / w = 2 (x_tex - low) / size - 1 with x_tex = (x / w + 1) / 2, so x' = (x + w (1 - 2 low)) / size -
    // w, linear in clip space.
    glm::dmat4 crop(1.0);
    crop[0][0] = 1.0 / size.x;
    crop[1][1] = 1.0 / size.y;
    crop[3][0] = (1.0 - 2.0 * low.x) / size.x - 1.0;
    crop[3][1] = (1.0 - 2.0 * low.y) / size.y - 1.0;
    return crop;
}

LightProjection fitToSamples(const glm::vec3& direction, const LightRect& samples,
                             std::span<const Aabb> boxes, int resolution, float marginTexels,
                             bool snapToTexels, SoftMargin soft, const LightRect* visible,
                             std::span<const LightProjection> kept) {
    LightProjection result;
    const glm::vec3 size = samples.max - samples.min;
    if (samples.empty() || resolution < 16 || !(size.x >= 0.0f && size.y >= 0.0f && size.z >= 0.0f) ||
        !std::isfinite(size.x) || !std::isfinite(size.y) || !std::isfinite(size.z)) {
        return result;
    }
    result.view = lightRotation(direction);
    // The nearest caster (towards the light) over a square of side `extent` around `centre`.
    const auto nearestCaster = [&](float extent, glm::vec2 centre) {
        const glm::vec2 half(0.5f * extent);
        float nearest = samples.max.z;
        for (const Aabb& box : boxes) {
            if (const std::optional<glm::vec2> span =
                    depthSpanOver(box, result.view, centre - half, centre + half)) {
                nearest = std::max(nearest, span->y);
            }
        }
        return nearest;
    };
    const float samplesExtent = std::max({size.x, size.y, 1e-6f * std::max(glm::length(samples.max), 1.0f)});
    glm::vec2 centre = 0.5f * (glm::vec2(samples.min) + glm::vec2(samples.max));
    // The soft margin: the widest penumbra over the samples, in texels of a map fitted without it (the final
    // texel is no smaller, so that many of its texels hold the penumbra).
    const float hardMargin = std::max(marginTexels, 0.0f);
    float softTexels = std::max(soft.texels, 0.0f);
    if (soft.perDepth > 0.0f && std::isfinite(soft.perDepth)) {
        const float texel =
            samplesExtent /
            std::max(static_cast<float>(resolution) - 2.0f * (hardMargin + softTexels + 1.0f), 1.0f);
        const float widest = soft.perDepth * (nearestCaster(samplesExtent, centre) - samples.min.z) / texel;
        if (std::isfinite(widest)) {
            softTexels = std::max(softTexels, std::min(widest, 0.125f * static_cast<float>(resolution)));
        }
    }
    result.softReachTexels = softTexels;
    // The samples, their kernels' reach and a texel of slack for the snapped origin inside the map: the texel
    // follows from fitting that many texels fewer than the resolution across the samples' box.
    const float slack = hardMargin + softTexels + 1.0f;
    float extent = samplesExtent * static_cast<float>(resolution) /
                   std::max(static_cast<float>(resolution) - 2.0f * slack, 1.0f);
    if (snapToTexels) {
        snapSquare(extent, centre, resolution);
        // An earlier square of this side on this grid keeps its place while it gives the samples the margin
        // the new one would (all but the snapping's texel): the map drawn there holds every texel they read.
        const float margin = (slack - 1.0f) * extent / static_cast<float>(resolution);
        for (const LightProjection& earlier : kept) {
            const glm::vec2 half(0.5f * earlier.square.z);
            if (earlier.valid && earlier.square.z == extent &&
                earlier.texelScale == extent / static_cast<float>(resolution) &&
                glm::all(glm::greaterThanEqual(glm::vec2(samples.min) - margin,
                                               glm::vec2(earlier.square) - half)) &&
                glm::all(
                    glm::lessThanEqual(glm::vec2(samples.max) + margin, glm::vec2(earlier.square) + half))) {
                centre = glm::vec2(earlier.square);
                break;
            }
        }
    }
    float nearest = nearestCaster(extent, centre);
    float farthest = samples.min.z;
    const float span = std::max(nearest - farthest, 1e-6f * std::max(std::abs(nearest), 1.0f));
    float depthMargin = 0.01f * span;
    if (snapToTexels) {
        const float step = std::exp2(std::floor(std::log2(span)) - 3.0f);
        nearest = std::ceil((nearest + depthMargin) / step) * step;
        farthest = std::floor((farthest - depthMargin) / step) * step;
        depthMargin = 0.0f;
    }
    constexpr float kReceiverOffsetTexels = 2.0f;
    completeOrthographicMap(result, centre, extent, nearest, farthest, depthMargin, resolution,
                            Aabb{samples.min, samples.max}, kReceiverOffsetTexels);
    result.square = glm::vec3(centre, extent);
    // A sample's lookup lies within its offsets of it and reads within the kernels' reach of that.
    const float reach = (slack + kReceiverOffsetTexels) * result.texelScale;
    const glm::vec2 origin = centre - glm::vec2(0.5f * extent);
    const LightRect& read = visible != nullptr && !visible->empty() ? *visible : samples;
    const glm::vec2 low = glm::clamp((glm::vec2(read.min) - reach - origin) / extent, 0.0f, 1.0f);
    const glm::vec2 high = glm::clamp((glm::vec2(read.max) + reach - origin) / extent, 0.0f, 1.0f);
    const glm::vec4 region(low, high);
    if (std::isfinite(region.x) && std::isfinite(region.y) && std::isfinite(region.z) &&
        std::isfinite(region.w)) {
        result.drawnRegion = region;
    }
    return result;
}

LightProjection fitSpotLight(const glm::vec3& position, const glm::vec3& direction, float outerConeAngle,
                             float range, std::span<const Aabb> boxes, int resolution) {
    const glm::mat4 view = lightRotation(direction) * glm::translate(glm::mat4(1.0f), -position);
    const float fov = std::min(2.0f * outerConeAngle + 0.02f, 3.0f);
    return perspectiveMap(view, fov, range, boxes, resolution);
}

std::vector<float> cascadeSplits(float near, float far, int count, float weight) {
    std::vector<float> splits(static_cast<std::size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const float fraction = static_cast<float>(i) / static_cast<float>(count);
        const float logarithmic = near * std::pow(far / near, fraction);
        const float uniform = near + (far - near) * fraction;
        splits[static_cast<std::size_t>(i)] = weight * logarithmic + (1.0f - weight) * uniform;
    }
    splits.front() = near;
    splits.back() = far;
    return splits;
}

std::optional<glm::vec2> visibleDepthRange(const FitView& view, std::span<const Aabb> boxes) {
    const FrustumCorners corners = frustumCorners(view.projection);
    const glm::mat4 viewProjection = view.projection * view.view;
    glm::vec2 range(std::numeric_limits<float>::max(), -std::numeric_limits<float>::max());
    for (const Aabb& box : boxes) {
        if (box.empty() || !engine::intersectsClipVolume(box, viewProjection)) {
            continue;
        }
        const Aabb inView = box.transformed(view.view);
        range.x = std::min(range.x, -inView.max.z);
        range.y = std::max(range.y, -inView.min.z);
    }
    range = glm::clamp(range, glm::vec2(corners.near), glm::vec2(corners.far));
    if (!(range.y > range.x)) {
        return std::nullopt;
    }
    // 1/8-octave steps: the range moves only when a receiver enters or leaves the view, or crosses a step.
    const auto step = [](float depth, bool up) {
        const float octaves = 8.0f * std::log2(depth);
        return std::exp2((up ? std::ceil(octaves) : std::floor(octaves)) / 8.0f);
    };
    return glm::clamp(glm::vec2(step(range.x, false), step(range.y, true)), glm::vec2(corners.near),
                      glm::vec2(corners.far));
}

int automaticCascadeCount(glm::vec2 depthRange) {
    if (!(depthRange.x > 0.0f) || !(depthRange.y > depthRange.x)) {
        return 1;
    }
    const float decades = std::log10(depthRange.y / depthRange.x);
    return std::clamp(static_cast<int>(std::floor(decades)) - 1, 1, kMaxCascades);
}

bool hasReceiversBetween(const FitView& view, std::span<const Aabb> boxes, float near, float far) {
    const glm::mat4 viewProjection = view.projection * view.view;
    for (const Aabb& box : boxes) {
        if (box.empty() || !engine::intersectsClipVolume(box, viewProjection)) {
            continue;
        }
        const Aabb inView = box.transformed(view.view);
        if (-inView.min.z >= near && -inView.max.z <= far) {
            return true;
        }
    }
    return false;
}

Sphere frustumSliceSphere(const glm::mat4& projection, float sliceNear, float sliceFar) {
    const FrustumCorners corners = frustumCorners(projection);
    const float span = std::max(corners.far - corners.near, 1e-30f);
    std::array<glm::vec3, 8> slice{};
    glm::vec3 nearCentre(0.0f);
    glm::vec3 farCentre(0.0f);
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::vec3 edge = corners.farPoints[i] - corners.nearPoints[i];
        slice[i] = corners.nearPoints[i] + edge * ((sliceNear - corners.near) / span);
        slice[i + 4] = corners.nearPoints[i] + edge * ((sliceFar - corners.near) / span);
        nearCentre += 0.25f * slice[i];
        farCentre += 0.25f * slice[i + 4];
    }
    float a = 0.0f; // half-diagonals of the slice's near and far faces
    float b = 0.0f;
    for (std::size_t i = 0; i < 4; ++i) {
        a = std::max(a, glm::length(slice[i] - nearCentre));
        b = std::max(b, glm::length(slice[i + 4] - farCentre));
    }
    // On the axis at t from the near face, the farthest corners are sqrt(a² + t²) and sqrt(b² + (L − t)²)
    // away; they are equal at t = (b² − a² + L²) / 2L (clamped to the slice).
    const float length = glm::length(farCentre - nearCentre);
    Sphere sphere;
    sphere.centre = nearCentre;
    if (length > 0.0f) {
        const float t = std::clamp((b * b - a * a + length * length) / (2.0f * length), 0.0f, length);
        sphere.centre = nearCentre + (farCentre - nearCentre) * (t / length);
    }
    for (const glm::vec3& corner : slice) {
        sphere.radius = std::max(sphere.radius, glm::length(corner - sphere.centre));
    }
    return sphere;
}

LightProjection fitCascade(const glm::vec3& direction, const FitView& view, float sliceNear, float sliceFar,
                           std::span<const Aabb> boxes, int resolution, bool snapToTexels) {
    LightProjection result;
    if (!(sliceFar > sliceNear) || resolution < 4) {
        return result;
    }
    result.view = lightRotation(direction);
    const Sphere sphere = frustumSliceSphere(view.projection, sliceNear, sliceFar);
    const glm::vec3 centre =
        glm::vec3(result.view * glm::inverse(view.view) * glm::vec4(sphere.centre, 1.0f));
    // Two texels of slack so the square still holds the sphere after its centre snaps by up to a texel.
    const float texel = 2.0f * sphere.radius / static_cast<float>(resolution - 2);
    const float half = 0.5f * texel * static_cast<float>(resolution);
    glm::vec2 middle(centre);
    if (snapToTexels) {
        middle = glm::floor(middle / texel) * texel; // the texel grid stays put in world space
    }
    float top = centre.z + sphere.radius;
    float bottom = centre.z - sphere.radius;
    for (const Aabb& box : boxes) {
        if (const std::optional<glm::vec2> span =
                depthSpanOver(box, result.view, middle - glm::vec2(half), middle + glm::vec2(half))) {
            top = std::max(top, span->y);
        }
    }
    if (snapToTexels) {
        // Depth moves in steps of a quarter radius, so the stored depths keep their values too.
        const float step = 0.25f * sphere.radius;
        top = std::ceil(top / step) * step;
        bottom = std::floor(bottom / step) * step;
    }
    result.projection =
        glm::ortho(middle.x - half, middle.x + half, middle.y - half, middle.y + half, -top, -bottom);
    result.worldToShadow = kClipToTexture * result.projection * result.view;
    result.texelScale = texel;
    result.valid = true;
    return result;
}

glm::vec3 cubeFaceAxis(int face) {
    glm::vec3 axis(0.0f);
    axis[face / 2] = face % 2 == 0 ? 1.0f : -1.0f;
    return axis;
}

float cubeFaceFieldOfView(int resolution, float marginTexels) {
    const float r = static_cast<float>(resolution);
    const float margin = std::clamp(marginTexels, 0.0f, 0.25f * r);
    return 2.0f * std::atan(r / (r - 2.0f * margin));
}

LightProjection fitPointLightFace(const glm::vec3& position, int face, float range,
                                  const glm::mat4& cameraViewProjection, std::span<const Aabb> boxes,
                                  int resolution, float marginTexels) {
    const glm::mat4 view = lightRotation(cubeFaceAxis(face)) * glm::translate(glm::mat4(1.0f), -position);
    const float fov = cubeFaceFieldOfView(resolution, marginTexels);
    // The face's frustum out to the farthest box, to find which boxes it sees.
    float reach = 0.0f;
    for (const Aabb& box : boxes) {
        if (!box.empty()) {
            reach = std::max(
                reach, glm::length(glm::max(glm::abs(box.min - position), glm::abs(box.max - position))));
        }
    }
    if (range > 0.0f) {
        reach = std::min(reach, range);
    }
    if (!(reach > 0.0f)) {
        return {};
    }
    const glm::mat4 faceVolume = glm::perspective(fov, 1.0f, reach * 1e-6f, reach) * view;
    std::vector<Aabb> seen;
    bool receives = false;
    for (const Aabb& box : boxes) {
        if (meetsVolume(box, faceVolume)) {
            seen.push_back(box);
            receives = receives || meetsVolume(visiblePart(box, cameraViewProjection), faceVolume);
        }
    }
    if (!receives) {
        return {};
    }
    return perspectiveMap(view, fov, range, seen, resolution);
}

} // namespace shadows
