#pragma once

#include <engine/Components.h>
#include <engine/Transform.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace engine {

/// @brief Index of an entity inside its Scene.
using EntityId = std::uint32_t;
inline constexpr EntityId kNoEntity = ~EntityId{0};

/// @brief A node of the scene hierarchy: a transform plus optional components.
struct Entity {
    std::string name;
    EntityId parent = kNoEntity;
    std::vector<EntityId> children;
    Transform transform;
    std::optional<MeshComponent> mesh;
    std::optional<LightComponent> light;
    std::optional<CameraComponent> camera;
};

/// @brief Entities in a hierarchy (OpenSceneGraph-style): world transforms compose parent to child.
class Scene {
public:
    /// @brief Adds an entity under `parent` (or at the root) and returns its id.
    EntityId create(std::string name, EntityId parent = kNoEntity);

    [[nodiscard]] Entity& entity(EntityId id);
    [[nodiscard]] const Entity& entity(EntityId id) const;
    [[nodiscard]] std::size_t size() const { return entities_.size(); }

    /// @brief Re-parents `child` under `parent` (kNoEntity = root). Throws Error on a cycle.
    void setParent(EntityId child, EntityId parent);

    /// @brief Local-to-world matrix: the product of the transforms from the root down to `id`.
    [[nodiscard]] glm::mat4 worldMatrix(EntityId id) const;

    /// @brief First entity with the given name, if any.
    [[nodiscard]] std::optional<EntityId> find(std::string_view name) const;
    /// @brief First entity with a camera component, if any.
    [[nodiscard]] std::optional<EntityId> firstCamera() const;

    /// @brief Calls `visit` for every entity in creation order.
    void forEach(const std::function<void(EntityId, const Entity&)>& visit) const;

private:
    void checkId(EntityId id) const;
    std::vector<Entity> entities_;
};

} // namespace engine
