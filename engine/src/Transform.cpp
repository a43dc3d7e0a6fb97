#include <engine/Transform.h>

#include <glm/gtc/matrix_transform.hpp>

namespace engine {

glm::mat4 Transform::matrix() const {
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

Transform Transform::lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 forward = glm::normalize(target - eye);
    // An up vector parallel to the view direction leaves the basis undefined: pick another axis.
    const glm::vec3 safeUp = glm::length(glm::cross(forward, up)) < 1e-6f
                                 ? (std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0))
                                 : up;
    const glm::vec3 right = glm::normalize(glm::cross(forward, safeUp));
    const glm::vec3 trueUp = glm::cross(right, forward);
    Transform result;
    result.translation = eye;
    result.rotation = glm::quat_cast(glm::mat3(right, trueUp, -forward));
    return result;
}

} // namespace engine
