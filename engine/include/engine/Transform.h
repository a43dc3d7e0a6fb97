#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace engine {

/// @brief Local transform of an entity relative to its parent: scale, then rotate, then translate.
struct Transform {
    /// Translation in parent units. Default origin.
    glm::vec3 translation{0.0f};
    /// Rotation as a unit quaternion. Default identity.
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    /// Per-axis scale, dimensionless. Default 1.
    glm::vec3 scale{1.0f};

    /// @brief The matrix T * R * S.
    [[nodiscard]] glm::mat4 matrix() const;

    /// @brief A transform at `eye` whose -Z axis points at `target` (the camera/light convention).
    /// Falls back to another up vector when `up` is parallel to the view direction.
    static Transform lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up = {0, 1, 0});
};

} // namespace engine
