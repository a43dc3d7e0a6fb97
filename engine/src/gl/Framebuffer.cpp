#include <engine/Error.h>
#include <engine/gl/Framebuffer.h>

#include <cstdio>
#include <string>
#include <vector>

namespace engine::gl {

static GLuint createFramebuffer() {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return name;
}

Framebuffer::Framebuffer(std::string_view label) : object_(createFramebuffer()), label_(label) {
    glObjectLabel(GL_FRAMEBUFFER, object_.id(), static_cast<GLsizei>(label_.size()), label_.data());
}

Framebuffer::Framebuffer(std::string_view label, const Texture& depth) : Framebuffer(label) {
    attach(GL_DEPTH_ATTACHMENT, depth);
    setDrawBuffers({});
    check();
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, GLint level) {
    glNamedFramebufferTexture(object_.id(), attachment, texture.id(), level);
}

void Framebuffer::attach(GLenum attachment, const TextureArray& texture, GLint layer, GLint level) {
    glNamedFramebufferTextureLayer(object_.id(), attachment, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(std::initializer_list<GLenum> buffers) {
    if (buffers.size() == 0) {
        glNamedFramebufferDrawBuffer(object_.id(), GL_NONE);
        glNamedFramebufferReadBuffer(object_.id(), GL_NONE);
        return;
    }
    std::vector<GLenum> list(buffers);
    glNamedFramebufferDrawBuffers(object_.id(), static_cast<GLsizei>(list.size()), list.data());
}

void Framebuffer::check() const {
    const GLenum status = glCheckNamedFramebufferStatus(object_.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", status);
        throw GlError("framebuffer '" + label_ + "' is incomplete (status " + hex + ")");
    }
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, object_.id());
}

void Framebuffer::beginDepthPass(glm::ivec2 size) const {
    bind();
    glViewport(0, 0, size.x, size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
}

} // namespace engine::gl
