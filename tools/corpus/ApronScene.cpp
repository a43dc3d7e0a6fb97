#include "ApronScene.h"

#include <engine/Primitives.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace corpus {

namespace {

constexpr float kGroundSize = 300.0f;
// A tessellated ground (2.3 m cells), as real site models have; it is also most of the scene's ~50k
// triangles, the 30k-70k of the reported view.
constexpr int kGroundDivisions = 128;

namespace colour {
constexpr glm::vec3 kConcrete{0.50f, 0.50f, 0.47f};
constexpr glm::vec3 kAircraft{0.85f, 0.86f, 0.88f};
constexpr glm::vec3 kBus{0.80f, 0.62f, 0.10f};
constexpr glm::vec3 kTruck{0.20f, 0.32f, 0.62f};
constexpr glm::vec3 kTug{0.85f, 0.45f, 0.08f};
constexpr glm::vec3 kCart{0.35f, 0.37f, 0.40f};
constexpr glm::vec3 kContainers[] = {{0.62f, 0.15f, 0.10f}, {0.12f, 0.35f, 0.55f}, {0.20f, 0.45f, 0.22f}};
constexpr glm::vec3 kPole{0.55f, 0.56f, 0.58f};
constexpr glm::vec3 kWire{0.10f, 0.10f, 0.10f};
constexpr glm::vec3 kFence{0.30f, 0.40f, 0.32f};
// The merged mesh has one material (MeshData holds no vertex colours): a neutral concrete-like grey.
constexpr glm::vec3 kMerged{0.60f, 0.60f, 0.58f};
} // namespace colour

/// Draws of std::mt19937 turned into numbers by our own arithmetic: the standard distributions are not
/// specified to give the same values in every library, and the scene must be the same bytes everywhere.
class Random {
public:
    explicit Random(std::uint32_t seed) : generator_(seed) {}

    /// Uniform in [low, high), from the top 24 bits of one draw (exact in a float).
    float uniform(float low, float high) {
        const float unit = static_cast<float>(generator_() >> 8) * (1.0f / 16777216.0f);
        return low + (high - low) * unit;
    }
    /// Uniform in [low, high]; the modulo bias is irrelevant here.
    int integer(int low, int high) {
        return low + static_cast<int>(generator_() % static_cast<std::uint32_t>(high - low + 1));
    }

private:
    std::mt19937 generator_;
};

/// Right-handed unit axes whose z is `direction`; x stays horizontal unless `direction` is vertical, so beams
/// and wings keep their cross-section upright.
struct Axes {
    glm::vec3 x, y, z;
};

Axes axesAlong(const glm::vec3& direction) {
    const glm::vec3 z = glm::normalize(direction);
    const glm::vec3 reference = std::abs(z.y) > 0.999f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 x = glm::normalize(glm::cross(reference, z));
    return {x, glm::cross(z, x), z};
}

/// One apron object: world-space triangles in one colour, added part by part in the object's own frame
/// (x forward, y up) that is turned `yaw` radians about +Y and moved to `origin`. Baking the placement into
/// the vertices lets the merged scene hold exactly the vertices of the per-object one.
class ObjectBuilder {
public:
    ObjectBuilder(std::string name, const glm::vec3& colour, const glm::vec3& origin = {}, float yaw = 0.0f)
        : origin_(origin), forward_(std::cos(yaw), 0.0f, -std::sin(yaw)),
          side_(std::sin(yaw), 0.0f, std::cos(yaw)) {
        mesh_.name = std::move(name);
        mesh_.material.baseColor = colour;
    }

    /// An upright box of `size` centred at `centre`, turned `yaw` radians about its vertical axis.
    void box(const glm::vec3& centre, const glm::vec3& size, float yaw = 0.0f) {
        const glm::vec3 x = turn({std::cos(yaw), 0.0f, -std::sin(yaw)});
        const glm::vec3 z = turn({std::sin(yaw), 0.0f, std::cos(yaw)});
        worldBox(world(centre), {x, {0.0f, 1.0f, 0.0f}, z}, size);
    }

