#pragma once

#include <shadows/ShadowPlan.h>

#include <engine/Error.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/TextureArray.h>

#include <optional>
#include <vector>

namespace shadows {

/// @brief The driver could not allocate a ShadowMapArray's targets: it reports a target it could not allocate
/// as an incomplete attachment.
class MapAllocationError : public engine::GlError {
public:
    using GlError::GlError;
};

/// @brief The render targets of every shadow map of a frame, one layer each (a light's map, a cascade, a cube
/// face), in the formats the plan names: the depth (one layer all share where ShadowPlan::sharesDepthLayer),
/// and the gradient or the filtered moments (with the blur's one temporary layer) where the technique stores
/// them. Layers let the lighting pass pick a cascade or a cube face per fragment.
struct ShadowMapArray {
    /// @throws MapAllocationError where the driver cannot allocate them.
    ShadowMapArray(int resolution, int layers, const ShadowPlan& plan);

    /// @brief GPU memory of these targets, bytes (ShadowPlan::mapBytes).
    [[nodiscard]] std::size_t bytes(const ShadowPlan& plan) const;
    /// @brief The texture the lighting pass samples: the moments where there are some, else the depth.
    [[nodiscard]] GLuint sampledTexture() const;
    [[nodiscard]] int layers() const { return static_cast<int>(framebuffers.size()); }

    engine::gl::TextureArray depth;
    std::optional<engine::gl::TextureArray> gradient;
    std::optional<engine::gl::TextureArray> moments;
    std::optional<engine::gl::TextureArray> blurTemporary;
    std::optional<engine::gl::Framebuffer> blurFramebuffer;
    /// One per layer: what the shadow pass draws into for that map.
    std::vector<engine::gl::Framebuffer> framebuffers;
};

} // namespace shadows
