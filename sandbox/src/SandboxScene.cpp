#include "SandboxScene.h"

#include <engine/LightAim.h>

#include "ParameterTable.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sandbox {

namespace {

glm::vec3 position(const glm::mat4& world) {
    return glm::vec3(world[3]);
}
glm::vec3 forward(const glm::mat4& world) {
    return glm::normalize(-glm::vec3(world[2]));
}

} // namespace

SandboxScene::SandboxScene(const std::filesystem::path& path, int level)
    : loaded_(content::GltfLoader::load(path, content::SceneLoadOptions{level})) {
    engine::Scene& scene = loaded_.scene;
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (entity.light && light_ == engine::kNoEntity) {
            light_ = id;
        }
        if (!entity.mesh || !entity.mesh->mesh) {
            return;
        }
        const glm::mat4 world = scene.worldMatrix(id);
        for (const glm::vec3& p : entity.mesh->mesh->positions) {
            const glm::vec3 q = glm::vec3(world * glm::vec4(p, 1.0f));
            low = glm::min(low, q);
            high = glm::max(high, q);
        }
        triangles_ += entity.mesh->mesh->triangleCount();
    });
    const bool hasMeshes = low.x <= high.x;
    centre_ = hasMeshes ? (low + high) * 0.5f : glm::vec3(0.0f);
    radius_ = hasMeshes ? std::max(glm::length(high - low) * 0.5f, 0.01f) : 1.0f;
    const float radius = radius_;

    if (const auto camera = scene.firstCamera()) {
        camera_ = *camera;
    } else {
        camera_ = scene.create("sandbox camera");
        scene.entity(camera_).camera = engine::CameraComponent{};
        scene.entity(camera_).camera->farPlane = std::max(100.0f, radius * 10.0f);
        OrbitCamera framing;
        framing.target = centre_;
        framing.yaw = 35.0f;
        framing.pitch = 25.0f;
        framing.distance = radius * 2.5f;
        scene.entity(camera_).transform = framing.transform();
        loaded_.warnings.push_back("the scene has no camera: the sandbox added one framing the meshes");
    }
    if (light_ == engine::kNoEntity) {
        light_ = scene.create("sandbox light");
        scene.entity(light_).light = engine::LightComponent{};
        scene.entity(light_).transform = engine::Transform::lookAt(
            centre_ + engine::towardsLight({45.0f, 40.0f}) * radius * 2.0f, centre_);
        loaded_.warnings.push_back("the scene has no light: the sandbox added a directional light");
    }
    fileCamera_ = scene.entity(camera_).transform;
    fileLight_ = scene.entity(light_).transform;
    fileLightComponent_ = *scene.entity(light_).light;

    // The orbit the light angles place the light on (as engine::aimLight): a point light has no axis, so it
    // orbits the meshes' centre at its distance from it; a spot or sun orbits the point of its axis nearest
    // the centre.
    const glm::mat4 lightWorld = scene.worldMatrix(light_);
    const glm::vec3 lightPosition = position(lightWorld);
    if (fileLightComponent_.type == engine::LightType::Point) {
        const float fromCentre = glm::length(lightPosition - centre_);
        lightDistance_ = fromCentre > radius * 0.1f ? fromCentre : radius * 2.0f;
        lightPivot_ = centre_;
    } else {
        const glm::vec3 lightForward = forward(lightWorld);
        const float along = glm::dot(centre_ - lightPosition, lightForward);
        lightDistance_ = along > radius * 0.1f ? along : radius * 2.0f;
        lightPivot_ = lightPosition + lightForward * lightDistance_;
    }
}

engine::LightType SandboxScene::lightType() const {
    return loaded_.scene.entity(light_).light->type;
}

float SandboxScene::lightSize() const {
    const engine::LightComponent& light = *loaded_.scene.entity(light_).light;
    return light.type == engine::LightType::Directional ? light.angularDiameter : light.radius;
}

void SandboxScene::setLightSize(float size) {
    engine::LightComponent& light = *loaded_.scene.entity(light_).light;
    const float largest = light.sizeLimit();
    // Just below the largest the loader accepts (its bound is exclusive); NaN becomes 0.
    const float clamped = std::clamp(std::isnan(size) ? 0.0f : size, 0.0f, std::nextafter(largest, 0.0f));
    (light.type == engine::LightType::Directional ? light.angularDiameter : light.radius) = clamped;
}

