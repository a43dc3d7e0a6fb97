#include "LargeScenes.h"
#include "RollingTerrain.h"
#include "Shapes.h"

#include "content/CageShapes.h"
#include "content/SubdivisionSurface.h"

#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace contentgen {

namespace {

constexpr float kGroundSize = 4096.0f;
// Random objects stay this far inside the ground's edge (a tree's crown must not overhang it).
constexpr float kObjectExtent = 1950.0f;

const glm::vec3 kGrass{0.26f, 0.36f, 0.15f};
const glm::vec3 kBark{0.3f, 0.22f, 0.15f};
const std::array kLeaves{glm::vec3(0.18f, 0.36f, 0.12f), glm::vec3(0.26f, 0.42f, 0.14f),
                         glm::vec3(0.35f, 0.4f, 0.12f)};
const glm::vec3 kNeedles{0.1f, 0.26f, 0.14f};
const std::array kWalls{glm::vec3(0.75f, 0.7f, 0.6f), glm::vec3(0.65f, 0.4f, 0.3f),
                        glm::vec3(0.8f, 0.8f, 0.78f), glm::vec3(0.55f, 0.55f, 0.6f),
                        glm::vec3(0.7f, 0.6f, 0.45f)};
const std::array kRoofs{glm::vec3(0.5f, 0.2f, 0.15f), glm::vec3(0.3f, 0.3f, 0.33f),
                        glm::vec3(0.45f, 0.32f, 0.2f)};
const glm::vec3 kConcrete{0.6f, 0.6f, 0.58f};
const glm::vec3 kMetal{0.45f, 0.46f, 0.48f};
const glm::vec3 kStone{0.5f, 0.48f, 0.45f};
const glm::vec3 kTimber{0.42f, 0.32f, 0.22f};

/// What placing objects on the ground needs: the builder, the ground, a seeded generator (the files must be
/// the same on every run) and the footprints taken so far (x, z, radius), so objects do not overlap.
struct Outdoor {
    SceneBuilder& b;
    RollingTerrain terrain{kGroundSize, 16, 10};
    std::mt19937 random{20261130u};
    std::vector<glm::vec3> taken{};
};

/// Uniform in [low, high) from the generator's top 24 bits: std::uniform_real_distribution's output is
/// left to the library, and the committed files must not depend on it.
float uniform(Outdoor& o, float low, float high) {
    return low + (high - low) * static_cast<float>(o.random() >> 8) / 16777216.0f;
}

/// Anywhere on the ground (x, z). Every draw is a statement of its own: the arguments of one call are
/// evaluated in an unspecified order (GCC's differs between optimisation levels), so the committed scene
/// would depend on the build. The draws keep the order the committed scene was made in: z, then x.
glm::vec2 anywhere(Outdoor& o) {
    const float z = uniform(o, -1900.0f, 1900.0f);
    const float x = uniform(o, -1900.0f, 1900.0f);
    return {x, z};
}

template <typename T, std::size_t N>
const T& pick(Outdoor& o, const std::array<T, N>& items) {
    return items[static_cast<std::size_t>(uniform(o, 0.0f, static_cast<float>(N))) % N];
}

/// Claims a footprint of `radius` at (x, z) unless it overlaps one taken already (or the camera's view
/// corridor, kept clear so the view reaches the horizon).
bool claim(Outdoor& o, float x, float z, float radius) {
    if (std::abs(x) < 8.0f + radius && z < 20.0f && z > -600.0f) {
        return false;
    }
    for (const glm::vec3& other : o.taken) {
        if (glm::length(glm::vec2(x - other.x, z - other.y)) < radius + other.z) {
            return false;
        }
    }
    o.taken.emplace_back(x, z, radius);
    return true;
}

/// A group standing on the ground at (x, z), turned `yawDegrees`, whose origin sits `sink` below the lowest
/// ground under `halfWidth` of it: parts built up from y = `sink` meet the ground on every side.
engine::EntityId footing(Outdoor& o, const std::string& name, float x, float z, float halfWidth, float sink,
                         float yawDegrees) {
    const float y = o.terrain.lowestUnder(x, z, halfWidth) - sink;
    return o.b.group(name, {x, y, z}, yawDegrees);
}

/// A part of `mesh` (built upwards from y = 0) under `parent`, scaled and lifted by `y`.
void upright(Outdoor& o, const std::string& name, const std::shared_ptr<engine::MeshData>& mesh,
             engine::EntityId parent, float y, glm::vec3 scale) {
    engine::Transform transform;
    transform.translation = {0.0f, y, 0.0f};
    transform.scale = scale;
    o.b.part(name, mesh, transform, parent);
}

std::shared_ptr<engine::MeshData> unitCylinder(Outdoor& o, glm::vec3 color) {
    return o.b.shape("cylinder", color, [] { return cylinder(1.0f, 1.0f, 8); });
}

/// A broadleaf tree (a trunk and a round crown) or a conifer (a cone on a short trunk), `height` tall.
void tree(Outdoor& o, float x, float z, float height, bool conifer) {
    const float sink = 0.3f;
    const engine::EntityId group = footing(o, "tree", x, z, 0.02f * height, sink, uniform(o, 0.0f, 360.0f));
    if (conifer) {
        const float trunk = 0.25f * height;
        upright(o, "trunk", unitCylinder(o, kBark), group, 0.0f,
                {0.02f * height, trunk + sink, 0.02f * height});
        const float radius = uniform(o, 0.17f, 0.24f) * height;
        upright(o, "needles", o.b.shape("conifer crown", kNeedles, [] { return cone(1.0f, 1.0f, 10); }),
                group, sink + trunk * 0.6f, {radius, height - trunk * 0.6f, radius});
        return;
    }
    const float radius = uniform(o, 0.28f, 0.38f) * height;
    const float trunk = height - 1.6f * radius;
    upright(o, "trunk", unitCylinder(o, kBark), group, 0.0f,
            {0.025f * height, trunk + sink + 0.3f * radius, 0.025f * height});
    const glm::vec3 leaves = pick(o, kLeaves);
    // The round crown is the limit surface of a cube-sphere cage: smooth, no pole triangles; it spans about
    // [-0.9, 0.9] (the limit lies inside the cage).
    const auto crown = o.b.shape("crown", leaves, [] {
        return content::SubdivisionSurface(content::CageShapes::quadSphere(2, 1.0f)).evaluate(1).mesh;
    });
    engine::Transform transform;
    transform.translation = {0.0f, sink + trunk + 0.8f * radius, 0.0f};
    transform.scale = glm::vec3(radius, 0.9f * radius, radius);
    o.b.part("crown", crown, transform, group);
}

/// A building of footprint `size.x` × `size.z` and walls `size.y` high, with a hipped roof unless `flat`.
void building(Outdoor& o, float x, float z, glm::vec3 size, float yawDegrees, bool flat) {
    // Half the footprint's diagonal: the square lowestUnder() samples covers the footprint however turned.
    const float halfWidth = 0.5f * std::hypot(size.x, size.z);
    const float sink = 0.5f;
    const engine::EntityId group = footing(o, flat ? "tower" : "house", x, z, halfWidth, sink, yawDegrees);
    const glm::vec3 walls = flat ? kConcrete * uniform(o, 0.8f, 1.1f) : pick(o, kWalls);
    o.b.box("walls", {0.0f, 0.5f * (size.y + sink), 0.0f}, {size.x, size.y + sink, size.z}, walls, group);
    if (!flat) {
        const float roof = 0.35f * std::min(size.x, size.z);
        upright(o, "roof", o.b.shape("roof", pick(o, kRoofs), pyramid), group, size.y + sink,
                {size.x * 1.08f, roof, size.z * 1.08f});
    }
}

/// A building of random size (within [low, high]) and yaw (0-90°) at `p`: yaw drawn first, then the size,
/// as for the committed scene (see anywhere).
void randomBuilding(Outdoor& o, glm::vec2 p, glm::vec3 low, glm::vec3 high, bool flat) {
    const float yaw = uniform(o, 0.0f, 90.0f);
    const float width = uniform(o, low.x, high.x);
    const float height = uniform(o, low.y, high.y);
    const float depth = uniform(o, low.z, high.z);
    building(o, p.x, p.y, {width, height, depth}, yaw, flat);
}

/// A tree of random height in [low, high) at `p`, a conifer with probability `conifers`: the kind drawn
/// first, then the height, as for the committed scene (see anywhere).
void randomTree(Outdoor& o, glm::vec2 p, float low, float high, float conifers) {
    const bool conifer = uniform(o, 0.0f, 1.0f) < conifers;
    const float height = uniform(o, low, high);
    tree(o, p.x, p.y, height, conifer);
}

/// A random point in the disc of `radius` around `centre` (x, z).
glm::vec2 inDisc(Outdoor& o, glm::vec2 centre, float radius) {
    const float r = radius * std::sqrt(uniform(o, 0.0f, 1.0f));
    const float angle = uniform(o, 0.0f, 6.2831853f);
    return centre + r * glm::vec2(std::cos(angle), std::sin(angle));
}

/// Up to `count` objects, each tried up to 20 times at `where()` until its footprint is free.
template <typename Where, typename Place>
void scatter(Outdoor& o, int count, float radius, Where where, Place place) {
    for (int i = 0; i < count; ++i) {
        for (int attempt = 0; attempt < 20; ++attempt) {
            const glm::vec2 p = where();
            if (std::abs(p.x) < kObjectExtent && std::abs(p.y) < kObjectExtent &&
                claim(o, p.x, p.y, radius)) {
                place(p);
                break;
            }
        }
    }
}

/// Beside the camera (which stands at the origin looking along -Z): fence posts, bollards, lamp posts,
/// boulders, a shed and a few trees, from 0.5 m up.
void nearObjects(Outdoor& o) {
    for (int i = 0; i < 28; ++i) {
        const float z = -3.0f - 2.5f * static_cast<float>(i);
        const engine::EntityId post = footing(o, "fence post", 2.4f, z, 0.06f, 0.2f, 0.0f);
        o.b.box("post", {0.0f, 0.6f, 0.0f}, {0.12f, 1.2f, 0.12f}, kTimber, post);
    }
    for (int i = 0; i < 6; ++i) {
        const engine::EntityId bollard =
            footing(o, "bollard", -1.3f, -4.0f - 4.0f * static_cast<float>(i), 0.1f, 0.1f, 0.0f);
        upright(o, "bollard", unitCylinder(o, kStone), bollard, 0.0f, {0.1f, 0.6f, 0.1f});
    }
    for (int i = 0; i < 11; ++i) {
        const engine::EntityId lamp =
            footing(o, "lamp post", -4.0f, -10.0f - 25.0f * static_cast<float>(i), 0.1f, 0.2f, 0.0f);
        upright(o, "pole", unitCylinder(o, kMetal), lamp, 0.0f, {0.08f, 5.2f, 0.08f});
        o.b.box("lamp arm", {0.45f, 5.1f, 0.0f}, {0.9f, 0.08f, 0.08f}, kMetal, lamp);
    }
    const std::array<glm::vec3, 12> boulders{{{5.5f, -6.0f, 0.6f},
                                              {-3.0f, -14.0f, 0.4f},
                                              {7.0f, -21.0f, 1.1f},
                                              {-7.5f, -9.0f, 0.8f},
                                              {4.0f, -35.0f, 0.5f},
                                              {-6.0f, -42.0f, 1.3f},
                                              {9.0f, -55.0f, 0.9f},
                                              {-2.8f, -28.0f, 0.3f},
                                              {12.0f, -12.0f, 0.7f},
                                              {-11.0f, -30.0f, 1.0f},
                                              {6.5f, 3.0f, 0.5f},
                                              {-5.0f, 4.5f, 0.6f}}};
    const auto stone = o.b.shape("boulder", kStone, [] {
        return content::SubdivisionSurface(content::CageShapes::quadSphere(2, 1.0f)).evaluate(1).mesh;
    });
    for (const glm::vec3& boulder : boulders) {
        const float radius = boulder.z;
        engine::Transform transform;
        // Flattened and partly buried: its centre a fifth of its radius above the ground.
        transform.translation = {boulder.x, o.terrain.height(boulder.x, boulder.y) + 0.2f * radius,
                                 boulder.y};
        transform.rotation = glm::angleAxis(uniform(o, 0.0f, 6.2831853f), glm::vec3(0, 1, 0));
        transform.scale = glm::vec3(1.2f * radius, 0.8f * radius, radius);
        o.b.part("boulder", stone, transform);
    }
    const engine::EntityId shed = footing(o, "shed", -10.0f, -18.0f, 2.0f, 0.3f, 20.0f);
    o.b.box("walls", {0.0f, 1.4f, 0.0f}, {3.0f, 2.8f, 4.0f}, kTimber, shed);
    upright(o, "roof", o.b.shape("roof", kRoofs[1], pyramid), shed, 2.8f, {3.3f, 1.2f, 4.3f});
    const std::array<glm::vec4, 8> trees{{{-9.0f, -4.0f, 7.0f, 0.0f},
                                          {11.0f, -16.0f, 12.0f, 0.0f},
                                          {-16.0f, -30.0f, 9.0f, 1.0f},
                                          {15.0f, -40.0f, 15.0f, 1.0f},
                                          {-14.0f, -60.0f, 11.0f, 0.0f},
                                          {20.0f, -75.0f, 8.0f, 0.0f},
                                          {-8.0f, 9.0f, 10.0f, 1.0f},
                                          {9.0f, 12.0f, 6.0f, 0.0f}}};
    for (const glm::vec4& t : trees) {
        o.taken.emplace_back(t.x, t.y, 0.35f * t.z);
        tree(o, t.x, t.y, t.z, t.w > 0.5f);
    }
}

} // namespace

