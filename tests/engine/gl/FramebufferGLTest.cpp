// engine::gl::Framebuffer: attachments, draw buffers, and the completeness check that names the framebuffer.
#include "../GLTestContext.h"

#include <engine/Error.h>
#include <engine/gl/Framebuffer.h>

#include <gtest/gtest.h>

#include <string>

TEST(FramebufferGLTest, DepthOnlyAndColourTargetsAreComplete) {
    glTestContext();
    const engine::gl::Texture depth(GL_DEPTH_COMPONENT24, {32, 32});
    engine::gl::Framebuffer depthOnly("depth only");
    depthOnly.attach(GL_DEPTH_ATTACHMENT, depth);
    depthOnly.setDrawBuffers({});
    EXPECT_NO_THROW(depthOnly.check());

    const engine::gl::Texture colour(GL_RGBA8, {32, 32});
    engine::gl::Framebuffer withColour("with colour");
    withColour.attach(GL_DEPTH_ATTACHMENT, depth);
    withColour.attach(GL_COLOR_ATTACHMENT0, colour);
    withColour.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    EXPECT_NO_THROW(withColour.check());

    // What is drawn lands in the attached texture.
    withColour.bind();
    glViewport(0, 0, 32, 32);
    const float red[4] = {1.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(withColour.id(), GL_COLOR, 0, red);
    unsigned char texel[4] = {};
    glGetTextureSubImage(colour.id(), 0, 5, 5, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, sizeof texel, texel);
    EXPECT_EQ(texel[0], 255);
    EXPECT_EQ(texel[1], 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST(FramebufferGLTest, DepthOnlyConstructorAttachesTheDepthAndDrawsNoColour) {
    glTestContext();
    const engine::gl::Texture depth(GL_DEPTH_COMPONENT32F, {16, 8});
    const engine::gl::Framebuffer framebuffer("depth target", depth);
    GLint attached = 0;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer.id(), GL_DEPTH_ATTACHMENT,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &attached);
    EXPECT_EQ(static_cast<GLuint>(attached), depth.id());
    framebuffer.bind();
    GLint drawBuffer = -1;
    glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EXPECT_EQ(drawBuffer, GL_NONE);
    // A colour texture is no depth: the framebuffer is incomplete, and the error names it.
    const engine::gl::Texture colour(GL_RGBA8, {16, 8});
    try {
        const engine::gl::Framebuffer wrong("not a depth target", colour);
        FAIL() << "expected GlError";
    } catch (const engine::GlError& error) {
        EXPECT_NE(std::string(error.what()).find("not a depth target"), std::string::npos) << error.what();
    }
}

TEST(FramebufferGLTest, IncompleteFramebufferIsAnErrorNamingIt) {
    glTestContext();
    const engine::gl::Framebuffer empty("the empty one");
    try {
        empty.check();
        FAIL() << "an attachment-less framebuffer is incomplete";
    } catch (const engine::GlError& error) {
        EXPECT_NE(std::string(error.what()).find("the empty one"), std::string::npos) << error.what();
    }
}
