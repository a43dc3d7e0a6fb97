#pragma once

#include <engine/Bounds.h>

#include <glm/glm.hpp>

#include <array>
#include <limits>
#include <span>

namespace shadows {

/// @brief World-space axis-aligned box (the engine's).
using Aabb = engine::Aabb;

/// @brief The view and projection a shadow map is rendered with.
struct LightProjection {
    /// World → light view space.
    glm::mat4 view{1.0f};
    /// Light view → clip space (orthographic for directional lights, perspective for spots).
    glm::mat4 projection{1.0f};
    /// World → shadow texture space: xy in [0,1] over the map, z the stored depth in [0,1] (after divide by
    /// w).
    glm::mat4 worldToShadow{1.0f};
    /// Whether `projection` is perspective (a spot light's).
    bool perspective = false;
    /// Orthographic: world size of one texel. Perspective: 2·tan(fov/2)/resolution (times distance = texel
    /// size).
    float texelScale = 0.0f;
    /// Perspective: the near and far plane distances; zero for orthographic maps (gsLinearDepth).
    glm::vec2 depthRange{0.0f};
    /// False when nothing visible can receive a shadow from this light (no map needs drawing).
    bool valid = false;
};

/// @brief Fits an orthographic shadow frustum for a directional light shining along `direction`.
///
/// Receivers are the boxes that intersect the camera frustum (`cameraViewProjection`); the map covers the
/// part of them the camera can see (their light-space extent clipped to the camera frustum's), and its depth
/// range extends towards the light over every box that overlaps that region, so casters outside the view
/// still cast. With `snapToTexels`, the extent is quantised to 1/8-octave steps and the origin to whole
/// texels, so a moving camera does not make shadow edges shimmer.
LightProjection fitDirectionalLight(const glm::vec3& direction, const glm::mat4& cameraViewProjection,
                                    std::span<const Aabb> boxes, int resolution, bool snapToTexels);

/// @brief Fits a perspective shadow frustum for a spot light at `position` shining along `direction` with
/// cone half-angle `outerConeAngle` (radians); near and far planes bound the boxes in front of the light (and
/// `range` when it is positive).
LightProjection fitSpotLight(const glm::vec3& position, const glm::vec3& direction, float outerConeAngle,
                             float range, std::span<const Aabb> boxes, int resolution);

} // namespace shadows
