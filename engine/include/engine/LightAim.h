#pragma once

#include <engine/Bounds.h>
#include <engine/Scene.h>

#include <glm/glm.hpp>

#include <string>

namespace engine {

/// @brief Where a light comes from, as seen from the scene.
struct LightAngles {
    /// Degrees around the up axis (+Y), measured from +Z towards +X.
    float azimuth = 45.0f;
    /// Degrees above the horizon (the XZ plane).
    float elevation = 40.0f;

    /// @brief "az<azimuth>-el<elevation>", for file and row names.
    [[nodiscard]] std::string label() const;

    bool operator==(const LightAngles&) const = default;
};

/// @brief Unit vector from the scene towards a light at `angles`.
[[nodiscard]] glm::vec3 towardsLight(const LightAngles& angles);

/// @brief World-space box around every mesh of `scene` (empty when it has none).
[[nodiscard]] Aabb meshBounds(const Scene& scene);

/// @brief Sets the world pose of `id` whatever its parents (their scale assumed uniform); the entity keeps
/// its own scale.
void setWorldTransform(Scene& scene, EntityId id, const Transform& world);

/// @brief Points light `light` from `angles`. A directional light only turns; a spot light swings around the
/// point its axis passes closest to the meshes' centre, keeping its distance to it, so it keeps lighting what
/// it lit; a point light swings around the meshes' centre at its distance from it (facing the centre). Throws
/// Error when `light` has no light component or the angles are not finite.
void aimLight(Scene& scene, EntityId light, const LightAngles& angles);

} // namespace engine
