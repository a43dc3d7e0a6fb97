#include "TestMeshes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace testsupport {

engine::MeshData merged(engine::MeshData a, const engine::MeshData& b, const glm::mat4& transform) {
    const auto base = static_cast<std::uint32_t>(a.positions.size());
    for (const glm::vec3& p : b.positions) {
        a.positions.emplace_back(transform * glm::vec4(p, 1.0f));
    }
    const glm::mat3 normalTransform = glm::transpose(glm::inverse(glm::mat3(transform)));
    for (const glm::vec3& n : b.normals) {
        a.normals.push_back(glm::normalize(normalTransform * n));
    }
    for (const std::uint32_t index : b.indices) {
        a.indices.push_back(base + index);
    }
    return a;
}

engine::MeshData merged(engine::MeshData a, const engine::MeshData& b, const glm::vec3& offset) {
    return merged(std::move(a), b, glm::translate(glm::mat4(1.0f), offset));
}

} // namespace testsupport
