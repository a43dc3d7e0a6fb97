#include <engine/Bounds.h>
#include <engine/Error.h>
#include <engine/LightAim.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace engine {

std::string LightAngles::label() const {
    std::ostringstream text;
    text << "az" << azimuth << "-el" << elevation;
    return text.str();
}

glm::vec3 towardsLight(const LightAngles& angles) {
    const float azimuth = glm::radians(angles.azimuth);
    const float elevation = glm::radians(angles.elevation);
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
            std::cos(elevation) * std::cos(azimuth)};
}

Aabb meshBounds(const Scene& scene) {
    Aabb bounds;
    scene.forEach([&](EntityId id, const Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh) {
            return;
        }
        const glm::mat4 world = scene.worldMatrix(id);
        for (const glm::vec3& p : entity.mesh->mesh->positions) {
            bounds.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
        }
    });
    return bounds;
}

void setWorldTransform(Scene& scene, EntityId id, const Transform& world) {
    Entity& entity = scene.entity(id);
    Transform local = world;
    local.scale = entity.transform.scale;
    if (entity.parent != kNoEntity) {
        const glm::mat4 parent = scene.worldMatrix(entity.parent);
        local.translation = glm::vec3(glm::inverse(parent) * glm::vec4(world.translation, 1.0f));
        const glm::mat3 rotation(glm::normalize(glm::vec3(parent[0])), glm::normalize(glm::vec3(parent[1])),
                                 glm::normalize(glm::vec3(parent[2])));
        local.rotation = glm::inverse(glm::quat_cast(rotation)) * world.rotation;
    }
    entity.transform = local;
}

void aimLight(Scene& scene, EntityId light, const LightAngles& angles) {
    const Entity& entity = scene.entity(light);
    if (!entity.light) {
        throw Error("aimLight: entity '" + entity.name + "' has no light");
    }
    if (!std::isfinite(angles.azimuth) || !std::isfinite(angles.elevation)) {
        throw Error("aimLight: light '" + entity.name + "': azimuth and elevation must be finite");
    }
    const glm::mat4 world = scene.worldMatrix(light);
    const glm::vec3 position(world[3]);
    const glm::vec3 forward = glm::normalize(-glm::vec3(world[2]));
    const Aabb bounds = meshBounds(scene);
    const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : (bounds.min + bounds.max) * 0.5f;
    const float radius = bounds.empty() ? 1.0f : std::max(glm::length(bounds.max - bounds.min) * 0.5f, 1e-6f);
    // A directional light only turns (its position is irrelevant); a point light has no axis, so it swings
    // around the meshes' centre at its own distance from it; a spot swings around the point of its axis
    // nearest the centre. A light in front of nothing (or at the centre) gets twice the meshes' radius.
    const float along = glm::dot(centre - position, forward);
    const float fromCentre = glm::length(position - centre);
    const bool point = entity.light->type == LightType::Point;
    const float distance = point ? (fromCentre > radius * 0.1f ? fromCentre : radius * 2.0f)
                                 : (along > radius * 0.1f ? along : radius * 2.0f);
    const glm::vec3 pivot = entity.light->type == LightType::Spot ? position + forward * distance : centre;
    setWorldTransform(scene, light, Transform::lookAt(pivot + towardsLight(angles) * distance, pivot));
}

} // namespace engine
