#include "LargeScenes.h"
#include "Shapes.h"

#include <engine/Primitives.h>

#include <glm/gtc/quaternion.hpp>

#include <string>

namespace contentgen {

namespace {

// The room spans x in [-4, 4], y in [0, 3], z in [-3, 3].
constexpr glm::vec3 kHalf{4.0f, 1.5f, 3.0f};

const glm::vec3 kWood{0.45f, 0.3f, 0.18f};
const glm::vec3 kDarkWood{0.3f, 0.19f, 0.11f};
const glm::vec3 kPaint{0.72f, 0.7f, 0.64f};

/// One face of the room: a unit plane (normal +Y) turned by `rotation` so its normal faces into the room,
/// scaled to `width` × `depth` before turning, centred at `centre`.
void surfaceOfRoom(SceneBuilder& b, const std::string& name, glm::vec3 centre, glm::quat rotation,
                   float width, float depth, glm::vec3 color) {
    engine::Transform transform;
    transform.translation = centre;
    transform.rotation = rotation;
    transform.scale = {width, 1.0f, depth};
    // 8 × 8 cells: lighting is per pixel, the cells only keep the triangles near the furniture's size.
    b.part(name, b.shape("room surface", color, [] { return engine::primitives::plane(1.0f, 8); }),
           transform);
}

/// A chair facing -Z in its own frame (seat 0.45 high, back towards +Z), legs 3.5 cm thick.
void chair(SceneBuilder& b, const std::string& name, glm::vec3 at, float yawDegrees, glm::vec3 color) {
    const engine::EntityId chair = b.group(name, at, yawDegrees);
    b.box(name + " seat", {0.0f, 0.45f, 0.0f}, {0.45f, 0.04f, 0.45f}, color, chair);
    for (const float x : {-0.2f, 0.2f}) {
        for (const float z : {-0.2f, 0.2f}) {
            b.box(name + " leg", {x, 0.215f, z}, {0.035f, 0.43f, 0.035f}, color, chair);
        }
        b.box(name + " back post", {x, 0.72f, 0.2f}, {0.035f, 0.5f, 0.035f}, color, chair);
    }
    b.box(name + " back", {0.0f, 0.85f, 0.2f}, {0.4f, 0.22f, 0.03f}, color, chair);
}

} // namespace

void buildRoom(SceneBuilder& b) {
    const auto about = [](float degrees, glm::vec3 axis) {
        return glm::angleAxis(glm::radians(degrees), axis);
    };
    const glm::vec3 x(1, 0, 0);
    const glm::vec3 z(0, 0, 1);
    // Each face's normal points into the room: the floor's +Y as is, the others turned from it.
    surfaceOfRoom(b, "floor", {0.0f, 0.0f, 0.0f}, glm::quat(1, 0, 0, 0), 8.0f, 6.0f, {0.55f, 0.42f, 0.3f});
    surfaceOfRoom(b, "ceiling", {0.0f, 3.0f, 0.0f}, about(180.0f, x), 8.0f, 6.0f, {0.85f, 0.85f, 0.82f});
    surfaceOfRoom(b, "back wall", {0.0f, kHalf.y, -kHalf.z}, about(90.0f, x), 8.0f, 3.0f, {0.5f, 0.6f, 0.7f});
    surfaceOfRoom(b, "front wall", {0.0f, kHalf.y, kHalf.z}, about(-90.0f, x), 8.0f, 3.0f, kPaint);
    surfaceOfRoom(b, "left wall", {-kHalf.x, kHalf.y, 0.0f}, about(-90.0f, z), 3.0f, 6.0f, kPaint);
    surfaceOfRoom(b, "right wall", {kHalf.x, kHalf.y, 0.0f}, about(90.0f, z), 3.0f, 6.0f, kPaint);

    // A table on thin legs: their shadows are thin lines, one per light.
    const engine::EntityId table = b.group("table", {0.4f, 0.0f, -0.4f}, 8.0f);
    b.box("table top", {0.0f, 0.75f, 0.0f}, {1.6f, 0.05f, 0.9f}, kWood, table);
    for (const float tx : {-0.74f, 0.74f}) {
        for (const float tz : {-0.39f, 0.39f}) {
            b.box("table leg", {tx, 0.3625f, tz}, {0.04f, 0.725f, 0.04f}, kWood, table);
        }
    }
    chair(b, "chair north", {0.2f, 0.0f, -1.35f}, 180.0f, kDarkWood);
    chair(b, "chair south", {0.6f, 0.0f, 0.55f}, 10.0f, kDarkWood);
    chair(b, "chair east", {1.65f, 0.0f, -0.3f}, 95.0f, {0.6f, 0.25f, 0.2f});

    // Crates stacked in a corner.
    b.box("crate", {3.3f, 0.3f, -2.35f}, {0.6f, 0.6f, 0.6f}, {0.62f, 0.5f, 0.32f}, engine::kNoEntity, 12.0f);
    b.box("crate", {2.6f, 0.25f, -2.45f}, {0.5f, 0.5f, 0.5f}, {0.62f, 0.5f, 0.32f}, engine::kNoEntity, -6.0f);
    b.box("crate", {3.25f, 0.8f, -2.3f}, {0.4f, 0.4f, 0.4f}, {0.55f, 0.45f, 0.3f}, engine::kNoEntity, 30.0f);
    b.box("low box", {-0.7f, 0.2f, -2.45f}, {0.9f, 0.4f, 0.5f}, {0.3f, 0.45f, 0.35f}, engine::kNoEntity,
          -20.0f);

    // Two pillars from floor to ceiling.
    for (const glm::vec3 at : {glm::vec3(-1.3f, 0.0f, -1.7f), glm::vec3(2.4f, 0.0f, 1.2f)}) {
        engine::Transform transform;
        transform.translation = at;
        b.part("pillar", b.shape("pillar", {0.8f, 0.78f, 0.74f}, [] { return cylinder(0.2f, 3.0f, 24); }),
               transform);
    }

    // A shelf against the back wall: two uprights, four boards, a few things on them.
    const engine::EntityId shelf = b.group("shelf", {-2.0f, 0.0f, -2.78f});
    for (const float sx : {-0.62f, 0.62f}) {
        b.box("shelf side", {sx, 0.9f, 0.0f}, {0.03f, 1.8f, 0.35f}, kDarkWood, shelf);
    }
    for (int board = 0; board < 4; ++board) {
        b.box("shelf board", {0.0f, 0.2f + 0.5f * static_cast<float>(board), 0.0f}, {1.21f, 0.03f, 0.35f},
              kDarkWood, shelf);
    }
    b.box("book", {-0.4f, 0.825f, 0.0f}, {0.06f, 0.22f, 0.25f}, {0.7f, 0.2f, 0.15f}, shelf);
    b.box("book", {-0.32f, 0.815f, 0.0f}, {0.07f, 0.2f, 0.24f}, {0.2f, 0.35f, 0.6f}, shelf);
    b.box("book", {-0.23f, 0.835f, 0.0f}, {0.06f, 0.24f, 0.26f}, {0.25f, 0.5f, 0.3f}, shelf);
    b.box("box on shelf", {0.3f, 1.3f, 0.0f}, {0.35f, 0.16f, 0.28f}, {0.8f, 0.75f, 0.6f}, shelf);
    b.box("box on shelf", {0.1f, 0.31f, 0.02f}, {0.5f, 0.19f, 0.3f}, {0.45f, 0.4f, 0.5f}, shelf);

    // A ball on the floor: a round caster under both lights.
    b.surface("ball", "sphere", 3, {0.8f, 0.35f, 0.25f}, {-0.9f, 0.35f, 1.0f}, 0.35f);

    // Two point lights under the ceiling whose pools overlap over the table: every caster throws two
    // shadows. Warm and cool white, so each light's contribution shows.
    // Bulbs 8 cm across (extras.radius): their soft shadows' truth (gs-shadowbench --soft).
    for (const engine::EntityId lamp :
         {b.point("lamp west", {-1.2f, 2.5f, -0.5f}, 4.0f, 10.0f, {1.0f, 0.88f, 0.72f}),
          b.point("lamp east", {1.8f, 2.4f, 0.7f}, 4.0f, 10.0f, {0.8f, 0.88f, 1.0f})}) {
        b.scene().entity(lamp).light->radius = 0.04f;
    }

    b.camera({-3.4f, 1.6f, 2.6f}, {0.5f, 0.65f, -0.7f}, 1.0f, 0.05f, 20.0f);
}

} // namespace contentgen
