#pragma once

// Meshes several test suites build: parts of one mesh appended, as real assets merge them.
#include <engine/MeshData.h>

#include <glm/glm.hpp>

namespace testsupport {

/// @brief `a` with `b`'s triangles appended, `b`'s positions (and normals, where `b` has them) moved by
/// `transform`.
engine::MeshData merged(engine::MeshData a, const engine::MeshData& b, const glm::mat4& transform);

/// @brief The same, `b` moved by `offset`.
engine::MeshData merged(engine::MeshData a, const engine::MeshData& b, const glm::vec3& offset);

} // namespace testsupport
