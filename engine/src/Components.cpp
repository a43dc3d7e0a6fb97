#include <engine/Components.h>

#include <glm/gtc/matrix_transform.hpp>

namespace engine {

glm::mat4 CameraComponent::projectionMatrix(float aspect) const {
    if (projection == ProjectionType::Orthographic) {
        const float halfHeight = orthographicHeight * 0.5f;
        const float halfWidth = halfHeight * aspect;
        return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane);
    }
    return glm::perspective(verticalFov, aspect, nearPlane, farPlane);
}

} // namespace engine
