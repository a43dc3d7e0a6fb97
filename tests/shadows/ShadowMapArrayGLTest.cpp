// ShadowMapArray: the frame's shadow maps as layers, in the formats of the plan.
#include "../engine/GLTestContext.h"

#include "ShadowMapArray.h"

#include <gtest/gtest.h>

using namespace shadows;

namespace {

GLint textureLevelParameter(GLuint texture, GLint level, GLenum parameter) {
    GLint value = 0;
    glGetTextureLevelParameteriv(texture, level, parameter, &value);
    return value;
}

} // namespace

TEST(ShadowMapArrayGLTest, DepthOnlyMapsHoldTheDepthFormatAlone) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::HardCompare;
    settings.depthFormat = DepthFormat::D16;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapArray target(128, 3, plan);
    EXPECT_FALSE(target.gradient || target.moments);
    EXPECT_EQ(target.sampledTexture(), target.depth.id());
    EXPECT_EQ(textureLevelParameter(target.depth.id(), 0, GL_TEXTURE_INTERNAL_FORMAT), GL_DEPTH_COMPONENT16);
    EXPECT_EQ(textureLevelParameter(target.depth.id(), 0, GL_TEXTURE_DEPTH), 3);
    EXPECT_EQ(target.layers(), 3);
    EXPECT_EQ(target.bytes(plan), 3u * 128u * 128u * 2u);
}

TEST(ShadowMapArrayGLTest, StoredGradientsAddAnRgTarget) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::Gsm;
    settings.gradientSource = GradientSource::StoredDerivatives;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapArray target(64, 1, plan);
    ASSERT_TRUE(target.gradient);
    EXPECT_EQ(target.gradient->internalFormat(), static_cast<GLenum>(GL_RG32F));
    EXPECT_EQ(target.bytes(plan), 64u * 64u * (4u + 8u));
}

TEST(ShadowMapArrayGLTest, MomentsHaveOneLevelInThePlansFormatOverOneSharedDepthLayer) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::Msm;
    settings.moments16 = true;
    settings.momentBlurRadius = 1;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapArray target(64, 2, plan);
    ASSERT_TRUE(target.moments && target.blurTemporary);
    EXPECT_EQ(target.moments->internalFormat(), static_cast<GLenum>(GL_RGBA16));
    EXPECT_EQ(target.sampledTexture(), target.moments->id());
    // No mip chain: the lookups read the first level only (receiver.glsl, gsShadowMoments).
    EXPECT_EQ(textureLevelParameter(target.moments->id(), 0, GL_TEXTURE_WIDTH), 64);
    EXPECT_EQ(textureLevelParameter(target.moments->id(), 1, GL_TEXTURE_WIDTH), 0);
    // The moments per layer, over one depth layer both maps draw their casters against in turn; one temporary
    // layer for the blur.
    EXPECT_EQ(target.layers(), 2);
    EXPECT_EQ(textureLevelParameter(target.depth.id(), 0, GL_TEXTURE_DEPTH), 1);
    EXPECT_EQ(target.bytes(plan), 64u * 64u * 4u + 2u * 64u * 64u * 8u + 64u * 64u * 8u);
}

TEST(ShadowMapArrayGLTest, UnblurredMomentsHaveNoBlurTemporary) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::Vsm;
    settings.momentBlurRadius = 0;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_FALSE(plan.blursMoments);
    const ShadowMapArray target(64, 1, plan);
    ASSERT_TRUE(target.moments);
    EXPECT_FALSE(target.blurTemporary || target.blurFramebuffer);
    EXPECT_EQ(target.bytes(plan), 64u * 64u * 4u + 64u * 64u * 4u); // D24 depth and RG16 moments
}

TEST(ShadowMapArrayGLTest, SoftMomentsHaveTheirMipChainCountedInTheirBytes) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::MsmSoft;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapArray target(256, 1, plan);
    ASSERT_TRUE(target.moments);
    // Levels 256² down to 4² (7 levels), each read by the sampler at the width a pixel asks for.
    EXPECT_EQ(textureLevelParameter(target.moments->id(), 6, GL_TEXTURE_WIDTH), 4);
    EXPECT_EQ(textureLevelParameter(target.moments->id(), 7, GL_TEXTURE_WIDTH), 0);
    std::size_t momentTexels = 0;
    for (int side = 256; side >= 4; side /= 2) {
        momentTexels += static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    }
    EXPECT_EQ(target.bytes(plan), 256u * 256u * 4u + momentTexels * 8u); // D24, RGBA16 moments
    // A map smaller than the chain ends at one texel.
    EXPECT_EQ(plan.momentLevelsAt(16), 5);
}
