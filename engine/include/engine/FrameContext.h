#pragma once

#include <engine/Components.h>
#include <engine/Scene.h>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace engine {

/// @brief Where a frame is drawn: a framebuffer name (0 = the window) and its size in pixels.
struct FrameTarget {
    GLuint framebuffer = 0;
    glm::ivec2 size{0};
};

/// @brief A light as the lighting pass sees it; `index` is its slot in the shader's light array.
struct FrameLight {
    int index = 0;
    EntityId entity = kNoEntity;
    LightComponent light;
    /// World position of the light's entity; where spot and point lights shine from.
    glm::vec3 position{0.0f};
    /// Unit vector the light shines along (world space): the entity's -Z axis. Directional and spot lights
    /// only; a point light shines every way, so for it this is just the entity's orientation.
    glm::vec3 direction{0.0f, 0.0f, -1.0f};

    bool operator==(const FrameLight&) const = default;
};

/// @brief Everything modules may read about the frame being drawn.
struct FrameContext {
    explicit FrameContext(const Scene& frameScene) : scene(frameScene) {}

    const Scene& scene;
    EntityId camera = kNoEntity;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    FrameTarget target;
    std::uint64_t frameIndex = 0;
    /// Lights in shader order (at most ForwardRenderer::kMaxLights).
    std::vector<FrameLight> lights;
};

/// @brief One mesh draw of the lighting pass.
struct DrawContext {
    const FrameContext& frame;
    EntityId entity = kNoEntity;
    const MeshData& mesh;
    glm::mat4 model{1.0f};
};

} // namespace engine