    /// A box from `from` to `to`, `width` wide across and `height` high (wires, rails, arms, wings, fins).
    void beam(const glm::vec3& from, const glm::vec3& to, float width, float height) {
        const glm::vec3 a = world(from);
        const glm::vec3 b = world(to);
        worldBox(0.5f * (a + b), axesAlong(b - a), {width, height, glm::length(b - a)});
    }

    /// A capped cylinder of `radius` from `from` to `to`, smooth sides of `segments` facets.
    void cylinder(const glm::vec3& from, const glm::vec3& to, float radius, int segments) {
        const glm::vec3 a = world(from);
        const glm::vec3 b = world(to);
        const Axes axes = axesAlong(b - a);
        const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
        for (int i = 0; i < segments; ++i) {
            const float angle = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
            const glm::vec3 radial = std::cos(angle) * axes.x + std::sin(angle) * axes.y;
            add(a + radius * radial, radial);
            add(b + radius * radial, radial);
        }
        const auto n = static_cast<std::uint32_t>(segments);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t bottom = first + 2 * i;
            const std::uint32_t nextBottom = first + 2 * ((i + 1) % n);
            triangle(bottom, nextBottom, nextBottom + 1);
            triangle(bottom, nextBottom + 1, bottom + 1);
        }
        cap(a, -axes.z, axes, radius, segments);
        cap(b, axes.z, axes, radius, segments);
    }

    [[nodiscard]] engine::MeshData finish() && { return std::move(mesh_); }

private:
    [[nodiscard]] glm::vec3 turn(const glm::vec3& local) const {
        return local.x * forward_ + glm::vec3(0.0f, local.y, 0.0f) + local.z * side_;
    }
    [[nodiscard]] glm::vec3 world(const glm::vec3& local) const { return origin_ + turn(local); }

    void add(const glm::vec3& position, const glm::vec3& normal) {
        mesh_.positions.push_back(position);
        mesh_.normals.push_back(normal);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    }

    void worldBox(const glm::vec3& centre, const Axes& axes, const glm::vec3& size) {
        static const engine::MeshData unitCube = engine::primitives::cube(1.0f);
        const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
        for (std::size_t i = 0; i < unitCube.positions.size(); ++i) {
            const glm::vec3 p = unitCube.positions[i] * size;
            const glm::vec3 n = unitCube.normals[i];
            add(centre + p.x * axes.x + p.y * axes.y + p.z * axes.z,
                n.x * axes.x + n.y * axes.y + n.z * axes.z);
        }
        for (std::uint32_t index : unitCube.indices) {
            mesh_.indices.push_back(first + index);
        }
    }

    /// A flat disc at `centre` facing `normal` (±axes.z), counter-clockwise seen from outside.
    void cap(const glm::vec3& centre, const glm::vec3& normal, const Axes& axes, float radius, int segments) {
        const auto middle = static_cast<std::uint32_t>(mesh_.positions.size());
        add(centre, normal);
        for (int i = 0; i < segments; ++i) {
            const float angle = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
            add(centre + radius * (std::cos(angle) * axes.x + std::sin(angle) * axes.y), normal);
        }
        const bool facesAlongAxis = glm::dot(normal, axes.z) > 0.0f;
        const auto n = static_cast<std::uint32_t>(segments);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t rim = middle + 1 + i;
            const std::uint32_t nextRim = middle + 1 + (i + 1) % n;
            if (facesAlongAxis) {
                triangle(middle, rim, nextRim);
            } else {
                triangle(middle, nextRim, rim);
            }
        }
    }

    engine::MeshData mesh_;
    glm::vec3 origin_;
    glm::vec3 forward_;
    glm::vec3 side_;
};

/// A wheel of `radius` and `width` whose axle runs across the vehicle (local z) at (`x`, `radius`, `z`).
void wheel(ObjectBuilder& object, float x, float z, float radius, float width) {
    object.cylinder({x, radius, z - 0.5f * width}, {x, radius, z + 0.5f * width}, radius, 20);
}

