#include "ShadowMapTarget.h"

namespace shadows {

namespace {

GLsizei mipLevels(int resolution) {
    GLsizei levels = 1;
    while ((resolution >> levels) > 0) {
        ++levels;
    }
    return levels;
}

} // namespace

ShadowMapTarget::ShadowMapTarget(int resolution, const ShadowPlan& plan)
    : depth(plan.depthFormat, glm::ivec2(resolution)), framebuffer("shadow map") {
    framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    if (plan.storesGradient) {
        gradient.emplace(GL_RG32F, glm::ivec2(resolution));
        framebuffer.attach(GL_COLOR_ATTACHMENT0, *gradient);
        framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    } else if (plan.momentsFormat != 0) {
        // Moments are filtered: blurred at level 0, then mipmapped for trilinear lookups.
        moments.emplace(plan.momentsFormat, glm::ivec2(resolution), mipLevels(resolution));
        blurTemporary.emplace(plan.momentsFormat, glm::ivec2(resolution));
        blurFramebuffer.emplace("shadow moments blur");
        blurFramebuffer->attach(GL_COLOR_ATTACHMENT0, *blurTemporary);
        blurFramebuffer->setDrawBuffers({GL_COLOR_ATTACHMENT0});
        blurFramebuffer->check();
        framebuffer.attach(GL_COLOR_ATTACHMENT0, *moments);
        framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    } else {
        framebuffer.setDrawBuffers({});
    }
    framebuffer.check();
}

std::size_t ShadowMapTarget::bytes(const ShadowPlan& plan) const {
    const auto side = static_cast<std::size_t>(depth.size().x);
    const std::size_t texels = side * side;
    std::size_t total = texels * (plan.depthBytesPerTexel + (gradient ? 8 : 0));
    if (moments) {
        // The mip chain (4/3 of level 0) plus the blur's temporary level.
        total += texels * plan.momentBytesPerTexel * 4 / 3 + texels * plan.momentBytesPerTexel;
    }
    return total;
}

GLuint ShadowMapTarget::sampledTexture() const {
    return moments ? moments->id() : depth.id();
}

} // namespace shadows
