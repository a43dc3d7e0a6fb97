#pragma once

#include <engine/MeshData.h>

#include <glm/glm.hpp>

#include <array>
#include <limits>
#include <memory>

namespace engine {

/// @brief Draws a mesh with the entity's world transform.
struct MeshComponent {
    std::shared_ptr<const MeshData> mesh;
};

/// @brief The KHR_lights_punctual light types: a sun (parallel light), a cone from a point, every direction
/// from a point.
enum class LightType { Directional, Spot, Point };

/// @brief Every LightType, for code that offers or cycles through them all.
inline constexpr std::array kLightTypes{LightType::Directional, LightType::Spot, LightType::Point};

/// @brief The KHR_lights_punctual name of `type`: "directional", "spot" or "point".
[[nodiscard]] const char* toString(LightType type);

/// @brief A light; directional and spot lights shine along the entity's local -Z axis; spot and point lights
/// shine from the entity's position and fall off with the inverse square of the distance, windowed by
/// `range` (KHR_lights_punctual, "Range Property").
struct LightComponent {
    LightType type = LightType::Directional;
    /// Linear RGB colour. Default white.
    glm::vec3 color{1.0f};
    /// Scale on colour: irradiance for directional lights, intensity (irradiance at distance 1) for spot and
    /// point lights. Default 1.
    float intensity = 1.0f;
    /// Whether shadow modules should make a shadow map for this light. Default true.
    bool castsShadows = true;
    /// Spot and point only: distance in world units beyond which the light has no effect; the inverse square
    /// is multiplied by clamp(1 - (d / range)^4, 0, 1), so it reaches zero smoothly there. 0 = unlimited
    /// (plain inverse square). Default 0.
    float range = 0.0f;
    /// Spot only: half-angle in radians where the falloff starts. Default 0.4 rad (~23°).
    float innerConeAngle = 0.4f;
    /// Spot only: half-angle in radians where the light reaches zero. Default 0.5 rad (~29°).
    float outerConeAngle = 0.5f;
    /// Directional only: the angular diameter of the light's disk, radians, for soft shadows. Default the
    /// sun's, 0.53° (0.00925 rad); 0 is a point at infinity.
    float angularDiameter = kSunAngularDiameter;
    /// Spot and point only: the radius of the light's sphere, world units, for soft shadows. Default 0, a
    /// point.
    float radius = 0.0f;

    /// @brief Where the light's size (angularDiameter for a directional light, radius for a spot or point
    /// light) must stay below: a hemisphere for a sun, the range (or the largest float) for a local light.
    [[nodiscard]] float sizeLimit() const {
        return type == LightType::Directional ? kMaxAngularDiameter
               : range > 0.0f                 ? range
                                              : std::numeric_limits<float>::max();
    }

    /// @brief The sun's mean angular diameter seen from the Earth, 0.53°, in radians.
    static constexpr float kSunAngularDiameter = 0.53f * 3.14159265358979f / 180.0f;
    /// @brief Largest angular diameter a directional light may have, radians: a disk wider than a hemisphere
    /// is no longer a direction.
    static constexpr float kMaxAngularDiameter = 3.14159265358979f / 2.0f;

    bool operator==(const LightComponent&) const = default;
};

enum class ProjectionType { Perspective, Orthographic };

/// @brief A camera looking along the entity's local -Z axis.
struct CameraComponent {
    ProjectionType projection = ProjectionType::Perspective;
    /// Perspective only: vertical field of view in radians. Default 0.8 rad (~46°).
    float verticalFov = 0.8f;
    /// Orthographic only: full height of the view volume in world units. Default 10.
    float orthographicHeight = 10.0f;
    /// Near plane distance, world units, > 0. Default 0.1.
    float nearPlane = 0.1f;
    /// Far plane distance, world units, > nearPlane. Default 100.
    float farPlane = 100.0f;

    /// @brief OpenGL clip-space projection for a viewport of the given width/height ratio.
    [[nodiscard]] glm::mat4 projectionMatrix(float aspect) const;
};

} // namespace engine
