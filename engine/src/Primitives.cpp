#include <engine/Primitives.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>

namespace engine::primitives {

MeshData cube(float size) {
    MeshData mesh;
    mesh.name = "cube";
    const float h = size * 0.5f;
    // Each face: outward normal n and two in-plane axes u, v with cross(u, v) = n (counter-clockwise).
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(n.y, 0, 0) : glm::vec3(-n.z, 0, n.x);
        const glm::vec3 v = glm::cross(n, u);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::vec2 corner :
             {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            mesh.positions.push_back(h * (n + corner.x * u + corner.y * v));
            mesh.normals.push_back(n);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) {
            mesh.indices.push_back(base + i);
        }
    }
    return mesh;
}

MeshData plane(float size, int divisions) {
    MeshData mesh;
    mesh.name = "plane";
    const int n = std::max(1, divisions);
    for (int z = 0; z <= n; ++z) {
        for (int x = 0; x <= n; ++x) {
            const float fx = (static_cast<float>(x) / static_cast<float>(n) - 0.5f) * size;
            const float fz = (static_cast<float>(z) / static_cast<float>(n) - 0.5f) * size;
            mesh.positions.emplace_back(fx, 0.0f, fz);
            mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
        }
    }
    const auto row = static_cast<std::uint32_t>(n + 1);
    for (std::uint32_t z = 0; z < static_cast<std::uint32_t>(n); ++z) {
        for (std::uint32_t x = 0; x < static_cast<std::uint32_t>(n); ++x) {
            const std::uint32_t i = z * row + x;
            // Counter-clockwise seen from +Y.
            mesh.indices.insert(mesh.indices.end(), {i, i + row, i + 1, i + 1, i + row, i + row + 1});
        }
    }
    return mesh;
}

MeshData sphere(float radius, int rings, int segments) {
    MeshData mesh;
    mesh.name = "sphere";
    rings = std::max(2, rings);
    segments = std::max(3, segments);
    for (int r = 0; r <= rings; ++r) {
        const float theta = glm::pi<float>() * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s <= segments; ++s) {
            const float phi = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(radius * n);
            mesh.normals.push_back(n);
        }
    }
    const auto row = static_cast<std::uint32_t>(segments + 1);
    for (std::uint32_t r = 0; r < static_cast<std::uint32_t>(rings); ++r) {
        for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
            const std::uint32_t i = r * row + s;
            mesh.indices.insert(mesh.indices.end(), {i, i + 1, i + row, i + 1, i + row + 1, i + row});
        }
    }
    return mesh;
}

} // namespace engine::primitives
