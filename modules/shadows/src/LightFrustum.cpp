#include <shadows/LightFrustum.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
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

} // namespace

LightProjection fitDirectionalLight(const glm::vec3& direction, const glm::mat4& cameraViewProjection,
                                    std::span<const Aabb> boxes, int resolution, bool snapToTexels) {
    LightProjection result;
    result.view = lightRotation(direction);

    Aabb frustum; // the camera frustum in light space
    const glm::mat4 clipToLight = result.view * glm::inverse(cameraViewProjection);
    for (const float x : {-1.0f, 1.0f}) {
        for (const float y : {-1.0f, 1.0f}) {
            for (const float z : {-1.0f, 1.0f}) {
                const glm::vec4 p = clipToLight * glm::vec4(x, y, z, 1.0f);
                frustum.extend(glm::vec3(p) / p.w);
            }
        }
    }
    Aabb receivers;
    for (const Aabb& box : boxes) {
        if (!box.empty() && engine::intersectsClipVolume(box, cameraViewProjection)) {
            const Aabb light = box.transformed(result.view);
            receivers.extend(light.min);
            receivers.extend(light.max);
        }
    }
    if (receivers.empty()) {
        return result;
    }
    glm::vec2 low = glm::max(glm::vec2(receivers.min), glm::vec2(frustum.min));
    glm::vec2 high = glm::min(glm::vec2(receivers.max), glm::vec2(frustum.max));
    if (low.x >= high.x || low.y >= high.y) {
        return result;
    }
    // Depth: everything overlapping the covered region, towards the light and beyond the receivers.
    float nearest = -std::numeric_limits<float>::max();
    float farthest = std::numeric_limits<float>::max();
    for (const Aabb& box : boxes) {
        if (box.empty()) {
            continue;
        }
        const Aabb light = box.transformed(result.view);
        if (light.max.x < low.x || light.min.x > high.x || light.max.y < low.y || light.min.y > high.y) {
            continue;
        }
        nearest = std::max(nearest, light.max.z);
        farthest = std::min(farthest, light.min.z);
    }
    const float depthMargin = 0.01f * std::max(nearest - farthest, 1e-3f);

    float extent = std::max(high.x - low.x, high.y - low.y);
    glm::vec2 centre = 0.5f * (low + high);
    if (snapToTexels) {
        // Quantise the extent to 1/8-octave steps so it changes rarely, then the origin to whole texels.
        const float unit = std::exp2(std::floor(std::log2(extent)) - 3.0f);
        extent = std::ceil(extent / unit) * unit;
        const float texel = extent / static_cast<float>(resolution);
        centre = glm::floor(centre / texel) * texel;
    }
    const glm::vec2 half(0.5f * extent);
    result.projection = glm::ortho(centre.x - half.x, centre.x + half.x, centre.y - half.y, centre.y + half.y,
                                   -nearest - depthMargin, -farthest + depthMargin);
    result.worldToShadow = kClipToTexture * result.projection * result.view;
    result.texelScale = extent / static_cast<float>(resolution);
    result.valid = true;
    return result;
}

LightProjection fitSpotLight(const glm::vec3& position, const glm::vec3& direction, float outerConeAngle,
                             float range, std::span<const Aabb> boxes, int resolution) {
    LightProjection result;
    result.perspective = true;
    result.view = lightRotation(direction) * glm::translate(glm::mat4(1.0f), -position);
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
    const float fov = std::min(2.0f * outerConeAngle + 0.02f, 3.0f);
    result.projection = glm::perspective(fov, 1.0f, nearest, farthest * 1.01f);
    result.depthRange = {nearest, farthest * 1.01f};
    result.worldToShadow = kClipToTexture * result.projection * result.view;
    result.texelScale = 2.0f * std::tan(0.5f * fov) / static_cast<float>(resolution);
    result.valid = true;
    return result;
}

} // namespace shadows
