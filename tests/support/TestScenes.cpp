#include "TestScenes.h"

#include <engine/Primitives.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace testsupport {

engine::EntityId addGround(engine::Scene& scene, float size) {
    const auto ground = scene.create("ground");
    scene.entity(ground).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::plane(size, 1))};
    return ground;
}

engine::Scene boxOnPlane(float groundSize, float boxEdge) {
    engine::Scene scene;
    addGround(scene, groundSize);
    const auto box = scene.create("box");
    scene.entity(box).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::cube(boxEdge))};
    scene.entity(box).transform.translation = {0.0f, 0.5f * boxEdge, 0.0f};
    return scene;
}

BoxCrossing crossBox(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& low,
                     const glm::vec3& high, float start) {
    float enter = start;
    float exit = 1e30f;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-12f) {
            if (origin[axis] < low[axis] || origin[axis] > high[axis]) {
                return {0.0f, 0.0f};
            }
            continue;
        }
        const float t0 = (low[axis] - origin[axis]) / direction[axis];
        const float t1 = (high[axis] - origin[axis]) / direction[axis];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return {enter, exit};
}

void addBlocks(engine::Scene& scene, std::span<const Block> blocks) {
    const auto cube = std::make_shared<engine::MeshData>(engine::primitives::cube(1.0f));
    for (const Block& block : blocks) {
        const auto entity = scene.create("block");
        scene.entity(entity).mesh = engine::MeshComponent{cube};
        scene.entity(entity).transform.translation = 0.5f * (block.min + block.max);
        scene.entity(entity).transform.scale = block.max - block.min;
    }
}

bool blocksRay(std::span<const Block> blocks, const glm::vec3& origin, const glm::vec3& direction,
               float length) {
    for (const Block& block : blocks) {
        const BoxCrossing crossing = crossBox(origin, direction, block.min, block.max, 1e-4f);
        if (crossing.enter < crossing.exit && crossing.enter < length) {
            return true;
        }
    }
    return false;
}

} // namespace testsupport
