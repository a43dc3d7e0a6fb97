#pragma once

#include <engine/Transform.h>

#include <glm/glm.hpp>

namespace sandbox {

/// @brief A camera orbiting a target point: yaw and pitch (degrees) of the eye around the target, and its
/// distance. Plain data, compared exactly, saved in sandbox settings files.
struct OrbitCamera {
    /// Point the camera looks at and orbits around, world units.
    glm::vec3 target{0.0f};
    /// Angle of the eye around the up axis (+Y), degrees, measured from +Z towards +X.
    float yaw = 0.0f;
    /// Angle of the eye above the target's horizontal plane, degrees (ParameterTable::kPitch).
    float pitch = 30.0f;
    /// Eye to target, world units (ParameterTable::kDistance).
    float distance = 5.0f;

    /// @brief The orbit that reproduces a camera at `eye` looking along `forward` (roll is dropped), with
    /// the target where the view ray passes closest to `pivot` (at least a small distance ahead).
    static OrbitCamera lookingFrom(const glm::vec3& eye, const glm::vec3& forward, const glm::vec3& pivot);

    /// @brief Eye position, world units.
    [[nodiscard]] glm::vec3 eye() const;
    /// @brief The camera transform: at eye(), -Z towards the target, +Y up.
    [[nodiscard]] engine::Transform transform() const;

    /// @brief Turns the eye around the target by the given degrees (pitch clamped to ParameterTable::kPitch).
    void orbit(float yawDegrees, float pitchDegrees);
    /// @brief Moves target and eye together in the view plane by fractions of the distance (right, up).
    void pan(float right, float up);
    /// @brief Multiplies the distance by `factor` (clamped to ParameterTable::kDistance).
    void zoom(float factor);

    bool operator==(const OrbitCamera&) const = default;
};

} // namespace sandbox
