#include "DefaultScene.h"

#include <engine/Primitives.h>

#include <glm/gtc/quaternion.hpp>

#include <memory>

engine::Scene makeDefaultScene() {
    using namespace engine;
    Scene scene;

    const EntityId ground = scene.create("ground");
    auto plane = std::make_shared<MeshData>(primitives::plane(12.0f, 4));
    plane->material.baseColor = {0.7f, 0.7f, 0.65f};
    scene.entity(ground).mesh = MeshComponent{plane};

    const EntityId cube = scene.create("cube");
    auto cubeMesh = std::make_shared<MeshData>(primitives::cube(1.5f));
    cubeMesh->material.baseColor = {0.8f, 0.25f, 0.2f};
    scene.entity(cube).mesh = MeshComponent{cubeMesh};
    scene.entity(cube).transform.translation = {-1.2f, 0.75f, 0.0f};
    scene.entity(cube).transform.rotation = glm::angleAxis(0.5f, glm::vec3(0, 1, 0));

    const EntityId ball = scene.create("sphere");
    auto sphereMesh = std::make_shared<MeshData>(primitives::sphere(0.8f, 24, 48));
    sphereMesh->material.baseColor = {0.2f, 0.4f, 0.8f};
    sphereMesh->material.specularColor = glm::vec3(0.3f);
    sphereMesh->material.shininess = 64.0f;
    scene.entity(ball).mesh = MeshComponent{sphereMesh};
    scene.entity(ball).transform.translation = {1.3f, 0.8f, 0.5f};

    const EntityId sun = scene.create("sun");
    scene.entity(sun).light = LightComponent{};
    scene.entity(sun).light->intensity = 1.1f;
    scene.entity(sun).transform = Transform::lookAt({4.0f, 8.0f, 3.0f}, {0.0f, 0.0f, 0.0f});

    const EntityId camera = scene.create("camera");
    scene.entity(camera).camera = CameraComponent{};
    scene.entity(camera).transform = Transform::lookAt({0.0f, 4.0f, 8.0f}, {0.0f, 0.5f, 0.0f});
    return scene;
}