/// A twin-engine airliner of 40 m with a 36 m span, standing on its gear (the ground shows under it).
engine::MeshData aircraft(const std::string& name, const glm::vec2& at, float yaw) {
    ObjectBuilder parts(name, colour::kAircraft, {at.x, 0.0f, at.y}, yaw);
    parts.cylinder({-16.0f, 4.5f, 0.0f}, {16.0f, 4.5f, 0.0f}, 2.0f, 40);
    parts.cylinder({16.0f, 4.4f, 0.0f}, {18.8f, 4.1f, 0.0f}, 1.5f, 32);
    parts.cylinder({18.8f, 4.1f, 0.0f}, {20.0f, 3.9f, 0.0f}, 0.7f, 24);
    parts.cylinder({-16.0f, 4.7f, 0.0f}, {-20.0f, 5.6f, 0.0f}, 1.1f, 32);
    for (const float side : {-1.0f, 1.0f}) {
        parts.beam({1.5f, 3.3f, side * 1.8f}, {-6.5f, 3.9f, side * 18.0f}, 3.2f, 0.35f);
        parts.beam({-16.0f, 5.6f, side * 1.0f}, {-19.0f, 5.8f, side * 6.5f}, 2.0f, 0.2f);
        parts.cylinder({3.5f, 2.3f, side * 6.5f}, {-1.0f, 2.3f, side * 6.5f}, 1.1f, 32);
        parts.box({0.8f, 3.1f, side * 6.5f}, {2.5f, 0.8f, 0.3f});
        parts.cylinder({-1.0f, 0.6f, side * 2.8f}, {-1.0f, 2.8f, side * 2.8f}, 0.18f, 12);
        for (const float offset : {-0.7f, 0.7f}) {
            wheel(parts, -1.0f + offset, side * 2.8f, 0.6f, 0.45f);
        }
    }
    parts.beam({-16.0f, 6.2f, 0.0f}, {-18.2f, 11.8f, 0.0f}, 0.35f, 4.0f);
    parts.cylinder({15.0f, 0.45f, 0.0f}, {15.0f, 2.7f, 0.0f}, 0.14f, 12);
    for (const float side : {-1.0f, 1.0f}) {
        wheel(parts, 15.0f, side * 0.3f, 0.45f, 0.28f);
    }
    return std::move(parts).finish();
}

engine::MeshData bus(const std::string& name, const glm::vec2& at, float yaw, float length) {
    ObjectBuilder parts(name, colour::kBus, {at.x, 0.0f, at.y}, yaw);
    parts.box({0.0f, 1.95f, 0.0f}, {length, 2.9f, 2.5f});
    parts.box({-0.25f * length, 3.55f, 0.0f}, {2.5f, 0.3f, 1.6f}); // roof air conditioner
    for (const float x : {0.35f * length, -0.25f * length, -0.36f * length}) {
        for (const float side : {-1.05f, 1.05f}) {
            wheel(parts, x, side, 0.5f, 0.35f);
        }
    }
    return std::move(parts).finish();
}

/// A truck of `length` (8-10 m): a cab and one of three bodies, chosen by `body`: a box, a fuel tank, or a
/// catering box raised on a scissor frame with the ground showing under it.
engine::MeshData truck(const std::string& name, const glm::vec2& at, float yaw, float length, int body) {
    ObjectBuilder parts(name, colour::kTruck, {at.x, 0.0f, at.y}, yaw);
    const float front = 0.5f * length;
    parts.box({front - 1.1f, 1.85f, 0.0f}, {2.2f, 2.5f, 2.4f});
    parts.box({-0.6f, 0.85f, 0.0f}, {length - 1.2f, 0.3f, 1.0f}); // chassis
    const float bodyLength = length - 2.8f;
    const float bodyCentre = front - 2.5f - 0.5f * bodyLength;
    if (body == 0) {
        parts.box({bodyCentre, 2.45f, 0.0f}, {bodyLength, 2.9f, 2.5f});
    } else if (body == 1) {
        parts.cylinder({bodyCentre + 0.5f * bodyLength, 2.2f, 0.0f},
                       {bodyCentre - 0.5f * bodyLength, 2.2f, 0.0f}, 1.2f, 32);
    } else {
        const float raised = 4.5f;
        for (const float side : {-1.0f, 1.0f}) {
            parts.beam({bodyCentre - 0.4f * bodyLength, 1.0f, side * 1.0f},
                       {bodyCentre + 0.4f * bodyLength, raised, side * 1.0f}, 0.12f, 0.15f);
            parts.beam({bodyCentre + 0.4f * bodyLength, 1.0f, side * 1.0f},
                       {bodyCentre - 0.4f * bodyLength, raised, side * 1.0f}, 0.12f, 0.15f);
        }
        parts.box({bodyCentre, raised + 1.3f, 0.0f}, {bodyLength, 2.6f, 2.5f});
    }
    for (const float x : {front - 1.3f, -0.5f * length + 1.6f, -0.5f * length + 0.6f}) {
        for (const float side : {-1.0f, 1.0f}) {
            wheel(parts, x, side, 0.5f, 0.4f);
        }
    }
    return std::move(parts).finish();
}