SandboxSettings::LightAngles SandboxScene::fileLightAngles() const {
    // The light's own transform may be overridden by apply(); read the file's through its parent.
    const engine::Entity& entity = loaded_.scene.entity(light_);
    const glm::mat4 parent =
        entity.parent == engine::kNoEntity ? glm::mat4(1.0f) : loaded_.scene.worldMatrix(entity.parent);
    const glm::mat4 fileWorld = parent * fileLight_.matrix();
    // A point light's direction is where it sits seen from its orbit's centre; the others shine along -Z.
    const glm::vec3 offset = position(fileWorld) - lightPivot_;
    const glm::vec3 toLight =
        fileLightComponent_.type == engine::LightType::Point && glm::length(offset) > 0.0f
            ? glm::normalize(offset)
            : -forward(fileWorld);
    SandboxSettings::LightAngles angles;
    angles.elevation = std::clamp(glm::degrees(std::asin(std::clamp(toLight.y, -1.0f, 1.0f))),
                                  ParameterTable::kElevation.min, ParameterTable::kElevation.max);
    angles.azimuth = glm::degrees(std::atan2(toLight.x, toLight.z));
    if (angles.azimuth < 0.0f) {
        angles.azimuth += 360.0f;
    }
    return angles;
}

OrbitCamera SandboxScene::fileOrbit() const {
    const engine::Entity& entity = loaded_.scene.entity(camera_);
    const glm::mat4 parent =
        entity.parent == engine::kNoEntity ? glm::mat4(1.0f) : loaded_.scene.worldMatrix(entity.parent);
    const glm::mat4 world = parent * fileCamera_.matrix();
    return OrbitCamera::lookingFrom(position(world), forward(world), centre_);
}

void SandboxScene::offsetFirstMesh(const glm::vec3& offset) {
    if (firstMesh_ == engine::kNoEntity) {
        loaded_.scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
            if (firstMesh_ == engine::kNoEntity && entity.mesh) {
                firstMesh_ = id;
                firstMeshTranslation_ = entity.transform.translation;
            }
        });
    }
    if (firstMesh_ != engine::kNoEntity) {
        loaded_.scene.entity(firstMesh_).transform.translation = firstMeshTranslation_ + offset;
    }
}

void SandboxScene::apply(const std::optional<SandboxSettings::LightAngles>& light,
                         const std::optional<OrbitCamera>& camera) {
    engine::Scene& scene = loaded_.scene;
    if (light) {
        const glm::vec3 eye = lightPivot_ + engine::towardsLight(*light) * lightDistance_;
        engine::setWorldTransform(loaded_.scene, light_, engine::Transform::lookAt(eye, lightPivot_));
    } else {
        scene.entity(light_).transform = fileLight_;
    }
    if (camera) {
        engine::setWorldTransform(loaded_.scene, camera_, camera->transform());
    } else {
        scene.entity(camera_).transform = fileCamera_;
    }
}

void SandboxScene::setLightType(engine::LightType type) {
    engine::LightComponent light = fileLightComponent_;
    if (type != light.type) {
        light.type = type;
        // Directional intensity is irradiance, spot and point intensity is irradiance at distance 1: scaled
        // by distance² between them, the meshes' centre stays as bright. Spot and point share theirs (and
        // range).
        const bool wasDirectional = fileLightComponent_.type == engine::LightType::Directional;
        const float distanceSquared = lightDistance_ * lightDistance_;
        if (type == engine::LightType::Directional) {
            light.intensity = fileLightComponent_.intensity / distanceSquared;
        } else if (wasDirectional) {
            light.intensity = fileLightComponent_.intensity * distanceSquared;
        }
        if (type == engine::LightType::Spot) {
            // A cone around the meshes' bounding sphere seen from the light's orbit distance, 10 % to spare,
            // and at most 75° so the shadow map's perspective stays well conditioned.
            light.outerConeAngle = std::min(1.1f * std::atan(radius_ / lightDistance_), glm::radians(75.0f));
            light.innerConeAngle = 0.8f * light.outerConeAngle;
        }
    }
    *loaded_.scene.entity(light_).light = light;
}

} // namespace sandbox
