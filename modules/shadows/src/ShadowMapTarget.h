#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/ShadowPlan.h>

#include <engine/gl/Framebuffer.h>
#include <engine/gl/Texture.h>

#include <optional>

namespace shadows {

/// @brief The render targets of one light's shadow map, in the formats the plan names: the depth buffer,
/// and the gradient or the filtered moments (with the blur's temporary level) where the technique stores
/// them.
struct ShadowMapTarget {
    ShadowMapTarget(int resolution, const ShadowPlan& plan);

    /// @brief GPU memory of these targets, bytes (the moments' mip chain counts 4/3 of level 0).
    [[nodiscard]] std::size_t bytes(const ShadowPlan& plan) const;
    /// @brief The texture the lighting pass samples: the moments where there are some, else the depth.
    [[nodiscard]] GLuint sampledTexture() const;

    int lightIndex = -1;
    LightProjection projection;
    engine::gl::Texture depth;
    std::optional<engine::gl::Texture> gradient;
    std::optional<engine::gl::Texture> moments;
    std::optional<engine::gl::Texture> blurTemporary;
    std::optional<engine::gl::Framebuffer> blurFramebuffer;
    engine::gl::Framebuffer framebuffer;
};

} // namespace shadows
