#include "SceneStaging.h"

#include <content/ContentError.h>
#include <engine/Primitives.h>

#include <glm/gtc/constants.hpp>
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/quaternion.hpp>

#include <cmath>
#include <memory>

namespace corpus {

namespace {

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    [[nodiscard]] bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    [[nodiscard]] glm::vec3 centre() const { return 0.5f * (min + max); }
    [[nodiscard]] float radius() const { return 0.5f * glm::length(max - min); }
};

Bounds worldBounds(const engine::Scene& scene) {
    Bounds bounds;
    scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh) {
            return;
        }
        const glm::mat4 world = scene.worldMatrix(id);
        for (const glm::vec3& p : entity.mesh->mesh->positions) {
            const glm::vec3 w(world * glm::vec4(p, 1.0f));
            if (std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) {
                bounds.min = glm::min(bounds.min, w);
                bounds.max = glm::max(bounds.max, w);
            }
        }
    });
    return bounds;
}

/// Unit vector from `elevation` above the horizon and `azimuth` around +Y (0 = towards +Z), degrees.
glm::vec3 direction(float elevationDegrees, float azimuthDegrees) {
    const float elevation = glm::radians(elevationDegrees);
    const float azimuth = glm::radians(azimuthDegrees);
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
            std::cos(elevation) * std::cos(azimuth)};
}

void addSun(engine::Scene& scene, const glm::vec3& target, float distance, const StagingOptions& options) {
    const engine::EntityId sun = scene.create("sun");
    scene.entity(sun).transform = engine::Transform::lookAt(
        target + distance * direction(options.sunElevation, options.sunAzimuth), target);
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).light->intensity = 1.2f;
}

void addCamera(engine::Scene& scene, const glm::vec3& eye, const glm::vec3& target, float nearPlane,
               float farPlane) {
    const engine::EntityId camera = scene.create("camera");
    scene.entity(camera).transform = engine::Transform::lookAt(eye, target);
    engine::CameraComponent lens;
    lens.nearPlane = nearPlane;
    lens.farPlane = farPlane;
    scene.entity(camera).camera = lens;
}

} // namespace

content::LoadedScene stageModel(const content::LoadedScene& loaded, const StagingOptions& options,
                                const std::string& source) {
    content::LoadedScene staged;
    engine::Scene& scene = staged.scene;
    const engine::Scene& model = loaded.scene;
    const engine::EntityId root = scene.create("model");
    // The rotation that takes the model's up axis to +Y.
    scene.entity(root).transform.rotation = glm::rotation(glm::normalize(options.up), glm::vec3(0, 1, 0));
    std::vector<engine::EntityId> copies(model.size(), engine::kNoEntity);
    model.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        copies[id] = scene.create(entity.name, root);
        engine::Entity& copy = scene.entity(copies[id]);
        copy.transform = entity.transform;
        copy.mesh = entity.mesh;
        if (copy.mesh && options.subdivision) {
            staged.subdivided.emplace_back(copies[id], *options.subdivision);
        }
    });
    model.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (entity.parent != engine::kNoEntity) {
            scene.setParent(copies[id], copies[entity.parent]);
        }
    });
    const Bounds bounds = worldBounds(scene);
    if (!bounds.valid() || !(bounds.radius() > 0.0f)) {
        throw content::ContentError(source, "the model has no finite geometry with a non-zero extent");
    }
    // Stand the model on y = 0, centred over the origin.
    const glm::vec3 centre = bounds.centre();
    scene.entity(root).transform.translation = -glm::vec3(centre.x, bounds.min.y, centre.z);
    const glm::vec3 extent = bounds.max - bounds.min;
    const float radius = bounds.radius();

    auto ground =
        std::make_shared<engine::MeshData>(engine::primitives::plane(4.0f * std::max(extent.x, extent.z), 1));
    ground->name = "ground";
    ground->material.baseColor = {0.75f, 0.75f, 0.72f};
    scene.entity(scene.create("ground")).mesh = engine::MeshComponent{ground};

    const glm::vec3 target(0.0f, 0.5f * extent.y, 0.0f);
    // The sphere fills ~87 % of the vertical field of view (0.8 rad, the camera default).
    const float distance = 1.15f * radius / std::sin(0.4f);
    addCamera(scene, target + distance * direction(options.cameraElevation, 35.0f), target,
              std::max(distance - 3.0f * radius, 0.01f * distance), distance + 4.0f * radius);
    addSun(scene, target, 2.0f * radius, options);
    return staged;
}

content::LoadedScene stageSurface(engine::MeshData surface, const StagingOptions& options) {
    content::LoadedScene staged;
    engine::Scene& scene = staged.scene;
    Bounds bounds;
    for (const glm::vec3& p : surface.positions) {
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    const glm::vec3 extent = bounds.max - bounds.min;
    const float width = std::max(extent.x, extent.z);
    // On the ground a fifth of the way in from the near edge: the highest vertex within 1 % of the width
    // around that point is the ground under the eye.
    const glm::vec2 foot(0.0f, 0.3f * width);
    float ground = bounds.min.y;
    for (const glm::vec3& p : surface.positions) {
        if (glm::distance(glm::vec2(p.x, p.z), foot) < 0.01f * width) {
            ground = std::max(ground, p.y);
        }
    }
    scene.entity(scene.create(surface.name)).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(std::move(surface))};
    if (options.cameraHeight) {
        // A person on the ground looking level across the surface: the near plane a fraction of the height,
        // so the ground at the feet is not clipped.
        const glm::vec3 eye(foot.x, ground + *options.cameraHeight, foot.y);
        addCamera(scene, eye, glm::vec3(0.0f, eye.y - 0.02f * width, -0.3f * width),
                  std::max(0.05f * *options.cameraHeight, 1e-4f * width), 1.5f * width);
    } else {
        // From above the near edge, across the surface towards its far half.
        const glm::vec3 target(0.0f, bounds.min.y + 0.3f * extent.y, -0.15f * width);
        const glm::vec3 eye =
            glm::vec3(0.0f, bounds.max.y, 0.6f * width) +
            glm::vec3(0.0f, 0.25f * width * std::tan(glm::radians(options.cameraElevation)), 0.0f);
        addCamera(scene, eye, target, 0.002f * width, 2.5f * width);
    }
    addSun(scene, glm::vec3(bounds.centre()), width, options);
    return staged;
}

} // namespace corpus
