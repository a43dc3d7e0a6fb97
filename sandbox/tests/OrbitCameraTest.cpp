// The orbit camera reproduces a scene camera and moves as documented (no GL).
#include "OrbitCamera.h"
#include "ParameterTable.h"

#include <gtest/gtest.h>

using sandbox::OrbitCamera;

namespace {

glm::vec3 forwardOf(const engine::Transform& transform) {
    return transform.rotation * glm::vec3(0.0f, 0.0f, -1.0f);
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    EXPECT_LT(glm::length(a - b), tolerance)
        << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")";
}

} // namespace

TEST(OrbitCameraTest, LookingFromKeepsEyeAndDirection) {
    const glm::vec3 eye(3.2f, 2.4f, 4.2f);
    const glm::vec3 forward = glm::normalize(glm::vec3(0.0f, 0.5f, 0.0f) - eye);
    const OrbitCamera camera = OrbitCamera::lookingFrom(eye, forward, glm::vec3(0.0f, 0.6f, 0.0f));
    expectNear(camera.eye(), eye, 1e-4f);
    expectNear(forwardOf(camera.transform()), forward, 1e-4f);
    EXPECT_NEAR(glm::dot(camera.target - eye, forward), camera.distance, 1e-4f);
}

TEST(OrbitCameraTest, OrbitKeepsTheTargetAndDistanceAndClampsPitch) {
    OrbitCamera camera{{1.0f, 2.0f, 3.0f}, 10.0f, 20.0f, 4.0f};
    camera.orbit(-30.0f, 200.0f);
    EXPECT_FLOAT_EQ(camera.yaw, 340.0f);
    EXPECT_FLOAT_EQ(camera.pitch, sandbox::ParameterTable::kPitch.max);
    EXPECT_NEAR(glm::length(camera.eye() - camera.target), 4.0f, 1e-4f);
    expectNear(forwardOf(camera.transform()), glm::normalize(camera.target - camera.eye()), 1e-4f);
}

TEST(OrbitCameraTest, PanMovesEyeAndTargetTogetherAndZoomClamps) {
    OrbitCamera camera{{0.0f, 0.0f, 0.0f}, 0.0f, 0.0f, 2.0f};
    const glm::vec3 eye = camera.eye();
    camera.pan(0.5f, 0.25f);
    expectNear(camera.target, glm::vec3(1.0f, 0.5f, 0.0f), 1e-5f); // looking along -Z: right is +X
    expectNear(camera.eye() - camera.target, eye, 1e-5f);
    camera.zoom(1e-6f);
    EXPECT_EQ(camera.distance, sandbox::ParameterTable::kDistance.min);
}
