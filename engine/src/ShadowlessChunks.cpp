#include <engine/ShadowlessChunks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace engine {

namespace {

/// `plane` (local space) in the world of `model`, unit normal; none when `model` cannot be inverted.
std::optional<glm::vec4> worldPlane(const glm::vec4& plane, const glm::mat4& model) {
    const float determinant = glm::determinant(model);
    if (!(std::abs(determinant) > 0.0f) || !std::isfinite(determinant)) {
        return std::nullopt;
    }
    // Planes map by the inverse transpose: (M⁻ᵀ π)·(M p) = π·p.
    const glm::vec4 world = glm::transpose(glm::inverse(model)) * plane;
    const float length = glm::length(glm::vec3(world));
    if (!(length > 0.0f) || !std::isfinite(length)) {
        return std::nullopt;
    }
    return world / length;
}

std::array<glm::vec3, 8> worldCorners(const Aabb& box, const glm::mat4& model) {
    std::array<glm::vec3, 8> corners = box.corners();
    for (glm::vec3& corner : corners) {
        corner = glm::vec3(model * glm::vec4(corner, 1.0f));
    }
    return corners;
}

/// Whether two unit-normal planes are one (either normal's way) within `tolerance` over `reach` from the
/// origin.
bool samePlane(const glm::vec4& a, const glm::vec4& b, float tolerance, float reach) {
    const float facing = glm::dot(glm::vec3(a), glm::vec3(b)) < 0.0f ? -1.0f : 1.0f;
    const glm::vec4 difference = a - facing * b;
    return glm::length(glm::vec3(difference)) * reach + std::abs(difference.w) <= tolerance;
}

} // namespace

bool castsNoShadow(const glm::vec4& plane, const glm::vec4& light, std::span<const glm::vec3> receivers,
                   float tolerance) {
    // A point's homogeneous coordinates scaled by a negative w name the same point.
    const float lightSide = glm::dot(plane, light.w < 0.0f ? -light : light);
    if (lightSide == 0.0f) {
        return true;
    }
    if (!std::isfinite(lightSide)) {
        return false;
    }
    const float side = lightSide > 0.0f ? 1.0f : -1.0f;
    return std::all_of(receivers.begin(), receivers.end(), [&](const glm::vec3& point) {
        return side * (glm::dot(glm::vec3(plane), point) + plane.w) >= -tolerance;
    });
}

std::vector<const MeshChunk*> chunksCastingNoShadow(std::span<const PlacedChunks> meshes,
                                                    const glm::vec4& light) {
    std::vector<const MeshChunk*> shadowless;
    // The scene's world box first: a plane with all of it on the light's side needs no mesh by mesh look
    // (a ground, a room's walls), which keeps a scene of many flat meshes from costing their square.
    Aabb sceneBox;
    for (const PlacedChunks& mesh : meshes) {
        for (const glm::vec3& corner : worldCorners(mesh.bounds, mesh.model)) {
            sceneBox.extend(corner);
        }
    }
    for (const PlacedChunks& flatMesh : meshes) {
        for (const MeshChunk& flat : flatMesh.chunks) {
            if (!flat.plane) {
                continue;
            }
            const std::optional<glm::vec4> plane = worldPlane(*flat.plane, flatMesh.model);
            if (!plane) {
                continue;
            }
            const std::array<glm::vec3, 8> flatCorners = worldCorners(flat.bounds, flatMesh.model);
            Aabb flatBox;
            for (const glm::vec3& corner : flatCorners) {
                flatBox.extend(corner);
            }
            const float reach = std::max(glm::length(flatBox.min), glm::length(flatBox.max));
            const float tolerance = 1e-5f * glm::length(flatBox.max - flatBox.min) + 1e-6f * reach;
            const auto onLightSide = [&](const Aabb& box, const glm::mat4& model) {
                return castsNoShadow(*plane, light, worldCorners(box, model), tolerance);
            };
            const bool noneBehind =
                castsNoShadow(*plane, light, sceneBox.corners(), tolerance) ||
                std::all_of(meshes.begin(), meshes.end(), [&](const PlacedChunks& mesh) {
                    return onLightSide(mesh.bounds, mesh.model) ||
                           std::all_of(mesh.chunks.begin(), mesh.chunks.end(), [&](const MeshChunk& chunk) {
                               if (&chunk == &flat) {
                                   return true;
                               }
                               if (chunk.plane) {
                                   const std::optional<glm::vec4> other =
                                       worldPlane(*chunk.plane, mesh.model);
                                   if (other && samePlane(*plane, *other, tolerance, reach)) {
                                       return true;
                                   }
                               }
                               return onLightSide(chunk.bounds, mesh.model);
                           });
                });
            if (noneBehind) {
                shadowless.push_back(&flat);
            }
        }
    }
    return shadowless;
}

} // namespace engine
