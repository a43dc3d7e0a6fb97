// JitterTexture: the stratified offsets of jittered PCF as a 3D texture.
#include "../engine/GLTestContext.h"

#include "JitterTexture.h"

#include <gtest/gtest.h>

using namespace shadows;

TEST(JitterTextureGLTest, HoldsTwoOffsetsPerTexelOfA32x32Tile) {
    glTestContext();
    const JitterTexture jitter(16);
    EXPECT_EQ(jitter.taps(), 16);
    GLint width = 0;
    GLint depth = 0;
    GLint format = 0;
    glGetTextureLevelParameteriv(jitter.id(), 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(jitter.id(), 0, GL_TEXTURE_DEPTH, &depth);
    glGetTextureLevelParameteriv(jitter.id(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    EXPECT_EQ(width, 32);
    EXPECT_EQ(depth, 8);
    EXPECT_EQ(format, GL_RGBA16);
}
