// ShadowMapTarget: a light's render targets in the formats of the plan.
#include "../engine/GLTestContext.h"

#include "ShadowMapTarget.h"

#include <gtest/gtest.h>

using namespace shadows;

namespace {

GLint textureLevelParameter(GLuint texture, GLint level, GLenum parameter) {
    GLint value = 0;
    glGetTextureLevelParameteriv(texture, level, parameter, &value);
    return value;
}

} // namespace

TEST(ShadowMapTargetGLTest, DepthOnlyMapsHoldTheDepthFormatAlone) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::HardCompare;
    settings.depthFormat = DepthFormat::D16;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapTarget target(128, plan);
    EXPECT_FALSE(target.gradient || target.moments);
    EXPECT_EQ(target.sampledTexture(), target.depth.id());
    EXPECT_EQ(textureLevelParameter(target.depth.id(), 0, GL_TEXTURE_INTERNAL_FORMAT), GL_DEPTH_COMPONENT16);
    EXPECT_EQ(target.bytes(plan), 128u * 128u * 2u);
}

TEST(ShadowMapTargetGLTest, StoredGradientsAddAnRgTarget) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::Gsm;
    settings.gradientSource = GradientSource::StoredDerivatives;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapTarget target(64, plan);
    ASSERT_TRUE(target.gradient);
    EXPECT_EQ(target.gradient->internalFormat(), static_cast<GLenum>(GL_RG32F));
    EXPECT_EQ(target.bytes(plan), 64u * 64u * (4u + 8u));
}

TEST(ShadowMapTargetGLTest, MomentsAreMipmappedInThePlansFormatAndSampled) {
    glTestContext();
    ShadowSettings settings;
    settings.technique = ShadowTechnique::Msm;
    settings.msmQuantize16 = true;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    const ShadowMapTarget target(64, plan);
    ASSERT_TRUE(target.moments && target.blurTemporary);
    EXPECT_EQ(target.moments->internalFormat(), static_cast<GLenum>(GL_RGBA16));
    EXPECT_EQ(target.sampledTexture(), target.moments->id());
    EXPECT_EQ(textureLevelParameter(target.moments->id(), 6, GL_TEXTURE_WIDTH), 1); // 64 .. 1: seven levels
    // Depth, the mip chain (4/3 of level 0) and the blur's temporary level.
    EXPECT_EQ(target.bytes(plan), 64u * 64u * 4u + 64u * 64u * 8u * 4u / 3u + 64u * 64u * 8u);
}
