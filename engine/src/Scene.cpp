#include <engine/Error.h>
#include <engine/Scene.h>

#include <algorithm>

namespace engine {

EntityId Scene::create(std::string name, EntityId parent) {
    if (parent != kNoEntity) {
        checkId(parent);
    }
    const auto id = static_cast<EntityId>(entities_.size());
    Entity entity;
    entity.name = std::move(name);
    entities_.push_back(std::move(entity));
    setParent(id, parent);
    return id;
}

Entity& Scene::entity(EntityId id) {
    checkId(id);
    return entities_[id];
}

const Entity& Scene::entity(EntityId id) const {
    checkId(id);
    return entities_[id];
}

void Scene::setParent(EntityId child, EntityId parent) {
    checkId(child);
    for (EntityId ancestor = parent; ancestor != kNoEntity; ancestor = entities_[ancestor].parent) {
        checkId(ancestor);
        if (ancestor == child) {
            throw Error("scene: making '" + entities_[child].name + "' a child of '" +
                        entities_[parent].name + "' would create a cycle");
        }
    }
    Entity& entity = entities_[child];
    if (entity.parent != kNoEntity) {
        auto& siblings = entities_[entity.parent].children;
        siblings.erase(std::remove(siblings.begin(), siblings.end(), child), siblings.end());
    }
    entity.parent = parent;
    if (parent != kNoEntity) {
        entities_[parent].children.push_back(child);
    }
}

glm::mat4 Scene::worldMatrix(EntityId id) const {
    checkId(id);
    glm::mat4 matrix = entities_[id].transform.matrix();
    for (EntityId ancestor = entities_[id].parent; ancestor != kNoEntity;
         ancestor = entities_[ancestor].parent) {
        matrix = entities_[ancestor].transform.matrix() * matrix;
    }
    return matrix;
}

std::optional<EntityId> Scene::find(std::string_view name) const {
    for (EntityId id = 0; id < entities_.size(); ++id) {
        if (entities_[id].name == name) {
            return id;
        }
    }
    return std::nullopt;
}

std::optional<EntityId> Scene::firstCamera() const {
    for (EntityId id = 0; id < entities_.size(); ++id) {
        if (entities_[id].camera) {
            return id;
        }
    }
    return std::nullopt;
}

void Scene::forEach(const std::function<void(EntityId, const Entity&)>& visit) const {
    for (EntityId id = 0; id < entities_.size(); ++id) {
        visit(id, entities_[id]);
    }
}

void Scene::checkId(EntityId id) const {
    if (id >= entities_.size()) {
        throw Error("scene: entity id " + std::to_string(id) + " does not exist (scene has " +
                    std::to_string(entities_.size()) + " entities)");
    }
}

} // namespace engine