void buildOutdoor(SceneBuilder& b) {
    Outdoor o{b};
    for (int row = 0; row < o.terrain.tiles(); ++row) {
        for (int column = 0; column < o.terrain.tiles(); ++column) {
            auto tile = std::make_shared<engine::MeshData>(o.terrain.tile(column, row));
            tile->material.baseColor = kGrass;
            tile->material.specularColor = glm::vec3(0.01f);
            engine::Transform transform;
            transform.translation = o.terrain.tileCentre(column, row);
            b.part("ground " + std::to_string(column) + "," + std::to_string(row), tile, transform);
        }
    }
    nearObjects(o);
    // A village of houses half a kilometre ahead.
    scatter(
        o, 40, 9.0f,
        [&] {
            return inDisc(o, {260.0f, -450.0f}, 190.0f);
        },
        [&](glm::vec2 p) {
            randomBuilding(o, p, {6.0f, 4.0f, 6.0f}, {12.0f, 9.0f, 11.0f}, false);
        });
    // Towers of 20 to 40 m: a town centre 1.5 km away and two on their own.
    scatter(
        o, 14, 16.0f,
        [&] {
            return inDisc(o, {-650.0f, -1500.0f}, 160.0f);
        },
        [&](glm::vec2 p) {
            randomBuilding(o, p, {14.0f, 20.0f, 14.0f}, {26.0f, 40.0f, 26.0f}, true);
        });
    for (const glm::vec2 p : {glm::vec2(1100.0f, -1300.0f), glm::vec2(-1400.0f, 900.0f)}) {
        o.taken.emplace_back(p.x, p.y, 16.0f);
        building(o, p.x, p.y, {18.0f, 38.0f, 18.0f}, 15.0f, true);
    }
    // Farms anywhere.
    scatter(
        o, 25, 12.0f, [&] { return anywhere(o); },
        [&](glm::vec2 p) {
            randomBuilding(o, p, {10.0f, 5.0f, 8.0f}, {24.0f, 10.0f, 14.0f}, false);
        });
    // Three woods and trees scattered over everything.
    for (const glm::vec2 wood :
         {glm::vec2(-350.0f, -250.0f), glm::vec2(520.0f, -850.0f), glm::vec2(-1200.0f, -600.0f)}) {
        scatter(
            o, 45, 4.0f, [&] { return inDisc(o, wood, 130.0f); },
            [&](glm::vec2 p) { randomTree(o, p, 8.0f, 20.0f, 0.4f); });
    }
    scatter(
        o, 90, 4.0f, [&] { return anywhere(o); }, [&](glm::vec2 p) { randomTree(o, p, 4.0f, 18.0f, 0.3f); });
    // A power line across the whole ground: 12 m poles every 75 m.
    const glm::vec2 lineStart(-1900.0f, -350.0f);
    const glm::vec2 lineEnd(1900.0f, -700.0f);
    // Crossarms across the line: yaw turns their local +Z from (0, 1) to (sin, cos), perpendicular to it.
    const glm::vec2 along = glm::normalize(lineEnd - lineStart);
    const float crossarmYaw = glm::degrees(std::atan2(-along.y, along.x));
    for (int i = 0; i <= 50; ++i) {
        const glm::vec2 p = glm::mix(lineStart, lineEnd, static_cast<float>(i) / 50.0f);
        if (!claim(o, p.x, p.y, 1.5f)) {
            continue;
        }
        const engine::EntityId pole = footing(o, "power pole", p.x, p.y, 0.15f, 0.3f, crossarmYaw);
        upright(o, "pole", unitCylinder(o, kTimber), pole, 0.0f, {0.15f, 12.3f, 0.15f});
        o.b.box("crossarm", {0.0f, 11.8f, 0.0f}, {0.15f, 0.15f, 2.6f}, kTimber, pole);
    }

    // Eye height over the path, looking 2° down towards the horizon; the far plane reaches past the ground's
    // farthest corner (2.9 km).
    const glm::vec3 eye(0.0f, o.terrain.height(0.0f, 0.0f) + 1.8f, 0.0f);
    b.camera(eye, eye + glm::vec3(0.0f, -std::tan(glm::radians(2.0f)), -1.0f), 0.8f, 0.3f, 5000.0f);
    b.sun(115.0f, 30.0f, 2.0f);
}

} // namespace contentgen
