#include "SceneBuilder.h"

#include "content/CageLoader.h"
#include "content/SubdivisionSurface.h"

#include <engine/Primitives.h>

#include <glm/gtc/quaternion.hpp>

#include <iostream>
#include <tuple>

namespace contentgen {

SceneBuilder::SceneBuilder(std::filesystem::path cagesFolder) : cages_(std::move(cagesFolder)) {}

engine::EntityId SceneBuilder::ground(float size, glm::vec3 color) {
    auto plane = std::make_shared<engine::MeshData>(engine::primitives::plane(size, 1));
    plane->name = "ground";
    plane->material.baseColor = color;
    const engine::EntityId id = scene_.create("ground");
    scene_.entity(id).mesh = engine::MeshComponent{plane};
    return id;
}

engine::EntityId SceneBuilder::surface(const std::string& name, const std::string& cageName, int level,
                                       glm::vec3 color, glm::vec3 translation, float scale) {
    const content::Cage cage = content::CageLoader::load(cages_ / (cageName + ".obj"));
    auto preview = std::make_shared<engine::MeshData>(content::SubdivisionSurface(cage).evaluate(1).mesh);
    preview->name = cageName;
    preview->material.baseColor = color;
    const engine::EntityId id = scene_.create(name);
    scene_.entity(id).mesh = engine::MeshComponent{preview};
    scene_.entity(id).transform.translation = translation;
    scene_.entity(id).transform.scale = glm::vec3(scale);
    tags_.emplace_back(id, content::SubdivisionTag{"catmull-clark", level, "../cages/" + cageName + ".obj"});
    return id;
}

std::shared_ptr<engine::MeshData> SceneBuilder::shape(const std::string& shape, glm::vec3 color,
                                                      const std::function<engine::MeshData()>& make) {
    std::shared_ptr<engine::MeshData>& mesh = shapes_[{shape, std::make_tuple(color.r, color.g, color.b)}];
    if (!mesh) {
        mesh = std::make_shared<engine::MeshData>(make());
        mesh->name = shape;
        mesh->material.baseColor = color;
    }
    return mesh;
}

engine::EntityId SceneBuilder::part(const std::string& name, std::shared_ptr<engine::MeshData> mesh,
                                    const engine::Transform& transform, engine::EntityId parent) {
    const engine::EntityId id = scene_.create(name, parent);
    scene_.entity(id).mesh = engine::MeshComponent{std::move(mesh)};
    scene_.entity(id).transform = transform;
    return id;
}

engine::EntityId SceneBuilder::box(const std::string& name, glm::vec3 centre, glm::vec3 size, glm::vec3 color,
                                   engine::EntityId parent, float yawDegrees) {
    engine::Transform transform;
    transform.translation = centre;
    transform.rotation = glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0, 1, 0));
    transform.scale = size;
    return part(name, shape("box", color, [] { return engine::primitives::cube(1.0f); }), transform, parent);
}

engine::EntityId SceneBuilder::group(const std::string& name, glm::vec3 translation, float yawDegrees) {
    const engine::EntityId id = scene_.create(name);
    scene_.entity(id).transform.translation = translation;
    scene_.entity(id).transform.rotation = glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0, 1, 0));
    return id;
}

engine::EntityId SceneBuilder::sun(float azimuthDegrees, float elevationDegrees, float intensity) {
    const float azimuth = glm::radians(azimuthDegrees);
    const float elevation = glm::radians(elevationDegrees);
    const glm::vec3 from(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::cos(azimuth));
    const engine::EntityId id = scene_.create("sun");
    scene_.entity(id).light = engine::LightComponent{};
    scene_.entity(id).light->intensity = intensity;
    scene_.entity(id).transform = engine::Transform::lookAt(from * 10.0f, {0, 0, 0});
    return id;
}

engine::EntityId SceneBuilder::spot(glm::vec3 position, glm::vec3 target, float intensity,
                                    float outerConeAngle) {
    const engine::EntityId id = scene_.create("spot");
    engine::LightComponent light;
    light.type = engine::LightType::Spot;
    light.intensity = intensity;
    light.outerConeAngle = outerConeAngle;
    light.innerConeAngle = outerConeAngle * 0.8f;
    scene_.entity(id).light = light;
    scene_.entity(id).transform = engine::Transform::lookAt(position, target);
    return id;
}

engine::EntityId SceneBuilder::point(const std::string& name, glm::vec3 position, float intensity,
                                     float range, glm::vec3 color) {
    const engine::EntityId id = scene_.create(name);
    engine::LightComponent light;
    light.type = engine::LightType::Point;
    light.color = color;
    light.intensity = intensity;
    light.range = range;
    scene_.entity(id).light = light;
    scene_.entity(id).transform.translation = position;
    return id;
}

engine::EntityId SceneBuilder::camera(glm::vec3 eye, glm::vec3 target, float verticalFov, float nearPlane,
                                      float farPlane) {
    const engine::EntityId id = scene_.create("camera");
    engine::CameraComponent lens;
    lens.verticalFov = verticalFov;
    lens.nearPlane = nearPlane;
    lens.farPlane = farPlane;
    scene_.entity(id).camera = lens;
    scene_.entity(id).transform = engine::Transform::lookAt(eye, target);
    return id;
}

void SceneBuilder::save(const std::filesystem::path& path) const {
    content::GltfWriter::save(scene_, path, tags_);
    const content::LoadedScene check = content::GltfLoader::load(path);
    std::size_t triangles = 0;
    check.scene.forEach([&](engine::EntityId, const engine::Entity& entity) {
        triangles += entity.mesh ? entity.mesh->mesh->triangleCount() : 0;
    });
    std::cout << path.string() << ": " << check.scene.size() << " entities, " << triangles
              << " triangles as loaded\n";
}

} // namespace contentgen
