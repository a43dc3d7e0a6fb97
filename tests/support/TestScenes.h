#pragma once

// Scenes several test suites build: a ground plane, and a box standing on it, with the closed-form shadow
// test.
#include <engine/Scene.h>

#include <glm/glm.hpp>

#include <span>

namespace testsupport {

/// @brief Adds a square ground plane of side `size` at y = 0, named "ground".
engine::EntityId addGround(engine::Scene& scene, float size);

/// @brief A ground plane of side `groundSize` with a cube of edge `boxEdge` standing on it at the origin
/// (named "box"); no lights, no camera.
engine::Scene boxOnPlane(float groundSize, float boxEdge);

/// @brief Where a ray enters and leaves an axis-aligned box (slab test), `enter < exit` when it crosses it.
struct BoxCrossing {
    float enter;
    float exit;
};

/// @brief The ray `origin + t * direction`, t from `start` on, against the box [low, high]. A ray parallel to
/// a slab it starts outside of misses (enter = exit = 0).
BoxCrossing crossBox(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& low,
                     const glm::vec3& high, float start);

/// @brief An axis-aligned box standing in a scene (world space).
struct Block {
    glm::vec3 min;
    glm::vec3 max;
};

/// @brief Adds a cube mesh filling each block (named "block").
void addBlocks(engine::Scene& scene, std::span<const Block> blocks);

/// @brief Whether a block crosses the ray `origin + t * direction` for 1e-4 < t < `length` (infinite for a
/// sun): the closed-form shadow test of scenes made of blocks.
bool blocksRay(std::span<const Block> blocks, const glm::vec3& origin, const glm::vec3& direction,
               float length = 1e30f);

} // namespace testsupport