/// A 3 m baggage tug with an open cab: a roof on four thin posts.
engine::MeshData tug(const std::string& name, const glm::vec2& at, float yaw) {
    ObjectBuilder parts(name, colour::kTug, {at.x, 0.0f, at.y}, yaw);
    parts.box({0.0f, 0.8f, 0.0f}, {3.0f, 0.9f, 1.7f});
    for (const float x : {-1.3f, -0.1f}) {
        for (const float side : {-0.75f, 0.75f}) {
            parts.box({x, 1.7f, side}, {0.06f, 0.9f, 0.06f});
        }
    }
    parts.box({-0.7f, 2.18f, 0.0f}, {1.5f, 0.06f, 1.7f});
    for (const float x : {-1.0f, 1.0f}) {
        for (const float side : {-0.8f, 0.8f}) {
            wheel(parts, x, side, 0.35f, 0.3f);
        }
    }
    return std::move(parts).finish();
}

/// A 3 m covered baggage cart: a bed on small wheels, thin corner posts, a roof and some bags.
engine::MeshData cart(const std::string& name, const glm::vec2& at, float yaw, Random& random) {
    ObjectBuilder parts(name, colour::kCart, {at.x, 0.0f, at.y}, yaw);
    parts.box({0.0f, 0.55f, 0.0f}, {3.0f, 0.1f, 1.5f});
    for (const float x : {-1.45f, 1.45f}) {
        for (const float side : {-0.72f, 0.72f}) {
            parts.box({x, 1.25f, side}, {0.05f, 1.3f, 0.05f});
        }
    }
    parts.box({0.0f, 1.92f, 0.0f}, {3.1f, 0.05f, 1.6f});
    parts.beam({1.5f, 0.45f, 0.0f}, {2.6f, 0.3f, 0.0f}, 0.08f, 0.08f); // drawbar
    const int bags = random.integer(0, 4);
    for (int i = 0; i < bags; ++i) {
        const float height = random.uniform(0.3f, 0.7f);
        parts.box({-1.1f + 0.7f * static_cast<float>(i), 0.6f + 0.5f * height, 0.0f}, {0.55f, height, 1.0f});
    }
    for (const float x : {-1.0f, 1.0f}) {
        for (const float side : {-0.6f, 0.6f}) {
            wheel(parts, x, side, 0.25f, 0.15f);
        }
    }
    return std::move(parts).finish();
}

/// A 6 m container on the ground, two stacked (`style` 1), or on a low stand the ground shows under (2).
engine::MeshData container(const std::string& name, const glm::vec2& at, float yaw, int style, int tint) {
    ObjectBuilder parts(name, colour::kContainers[tint], {at.x, 0.0f, at.y}, yaw);
    const glm::vec3 size{6.06f, 2.59f, 2.44f};
    const float base = style == 2 ? 0.9f : 0.0f;
    parts.box({0.0f, base + 0.5f * size.y, 0.0f}, size);
    if (style == 1) {
        parts.box({0.0f, 1.5f * size.y + 0.02f, 0.0f}, size, 0.03f); // a little askew, as stacked by hand
    }
    if (style == 2) {
        for (const float x : {-2.8f, 2.8f}) {
            for (const float side : {-1.0f, 1.0f}) {
                parts.box({x, 0.45f, side}, {0.25f, 0.9f, 0.25f});
            }
        }
    }
    return std::move(parts).finish();
}

