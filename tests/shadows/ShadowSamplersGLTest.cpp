// ShadowSamplers: one sampler object per way the lighting pass reads a map.
#include "../engine/GLTestContext.h"

#include "ShadowSamplers.h"

#include <gtest/gtest.h>

using namespace shadows;

namespace {

GLint samplerParameter(GLuint sampler, GLenum parameter) {
    GLint value = 0;
    glGetSamplerParameteriv(sampler, parameter, &value);
    return value;
}

} // namespace

TEST(ShadowSamplersGLTest, EachWayOfReadingAMapHasItsSampler) {
    glTestContext();
    const ShadowSamplers samplers;
    const GLuint nearest = samplers.forMap(MapSampler::CompareNearest);
    const GLuint linear = samplers.forMap(MapSampler::CompareLinear);
    const GLuint moments = samplers.forMap(MapSampler::Moments);
    EXPECT_EQ(samplerParameter(nearest, GL_TEXTURE_COMPARE_MODE), GL_COMPARE_REF_TO_TEXTURE);
    EXPECT_EQ(samplerParameter(nearest, GL_TEXTURE_MAG_FILTER), GL_NEAREST);
    EXPECT_EQ(samplerParameter(linear, GL_TEXTURE_MAG_FILTER), GL_LINEAR);
    EXPECT_EQ(samplerParameter(samplers.forMap(MapSampler::DepthLinear), GL_TEXTURE_COMPARE_MODE), GL_NONE);
    EXPECT_EQ(samplers.forMap(MapSampler::DepthLinear), samplers.linear());
    EXPECT_EQ(samplerParameter(moments, GL_TEXTURE_MIN_FILTER), GL_LINEAR);
    EXPECT_EQ(samplerParameter(moments, GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
    EXPECT_EQ(samplerParameter(nearest, GL_TEXTURE_WRAP_S), GL_CLAMP_TO_BORDER);
}
