#pragma once

#include <engine/Primitives.h>
#include <engine/Scene.h>

#include <glm/glm.hpp>

#include <cmath>
#include <memory>

/// @brief Linear → sRGB byte, the encoding GL_FRAMEBUFFER_SRGB applies (IEC 61966-2-1).
inline int srgbByte(float linear) {
    linear = glm::clamp(linear, 0.0f, 1.0f);
    const float encoded =
        linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<int>(std::lround(encoded * 255.0f));
}

/// @brief A 2-unit cube at the origin whose +Z face fills the centre of an orthographic view from +Z.
struct LitCubeScene {
    engine::Scene scene;
    engine::EntityId cube;
    engine::EntityId camera;
    std::shared_ptr<engine::MeshData> mesh;

    explicit LitCubeScene(glm::vec3 baseColor = {0.5f, 0.25f, 0.125f}) {
        using namespace engine;
        mesh = std::make_shared<MeshData>(primitives::cube(2.0f));
        mesh->material.baseColor = baseColor;
        mesh->material.specularColor = glm::vec3(0.0f);
        cube = scene.create("cube");
        scene.entity(cube).mesh = MeshComponent{mesh};
        camera = scene.create("camera");
        CameraComponent lens;
        lens.projection = ProjectionType::Orthographic;
        lens.orthographicHeight = 4.0f;
        lens.nearPlane = 0.1f;
        lens.farPlane = 20.0f;
        scene.entity(camera).camera = lens;
        scene.entity(camera).transform = Transform::lookAt({0, 0, 5}, {0, 0, 0});
    }

    /// @brief Adds a directional light whose direction makes `angle` radians with the +Z face normal.
    engine::EntityId addDirectionalLight(float angle, float intensity) {
        const engine::EntityId light = scene.create("sun");
        scene.entity(light).light = engine::LightComponent{};
        scene.entity(light).light->intensity = intensity;
        scene.entity(light).transform =
            engine::Transform::lookAt(5.0f * glm::vec3(std::sin(angle), 0.0f, std::cos(angle)), {0, 0, 0});
        return light;
    }
};