/// A light pole of `height` and `thickness` whose arms run along local z: a lamp cross-arm on top and a
/// shorter arm at `wireHeight` that carries two overhead wires.
engine::MeshData lightPole(const std::string& name, const glm::vec2& at, float yaw, float height,
                           float thickness, float wireHeight) {
    ObjectBuilder parts(name, colour::kPole, {at.x, 0.0f, at.y}, yaw);
    parts.box({0.0f, 0.25f, 0.0f}, {0.7f, 0.5f, 0.7f});
    parts.cylinder({0.0f, 0.5f, 0.0f}, {0.0f, height, 0.0f}, 0.5f * thickness, 16);
    parts.beam({0.0f, height - 0.4f, -1.6f}, {0.0f, height - 0.4f, 1.6f}, 0.1f, 0.12f);
    for (const float side : {-1.0f, 1.0f}) {
        parts.box({0.0f, height - 0.6f, side * 1.5f}, {0.6f, 0.22f, 0.45f});
    }
    parts.beam({0.0f, wireHeight, -1.0f}, {0.0f, wireHeight, 1.0f}, 0.08f, 0.1f);
    return std::move(parts).finish();
}

/// Two wires 5 cm thick from pole `a` to pole `b`, hanging from the wire arms (±0.9 m across the line) at
/// `height` and sagging 0.6 m midway, each as straight pieces of a parabola.
engine::MeshData wireSpan(const std::string& name, const glm::vec2& a, const glm::vec2& b, float height) {
    ObjectBuilder parts(name, colour::kWire);
    const glm::vec2 along = glm::normalize(b - a);
    const glm::vec2 across(-along.y, along.x);
    constexpr int kPieces = 8;
    for (const float side : {-0.9f, 0.9f}) {
        const auto point = [&](int i) {
            const float t = static_cast<float>(i) / static_cast<float>(kPieces);
            const glm::vec2 ground = a + t * (b - a) + side * across;
            return glm::vec3(ground.x, height - 2.4f * t * (1.0f - t), ground.y);
        };
        for (int i = 0; i < kPieces; ++i) {
            parts.beam(point(i), point(i + 1), 0.05f, 0.05f);
        }
    }
    return std::move(parts).finish();
}

/// A fence section of `length` along local x from `start`: posts every 2.5 m and three rails of 10 cm.
engine::MeshData fence(const std::string& name, const glm::vec2& start, float yaw, float length) {
    ObjectBuilder parts(name, colour::kFence, {start.x, 0.0f, start.y}, yaw);
    const int posts = static_cast<int>(std::lround(length / 2.5f));
    for (int i = 0; i <= posts; ++i) {
        parts.box({length * static_cast<float>(i) / static_cast<float>(posts), 1.1f, 0.0f},
                  {0.08f, 2.2f, 0.08f});
    }
    for (const float height : {0.3f, 1.2f, 2.1f}) {
        parts.beam({0.0f, height, 0.0f}, {length, height, 0.0f}, 0.1f, 0.1f);
    }
    return std::move(parts).finish();
}

/// Where objects stand: circles on the ground that later objects keep clear of.
class Footprints {
public:
    explicit Footprints(Random& random) : random_(random) {}

    void reserve(const glm::vec2& centre, float radius) { taken_.push_back({centre, radius}); }

    /// A free spot for a circle of `radius` inside [low, high], or none after a fixed number of tries.
    std::optional<glm::vec2> place(float radius, const glm::vec2& low, const glm::vec2& high) {
        for (int attempt = 0; attempt < 200; ++attempt) {
            const float x = random_.uniform(low.x, high.x);
            const float z = random_.uniform(low.y, high.y);
            const glm::vec2 centre(x, z);
            if (free(centre, radius)) {
                reserve(centre, radius);
                return centre;
            }
        }
        return std::nullopt;
    }

private:
    struct Circle {
        glm::vec2 centre;
        float radius;
    };

    [[nodiscard]] bool free(const glm::vec2& centre, float radius) const {
        for (const Circle& circle : taken_) {
            if (glm::length(circle.centre - centre) < circle.radius + radius + 1.5f) {
                return false;
            }
        }
        return true;
    }

