#pragma once

#include <glm/glm.hpp>

#include <array>
#include <limits>

namespace engine {

/// @brief Axis-aligned box; empty (min > max) until extended.
struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    [[nodiscard]] bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& point);
    void extend(const Aabb& box);
    [[nodiscard]] std::array<glm::vec3, 8> corners() const;
    /// @brief The box around this box transformed by `matrix`.
    [[nodiscard]] Aabb transformed(const glm::mat4& matrix) const;
};

/// @brief False only when `box` lies entirely outside one plane of the clip volume of `clipFromBox` (e.g.
/// viewProjection · model for a box in model space). Conservative and exact for culling: every point of a box
/// outside one clip half-space is clipped, so a culled box cannot produce a fragment. A box with non-finite
/// corners is never culled.
[[nodiscard]] bool intersectsClipVolume(const Aabb& box, const glm::mat4& clipFromBox);

} // namespace engine
