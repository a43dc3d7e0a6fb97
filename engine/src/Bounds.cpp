#include <engine/Bounds.h>

#include <algorithm>

namespace engine {

void Aabb::extend(const glm::vec3& point) {
    min = glm::min(min, point);
    max = glm::max(max, point);
}

void Aabb::extend(const Aabb& box) {
    if (!box.empty()) {
        extend(box.min);
        extend(box.max);
    }
}

std::array<glm::vec3, 8> Aabb::corners() const {
    return {glm::vec3(min.x, min.y, min.z), glm::vec3(max.x, min.y, min.z), glm::vec3(min.x, max.y, min.z),
            glm::vec3(max.x, max.y, min.z), glm::vec3(min.x, min.y, max.z), glm::vec3(max.x, min.y, max.z),
            glm::vec3(min.x, max.y, max.z), glm::vec3(max.x, max.y, max.z)};
}

Aabb Aabb::transformed(const glm::mat4& matrix) const {
    Aabb result;
    if (empty()) {
        return result;
    }
    for (const glm::vec3& corner : corners()) {
        result.extend(glm::vec3(matrix * glm::vec4(corner, 1.0f)));
    }
    return result;
}

bool intersectsClipVolume(const Aabb& box, const glm::mat4& clipFromBox) {
    if (box.empty()) {
        return false;
    }
    std::array<glm::vec4, 8> clip;
    const auto corners = box.corners();
    for (std::size_t i = 0; i < 8; ++i) {
        clip[i] = clipFromBox * glm::vec4(corners[i], 1.0f);
    }
    // Each clip half-space (±x, ±y, ±z ≤ w) is linear in the position, so a box whose corners all lie outside
    // one of them lies outside it entirely. NaN compares false: such a box is kept.
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {-1.0f, 1.0f}) {
            const bool allOutside = std::all_of(clip.begin(), clip.end(),
                                                [&](const glm::vec4& c) { return sign * c[axis] > c.w; });
            if (allOutside) {
                return false;
            }
        }
    }
    return true;
}

} // namespace engine