    Random& random_;
    std::vector<Circle> taken_;
};

/// Every object of the apron, the ground first, each in world space.
std::vector<engine::MeshData> apronObjects() {
    std::vector<engine::MeshData> objects;
    engine::MeshData ground = engine::primitives::plane(kGroundSize, kGroundDivisions);
    ground.name = "ground";
    ground.material.baseColor = colour::kConcrete;
    objects.push_back(std::move(ground));

    Random random(20240607u);
    Footprints footprints(random);

    // Two lines of light poles carrying wires: one across the view 80 m ahead of the camera, one running away
    // from it on the right. The first one's wires hang below the eye, so that they do not lie on the horizon,
    // and below the second one's, so that the lines do not touch where they cross.
    struct PoleLine {
        glm::vec2 start, step;
        int poles;
        float wireHeight;
    };
    const PoleLine lines[] = {{{-120.0f, 60.0f}, {30.0f, 0.0f}, 9, 6.0f},
                              {{22.0f, 110.0f}, {0.0f, -30.0f}, 8, 7.2f}};
    int poleCount = 0;
    int spanCount = 0;
    for (const PoleLine& line : lines) {
        // Local x along the line, so the arms (local z) reach across it.
        const float yaw = std::atan2(-line.step.y, line.step.x);
        for (int i = 0; i < line.poles; ++i) {
            const glm::vec2 at = line.start + static_cast<float>(i) * line.step;
            const float height = random.uniform(14.0f, 18.0f);
            const float thickness = random.uniform(0.25f, 0.35f);
            objects.push_back(lightPole("pole-" + std::to_string(++poleCount), at, yaw, height, thickness,
                                        line.wireHeight));
            footprints.reserve(at, 3.0f);
            if (i + 1 < line.poles) {
                objects.push_back(
                    wireSpan("wires-" + std::to_string(++spanCount), at, at + line.step, line.wireHeight));
                // No vehicle under the wires.
                for (const float t : {0.25f, 0.5f, 0.75f}) {
                    footprints.reserve(at + t * line.step, 3.5f);
                }
            }
        }
    }
    int mastCount = 0;
    for (const glm::vec2 at :
         {glm::vec2(-45.0f, 10.0f), glm::vec2(80.0f, -20.0f), glm::vec2(-105.0f, -95.0f)}) {
        objects.push_back(lightPole("mast-" + std::to_string(++mastCount), at, 0.7f, 20.0f, 0.4f, 8.0f));
        footprints.reserve(at, 3.0f);
    }

    objects.push_back(aircraft("aircraft-1", {-12.0f, 25.0f}, glm::radians(20.0f)));
    footprints.reserve({-12.0f, 25.0f}, 21.0f);
    objects.push_back(aircraft("aircraft-2", {85.0f, -85.0f}, glm::radians(-110.0f)));
    footprints.reserve({85.0f, -85.0f}, 21.0f);

    // Fence along the far edge and the left edge.
    for (int i = 0; i < 4; ++i) {
        const float offset = -146.0f + 73.0f * static_cast<float>(i);
        objects.push_back(fence("fence-" + std::to_string(2 * i + 1), {offset, -146.0f}, 0.0f, 73.0f));
        objects.push_back(
            fence("fence-" + std::to_string(2 * i + 2), {-146.0f, offset}, -glm::half_pi<float>(), 73.0f));
    }

    // Vehicles: a group in the lower half of the view (15-60 m ahead, before the first pole line) placed
    // first, so that it fits, then the rest anywhere.
    struct Region {
        glm::vec2 low, high;
    };
    const Region regions[] = {{{-22.0f, 78.0f}, {22.0f, 120.0f}}, {{-135.0f, -135.0f}, {135.0f, 118.0f}}};
    enum class Kind { Bus, Truck, Tug, Cart, Container };
    int counts[5] = {};
    struct Fleet {
        Kind kind;
        const char* name;
        float footprint; // radius of the circle each stands in, m
        int perRegion[2];
    };
    const Fleet fleets[] = {{Kind::Bus, "bus", 7.0f, {1, 2}},
                            {Kind::Truck, "truck", 5.5f, {1, 2}},
                            {Kind::Tug, "tug", 2.0f, {2, 4}},
                            {Kind::Cart, "cart", 2.0f, {2, 4}},
                            {Kind::Container, "container", 3.5f, {2, 4}}};
    for (std::size_t region = 0; region < 2; ++region) {
        for (const Fleet& fleet : fleets) {
            for (int i = 0; i < fleet.perRegion[region]; ++i) {
                const std::optional<glm::vec2> at =
                    footprints.place(fleet.footprint, regions[region].low, regions[region].high);
                if (!at) {
                    continue;
                }
                const float yaw = random.uniform(0.0f, glm::two_pi<float>());
                const int number = ++counts[static_cast<std::size_t>(fleet.kind)];
                const std::string name = std::string(fleet.name) + "-" + std::to_string(number);
                switch (fleet.kind) {
                case Kind::Bus: {
                    const float length = random.uniform(11.0f, 13.5f);
                    objects.push_back(bus(name, *at, yaw, length));
                    break;
                }
                case Kind::Truck: {
                    const float length = random.uniform(8.0f, 10.0f);
                    objects.push_back(truck(name, *at, yaw, length, number % 3));
                    break;
                }
                case Kind::Tug:
                    objects.push_back(tug(name, *at, yaw));
                    break;
                case Kind::Cart:
                    objects.push_back(cart(name, *at, yaw, random));
                    break;
                case Kind::Container: {
                    const int tint = random.integer(0, 2);
                    objects.push_back(container(name, *at, yaw, number % 3, tint));
                    break;
                }
                }
            }
        }
    }
    return objects;
}

