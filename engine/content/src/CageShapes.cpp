#include "content/CageShapes.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <stdexcept>

namespace content {
namespace {

std::uint32_t toIndex(std::size_t i) {
    return static_cast<std::uint32_t>(i);
}

/// Shirley & Chiu, "A Low Distortion Map Between Disk and Square" (JGT 1997): maps [-1,1]^2 onto the unit
/// disc so that each square of radius max(|x|,|y|) lands on the circle of that radius, its border evenly.
glm::vec2 squareToDisc(float x, float y) {
    if (x == 0.0f && y == 0.0f) {
        return {0.0f, 0.0f};
    }
    const float quarterPi = glm::quarter_pi<float>();
    float radius = 0.0f;
    float angle = 0.0f;
    if (std::abs(x) >= std::abs(y)) {
        radius = x;
        angle = quarterPi * (y / x);
    } else {
        radius = y;
        angle = glm::half_pi<float>() - quarterPi * (x / y);
    }
    return radius * glm::vec2(std::cos(angle), std::sin(angle));
}

/// Closes the ring of `segments` vertices starting at `ringStart` with a grid of quads. The ring has radius
/// `ring.x` at height `ring.y`, vertex j at angle 2*pi*j/segments from +X towards +Z.
void addLatheCap(Cage& cage, std::uint32_t ringStart, int segments, glm::vec2 ring, float poleHeight,
                 bool facesDown) {
    const int cells = segments / 4; // the border of a cells x cells grid has exactly `segments` vertices
    const float step = glm::two_pi<float>() / static_cast<float>(segments);
    std::vector<std::uint32_t> grid(static_cast<std::size_t>((cells + 1) * (cells + 1)));
    for (int b = 0; b <= cells; ++b) {
        for (int a = 0; a <= cells; ++a) {
            const float x = 2.0f * static_cast<float>(a) / static_cast<float>(cells) - 1.0f;
            const float z = 2.0f * static_cast<float>(b) / static_cast<float>(cells) - 1.0f;
            const glm::vec2 disc = squareToDisc(x, z);
            auto& slot = grid[static_cast<std::size_t>(b * (cells + 1) + a)];
            if (a == 0 || b == 0 || a == cells || b == cells) {
                // Border points map evenly onto the unit circle: reuse the ring vertex at the same angle.
                float angle = std::atan2(disc.y, disc.x);
                if (angle < 0.0f) {
                    angle += glm::two_pi<float>();
                }
                slot = ringStart + toIndex(static_cast<std::size_t>(std::lround(angle / step)) % segments);
            } else {
                const float radius = glm::length(disc);
                const float height = ring.y + (poleHeight - ring.y) * (1.0f - radius * radius);
                slot = toIndex(cage.positions.size());
                cage.positions.emplace_back(disc.x * ring.x, height, disc.y * ring.x);
            }
        }
    }
    for (int b = 0; b < cells; ++b) {
        for (int a = 0; a < cells; ++a) {
            auto at = [&](int da, int db) {
                return grid[static_cast<std::size_t>((b + db) * (cells + 1) + a + da)];
            };
            // Counter-clockwise from +X to +Z, the grid faces -Y.
            if (facesDown) {
                cage.faces.push_back({at(0, 0), at(1, 0), at(1, 1), at(0, 1)});
            } else {
                cage.faces.push_back({at(0, 0), at(0, 1), at(1, 1), at(1, 0)});
            }
        }
    }
}

} // namespace

Cage CageShapes::box(glm::ivec3 segments, glm::vec3 size) {
    if (segments.x < 1 || segments.y < 1 || segments.z < 1) {
        throw std::invalid_argument("CageShapes::box: segments must be at least 1");
    }
    Cage cage;
    cage.source = "CageShapes::box";

    // Lattice points on the box surface get a vertex; interior lattice points stay unused.
    const glm::ivec3 points = segments + 1;
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    std::vector<std::uint32_t> lattice(static_cast<std::size_t>(points.x * points.y * points.z), kNone);
    auto vertexAt = [&](glm::ivec3 c) {
        auto& slot = lattice[static_cast<std::size_t>((c.z * points.y + c.y) * points.x + c.x)];
        if (slot == kNone) {
            slot = toIndex(cage.positions.size());
            cage.positions.push_back((glm::vec3(c) / glm::vec3(segments) - 0.5f) * size);
        }
        return slot;
    };

    for (int axis = 0; axis < 3; ++axis) {
        // (u, v, axis) is a right-handed frame, so quads counter-clockwise in (u, v) face +axis.
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        for (const bool positiveSide : {false, true}) {
            for (int j = 0; j < segments[v]; ++j) {
                for (int i = 0; i < segments[u]; ++i) {
                    auto corner = [&](int di, int dj) {
                        glm::ivec3 c(0);
                        c[axis] = positiveSide ? segments[axis] : 0;
                        c[u] = i + di;
                        c[v] = j + dj;
                        return vertexAt(c);
                    };
                    if (positiveSide) {
                        cage.faces.push_back({corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)});
                    } else {
                        cage.faces.push_back({corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)});
                    }
                }
            }
        }
    }
    return cage;
}

