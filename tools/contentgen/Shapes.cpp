#include "Shapes.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace contentgen {

namespace {

/// Unit vector in the XZ plane at `segment` of `segments` around +Y.
glm::vec3 around(int segment, int segments) {
    const float angle = glm::two_pi<float>() * static_cast<float>(segment) / static_cast<float>(segments);
    return {std::cos(angle), 0.0f, std::sin(angle)};
}

/// A flat disc of `radius` at height `y` facing `up` (+1) or down (-1), its own vertices (flat normal).
void appendCap(engine::MeshData& mesh, float radius, float y, float up, int segments) {
    const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(0.0f, y, 0.0f);
    mesh.normals.emplace_back(0.0f, up, 0.0f);
    for (int s = 0; s < segments; ++s) {
        mesh.positions.push_back(radius * around(s, segments) + glm::vec3(0.0f, y, 0.0f));
        mesh.normals.emplace_back(0.0f, up, 0.0f);
    }
    for (int s = 0; s < segments; ++s) {
        const std::uint32_t a = centre + 1 + static_cast<std::uint32_t>(s);
        const std::uint32_t b = centre + 1 + static_cast<std::uint32_t>((s + 1) % segments);
        // Counter-clockwise seen from the side the cap faces: angles grow from +X towards +Z, which is
        // clockwise seen from above.
        if (up > 0.0f) {
            mesh.indices.insert(mesh.indices.end(), {centre, b, a});
        } else {
            mesh.indices.insert(mesh.indices.end(), {centre, a, b});
        }
    }
}

} // namespace

engine::MeshData cylinder(float radius, float height, int segments) {
    segments = std::max(3, segments);
    engine::MeshData mesh;
    mesh.name = "cylinder";
    for (int s = 0; s <= segments; ++s) {
        const glm::vec3 out = around(s, segments);
        mesh.positions.push_back(radius * out);
        mesh.normals.push_back(out);
        mesh.positions.push_back(radius * out + glm::vec3(0.0f, height, 0.0f));
        mesh.normals.push_back(out);
    }
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
        const std::uint32_t i = 2 * s;
        // Counter-clockwise seen from outside.
        mesh.indices.insert(mesh.indices.end(), {i, i + 1, i + 2, i + 2, i + 1, i + 3});
    }
    appendCap(mesh, radius, 0.0f, -1.0f, segments);
    appendCap(mesh, radius, height, 1.0f, segments);
    return mesh;
}

engine::MeshData cone(float radius, float height, int segments) {
    segments = std::max(3, segments);
    engine::MeshData mesh;
    mesh.name = "cone";
    // The side's outward normal at angle a: (h cos a, r, h sin a), normalised (perpendicular to the slant).
    auto sideNormal = [&](float angle) {
        return glm::normalize(glm::vec3(height * std::cos(angle), radius, height * std::sin(angle)));
    };
    const float step = glm::two_pi<float>() / static_cast<float>(segments);
    for (int s = 0; s < segments; ++s) {
        const float a0 = step * static_cast<float>(s);
        const float a1 = step * static_cast<float>(s + 1);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(radius * around(s, segments));
        mesh.positions.push_back(radius * around(s + 1, segments));
        // The apex once per side, with the side's middle normal: one shared apex normal would point up.
        mesh.positions.emplace_back(0.0f, height, 0.0f);
        mesh.normals.push_back(sideNormal(a0));
        mesh.normals.push_back(sideNormal(a1));
        mesh.normals.push_back(sideNormal(0.5f * (a0 + a1)));
        // Counter-clockwise seen from outside.
        mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1});
    }
    appendCap(mesh, radius, 0.0f, -1.0f, segments);
    return mesh;
}

engine::MeshData pyramid() {
    engine::MeshData mesh;
    mesh.name = "pyramid";
    const glm::vec3 apex(0.0f, 1.0f, 0.0f);
    // Base corners counter-clockwise seen from above.
    const glm::vec3 corners[4] = {{-0.5f, 0, -0.5f}, {-0.5f, 0, 0.5f}, {0.5f, 0, 0.5f}, {0.5f, 0, -0.5f}};
    for (int side = 0; side < 4; ++side) {
        const glm::vec3 a = corners[side];
        const glm::vec3 b = corners[(side + 1) % 4];
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, apex - a));
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::vec3& p : {a, b, apex}) {
            mesh.positions.push_back(p);
            mesh.normals.push_back(normal);
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    }
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (int corner = 0; corner < 4; ++corner) {
        mesh.positions.push_back(corners[corner]);
        mesh.normals.emplace_back(0.0f, -1.0f, 0.0f);
    }
    // Counter-clockwise seen from below: the corners' order reversed.
    mesh.indices.insert(mesh.indices.end(), {base, base + 3, base + 2, base, base + 2, base + 1});
    return mesh;
}

} // namespace contentgen