/// Unit vector towards `elevation` above the horizon at `azimuth` around +Y from +Z, degrees.
glm::vec3 towards(float elevationDegrees, float azimuthDegrees) {
    const float elevation = glm::radians(elevationDegrees);
    const float azimuth = glm::radians(azimuthDegrees);
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
            std::cos(elevation) * std::cos(azimuth)};
}

} // namespace

content::LoadedScene apronScene(const ApronOptions& options) {
    std::vector<engine::MeshData> objects = apronObjects();
    content::LoadedScene apron;
    engine::Scene& scene = apron.scene;
    if (options.merged) {
        auto merged = std::make_shared<engine::MeshData>();
        merged->name = "apron";
        merged->material.baseColor = colour::kMerged;
        for (const engine::MeshData& object : objects) {
            const auto first = static_cast<std::uint32_t>(merged->positions.size());
            merged->positions.insert(merged->positions.end(), object.positions.begin(),
                                     object.positions.end());
            merged->normals.insert(merged->normals.end(), object.normals.begin(), object.normals.end());
            for (std::uint32_t index : object.indices) {
                merged->indices.push_back(first + index);
            }
        }
        scene.entity(scene.create("apron")).mesh = engine::MeshComponent{merged};
    } else {
        for (engine::MeshData& object : objects) {
            const engine::EntityId id = scene.create(object.name);
            scene.entity(id).mesh =
                engine::MeshComponent{std::make_shared<engine::MeshData>(std::move(object))};
        }
    }

    // 8 m up near the +Z edge, looking 60 m ahead across the apron; the far plane takes in its far corners.
    const glm::vec3 eye(0.0f, 8.0f, 140.0f);
    const engine::EntityId camera = scene.create("camera");
    scene.entity(camera).transform = engine::Transform::lookAt(eye, eye + glm::vec3(0.0f, -8.0f, -60.0f));
    engine::CameraComponent lens;
    lens.verticalFov = 0.8f;
    lens.nearPlane = 0.5f;
    lens.farPlane = 450.0f;
    scene.entity(camera).camera = lens;

    const engine::EntityId sun = scene.create("sun");
    scene.entity(sun).transform = engine::Transform::lookAt(
        kGroundSize * towards(options.sunElevation, options.sunAzimuth), glm::vec3(0.0f));
    scene.entity(sun).light = engine::LightComponent{};
    // Bright enough that the ground, lit at the default grazing 8 degrees, stands out from its shadows.
    scene.entity(sun).light->intensity = 2.0f;
    return apron;
}

} // namespace corpus
