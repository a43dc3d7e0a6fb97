#include "ShadowMapArray.h"

#include <string>

namespace shadows {

namespace {

/// Checks `framebuffer`, one of the targets of `layers` maps of `resolution`², saying what was asked where
/// the driver could not allocate it.
void checkAllocated(const engine::gl::Framebuffer& framebuffer, int resolution, int layers,
                    const ShadowPlan& plan) {
    try {
        framebuffer.check();
    } catch (const engine::GlError& error) {
        throw MapAllocationError("the shadow maps, " + std::to_string(layers) +
                                 (layers == 1 ? " layer of " : " layers of ") + std::to_string(resolution) +
                                 "² (" + std::to_string(plan.mapBytes(resolution, layers) >> 20) +
                                 " MiB), could not be allocated (" + error.what() + ")");
    }
}

} // namespace

ShadowMapArray::ShadowMapArray(int resolution, int layers, const ShadowPlan& plan)
    : depth(plan.depthFormat, glm::ivec2(resolution), plan.sharesDepthLayer ? 1 : layers) {
    const glm::ivec2 size(resolution);
    if (plan.storesGradient) {
        gradient.emplace(GL_RG32F, size, layers);
    } else if (plan.momentsFormat != 0) {
        // Moments are filtered: blurred when the settings ask for it, then read bilinearly at their one level
        // (no mip chain: receiver.glsl, gsShadowMoments), or over the chain a soft technique reads at its
        // width.
        moments.emplace(plan.momentsFormat, size, layers, plan.momentLevelsAt(resolution));
        if (plan.blursMoments) {
            blurTemporary.emplace(plan.momentsFormat, size, 1);
            blurFramebuffer.emplace("shadow moments blur");
            blurFramebuffer->attach(GL_COLOR_ATTACHMENT0, *blurTemporary, 0);
            blurFramebuffer->setDrawBuffers({GL_COLOR_ATTACHMENT0});
            checkAllocated(*blurFramebuffer, resolution, layers, plan);
        }
    }
    framebuffers.reserve(static_cast<std::size_t>(layers));
    for (int layer = 0; layer < layers; ++layer) {
        engine::gl::Framebuffer& framebuffer = framebuffers.emplace_back("shadow map");
        framebuffer.attach(GL_DEPTH_ATTACHMENT, depth, plan.sharesDepthLayer ? 0 : layer);
        if (gradient || moments) {
            framebuffer.attach(GL_COLOR_ATTACHMENT0, gradient ? *gradient : *moments, layer);
            framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        } else {
            framebuffer.setDrawBuffers({});
        }
        checkAllocated(framebuffer, resolution, layers, plan);
    }
}

std::size_t ShadowMapArray::bytes(const ShadowPlan& plan) const {
    return plan.mapBytes(depth.size().x, layers());
}

GLuint ShadowMapArray::sampledTexture() const {
    return moments ? moments->id() : depth.id();
}

} // namespace shadows
