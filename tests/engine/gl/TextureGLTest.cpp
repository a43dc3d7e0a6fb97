// engine::gl::Texture: immutable storage of the asked format, size and levels.
#include "../GLTestContext.h"

#include <engine/gl/Texture.h>

#include <gtest/gtest.h>

TEST(TextureGLTest, AllocatesTheFormatSizeAndLevels) {
    glTestContext();
    const engine::gl::Texture texture(GL_RG32F, {64, 32}, 3);
    EXPECT_EQ(texture.size(), glm::ivec2(64, 32));
    EXPECT_EQ(texture.internalFormat(), static_cast<GLenum>(GL_RG32F));
    GLint levels = 0;
    GLint format = 0;
    GLint width = 0;
    glGetTextureParameteriv(texture.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    glGetTextureLevelParameteriv(texture.id(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture.id(), 2, GL_TEXTURE_WIDTH, &width);
    EXPECT_EQ(levels, 3);
    EXPECT_EQ(format, GL_RG32F);
    EXPECT_EQ(width, 16);
}

TEST(TextureGLTest, FilterSettingsReachTheTexture) {
    glTestContext();
    engine::gl::Texture texture(GL_RGBA8, {4, 4});
    texture.setFilter(GL_NEAREST, GL_LINEAR);
    GLint minFilter = 0;
    GLint magFilter = 0;
    glGetTextureParameteriv(texture.id(), GL_TEXTURE_MIN_FILTER, &minFilter);
    glGetTextureParameteriv(texture.id(), GL_TEXTURE_MAG_FILTER, &magFilter);
    EXPECT_EQ(minFilter, GL_NEAREST);
    EXPECT_EQ(magFilter, GL_LINEAR);
}
