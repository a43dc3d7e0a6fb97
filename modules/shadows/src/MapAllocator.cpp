#include "MapAllocator.h"

#include <glm/glm.hpp>

namespace shadows {

int addSlot(std::vector<MapSlot>& slots, int lightIndex, const LightProjection& projection, int resolution) {
    if (!projection.valid || slots.size() == static_cast<std::size_t>(kMaxMaps)) {
        return -1;
    }
    slots.push_back({lightIndex, projection, resolution});
    return static_cast<int>(slots.size()) - 1;
}

std::int32_t drawnKind(const LightMapsBlock& maps, LightMapsKind drawn) {
    const bool any = glm::any(glm::greaterThanEqual(maps.slots, glm::ivec4(0))) ||
                     glm::any(glm::greaterThanEqual(maps.faceSlots, glm::ivec4(0)));
    return static_cast<std::int32_t>(any ? drawn : LightMapsKind::None);
}

} // namespace shadows
