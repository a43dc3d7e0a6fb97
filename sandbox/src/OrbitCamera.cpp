#include "OrbitCamera.h"

#include "ParameterTable.h"

#include <algorithm>
#include <cmath>

namespace sandbox {

namespace {

/// Unit vector from the target to the eye.
glm::vec3 offsetDirection(float yawDegrees, float pitchDegrees) {
    const float yaw = glm::radians(yawDegrees);
    const float pitch = glm::radians(pitchDegrees);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

} // namespace

OrbitCamera OrbitCamera::lookingFrom(const glm::vec3& eye, const glm::vec3& forward, const glm::vec3& pivot) {
    const glm::vec3 f = glm::normalize(forward);
    OrbitCamera camera;
    camera.pitch = std::clamp(glm::degrees(std::asin(std::clamp(-f.y, -1.0f, 1.0f))),
                              ParameterTable::kPitch.min, ParameterTable::kPitch.max);
    camera.yaw = glm::degrees(std::atan2(-f.x, -f.z));
    if (camera.yaw < 0.0f) {
        camera.yaw += 360.0f;
    }
    // Keep the eye where it is: the target lies on the (pitch-clamped) view ray.
    camera.distance = std::clamp(glm::dot(pivot - eye, f), ParameterTable::kDistance.min * 10.0f,
                                 ParameterTable::kDistance.max);
    camera.target = eye - offsetDirection(camera.yaw, camera.pitch) * camera.distance;
    return camera;
}

glm::vec3 OrbitCamera::eye() const {
    return target + offsetDirection(yaw, pitch) * distance;
}

engine::Transform OrbitCamera::transform() const {
    return engine::Transform::lookAt(eye(), target);
}

void OrbitCamera::orbit(float yawDegrees, float pitchDegrees) {
    yaw = std::fmod(yaw + yawDegrees, 360.0f);
    if (yaw < 0.0f) {
        yaw += 360.0f;
    }
    pitch = std::clamp(pitch + pitchDegrees, ParameterTable::kPitch.min, ParameterTable::kPitch.max);
}

void OrbitCamera::pan(float right, float up) {
    const engine::Transform view = transform();
    const glm::vec3 rightAxis = view.rotation * glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 upAxis = view.rotation * glm::vec3(0.0f, 1.0f, 0.0f);
    target += (rightAxis * right + upAxis * up) * distance;
}

void OrbitCamera::zoom(float factor) {
    distance = std::clamp(distance * factor, ParameterTable::kDistance.min, ParameterTable::kDistance.max);
}

} // namespace sandbox