Cage CageShapes::quadSphere(int segmentsPerEdge, float radius) {
    Cage cage = box(glm::ivec3(segmentsPerEdge), glm::vec3(2.0f));
    cage.source = "CageShapes::quadSphere";
    for (glm::vec3& p : cage.positions) {
        p = glm::normalize(p) * radius;
    }
    return cage;
}

Cage CageShapes::torus(int ringSegments, int tubeSegments, float majorRadius, float minorRadius) {
    if (ringSegments < 3 || tubeSegments < 3) {
        throw std::invalid_argument("CageShapes::torus: at least 3 segments are needed in each direction");
    }
    Cage cage;
    cage.source = "CageShapes::torus";
    for (int i = 0; i < ringSegments; ++i) {
        const float theta = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(ringSegments);
        for (int j = 0; j < tubeSegments; ++j) {
            const float phi = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(tubeSegments);
            const float distance = majorRadius + minorRadius * std::cos(phi);
            cage.positions.emplace_back(distance * std::cos(theta), minorRadius * std::sin(phi),
                                        distance * std::sin(theta));
        }
    }
    auto at = [&](int i, int j) {
        return toIndex(static_cast<std::size_t>((i % ringSegments) * tubeSegments + j % tubeSegments));
    };
    for (int i = 0; i < ringSegments; ++i) {
        for (int j = 0; j < tubeSegments; ++j) {
            // d/dphi x d/dtheta points away from the tube's centre line.
            cage.faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    return cage;
}

Cage CageShapes::lathe(const LatheProfile& profile, int segments) {
    if (segments < 4 || segments % 4 != 0) {
        throw std::invalid_argument("CageShapes::lathe: segments must be a positive multiple of 4");
    }
    if (profile.rings.empty()) {
        throw std::invalid_argument("CageShapes::lathe: the profile needs at least one ring");
    }
    for (const glm::vec2& ring : profile.rings) {
        if (!(ring.x > 0.0f)) {
            throw std::invalid_argument("CageShapes::lathe: ring radii must be positive");
        }
    }
    Cage cage;
    cage.source = "CageShapes::lathe";
    for (const glm::vec2& ring : profile.rings) {
        for (int j = 0; j < segments; ++j) {
            const float theta = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(segments);
            cage.positions.emplace_back(ring.x * std::cos(theta), ring.y, ring.x * std::sin(theta));
        }
    }
    const auto n = static_cast<std::uint32_t>(segments);
    for (std::uint32_t k = 0; k + 1 < profile.rings.size(); ++k) {
        for (std::uint32_t j = 0; j < n; ++j) {
            const std::uint32_t next = (j + 1) % n;
            // Walking up the profile then around the axis: the normal is the profile direction turned
            // clockwise, i.e. away from the solid on the profile's left.
            cage.faces.push_back({k * n + j, (k + 1) * n + j, (k + 1) * n + next, k * n + next});
        }
    }
    const auto lastRing = toIndex(profile.rings.size() - 1);
    addLatheCap(cage, 0, segments, profile.rings.front(), profile.bottomPoleHeight, true);
    addLatheCap(cage, lastRing * n, segments, profile.rings.back(), profile.topPoleHeight, false);
    return cage;
}

} // namespace content
