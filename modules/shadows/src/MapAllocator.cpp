#include "MapAllocator.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace shadows {

float softLightSize(const engine::LightComponent& light, float lightSizeScale) {
    return light.type == engine::LightType::Directional
               ? std::tan(0.5f * std::min(lightSizeScale * light.angularDiameter,
                                          engine::LightComponent::kMaxAngularDiameter))
               : lightSizeScale * light.radius;
}

int addSlot(std::vector<MapSlot>& slots, int lightIndex, const LightProjection& projection, int resolution) {
    if (!projection.valid || slots.size() == static_cast<std::size_t>(kMaxMaps)) {
        return -1;
    }
    slots.push_back({lightIndex, projection, resolution});
    return static_cast<int>(slots.size()) - 1;
}

void setFaceSlot(LightMapsBlock& maps, int face, int slot) {
    if (face < 4) {
        maps.slots[face] = slot;
    } else {
        maps.faceSlots[face - 4] = slot;
    }
}

std::int32_t drawnKind(const LightMapsBlock& maps, LightMapsKind drawn) {
    const bool any = glm::any(glm::greaterThanEqual(maps.slots, glm::ivec4(0))) ||
                     glm::any(glm::greaterThanEqual(maps.faceSlots, glm::ivec4(0)));
    return static_cast<std::int32_t>(any ? drawn : LightMapsKind::None);
}

void clearMapTargets(const ShadowMapArray& maps, GLuint framebuffer, const ShadowPlan& plan) {
    if (maps.gradient) {
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, zero);
    } else if (maps.moments) {
        glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, glm::value_ptr(plan.momentsClear));
    }
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
}

glm::ivec4 drawnTexels(const LightProjection& projection, int side) {
    const glm::vec4 region = glm::clamp(projection.drawnRegion, 0.0f, 1.0f) * static_cast<float>(side);
    const glm::ivec2 low(glm::floor(glm::vec2(region.x, region.y)));
    const glm::ivec2 high(glm::ceil(glm::vec2(region.z, region.w)));
    return {low, glm::max(high - low, glm::ivec2(0))};
}

glm::vec4 lightPosition(const LightProjection& projection) {
    const glm::mat4 worldFromLight = glm::inverse(projection.view);
    // GL's eye looks down its -z: a directional light lies towards +z.
    return projection.perspective ? worldFromLight[3] : worldFromLight[2];
}

void accumulate(engine::DrawnMeshes& total, const engine::DrawnMeshes& drawn) {
    total.drawCalls += drawn.drawCalls;
    total.triangles += drawn.triangles;
    total.culledChunks += drawn.culledChunks;
    total.shadowlessChunks += drawn.shadowlessChunks;
}

engine::DrawnMeshes drawCasters(engine::ModuleHost& host, const engine::Scene& scene,
                                const engine::gl::Program& program, const LightProjection& projection,
                                const CasterOmissions& omissions) {
    const glm::mat4 viewProjection = projection.projection * projection.view;
    program.set("uLightViewProjection", viewProjection);
    program.set("uDepthRange", projection.depthRange);
    const glm::dvec2 low(projection.drawnRegion.x, projection.drawnRegion.y);
    const glm::dvec2 size =
        glm::max(glm::dvec2(projection.drawnRegion.z, projection.drawnRegion.w) - low, glm::dvec2(1e-6));
    const engine::MeshPass pass{omissions.hiddenFaces, omissions.shadowlessPlanes
                                                           ? std::optional(lightPosition(projection))
                                                           : std::nullopt};
    return host.drawMeshes(scene, glm::mat4(textureRectClip(low, size)) * viewProjection, pass,
                           [&](engine::EntityId, const glm::mat4& model) {
                               program.set("uModel", model);
                               return true;
                           });
}

} // namespace shadows
