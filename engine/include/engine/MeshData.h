#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace engine {

/// @brief Surface appearance for the forward renderer's Blinn-Phong model.
struct Material {
    /// Linear-space base (diffuse) colour. Default mid grey.
    glm::vec3 baseColor{0.8f, 0.8f, 0.8f};
    /// Specular colour, linear. Default 0.04 (dielectric-like highlight).
    glm::vec3 specularColor{0.04f, 0.04f, 0.04f};
    /// Blinn-Phong exponent, dimensionless. Default 32.
    float shininess = 32.0f;
};

/// @brief CPU-side indexed triangle mesh: the common currency between content loaders and the renderer.
///
/// Positions and normals are in the mesh's local space; `indices` holds three entries per triangle.
struct MeshData {
    std::string name;
    std::vector<glm::vec3> positions;
    /// Unit normals, one per position (smooth shading). May be empty: the renderer then derives face normals.
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
    Material material;

    [[nodiscard]] std::size_t triangleCount() const { return indices.size() / 3; }
};

} // namespace engine
