#include <engine/Components.h>
#include <engine/Error.h>

#include <glm/gtc/matrix_transform.hpp>

namespace engine {

const char* toString(LightType type) {
    switch (type) {
    case LightType::Directional:
        return "directional";
    case LightType::Spot:
        return "spot";
    case LightType::Point:
        return "point";
    }
    throw Error("unknown light type " + std::to_string(static_cast<int>(type)));
}

glm::mat4 CameraComponent::projectionMatrix(float aspect) const {
    if (projection == ProjectionType::Orthographic) {
        const float halfHeight = orthographicHeight * 0.5f;
        const float halfWidth = halfHeight * aspect;
        return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane);
    }
    return glm::perspective(verticalFov, aspect, nearPlane, farPlane);
}

} // namespace engine
