#include <engine/RenderTarget.h>

#include <algorithm>

namespace engine {

RenderTarget::RenderTarget(glm::ivec2 size)
    : size_(size), color_(GL_SRGB8_ALPHA8, size), depth_(GL_DEPTH_COMPONENT24, size),
      framebuffer_("render target") {
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, color_);
    framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
    framebuffer_.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    framebuffer_.check();
}

void RenderTarget::bind() const {
    framebuffer_.bind();
    glViewport(0, 0, size_.x, size_.y);
}

Image RenderTarget::readPixels() const {
    Image image;
    image.size = size_;
    const std::size_t rowBytes = static_cast<std::size_t>(size_.x) * 4;
    image.pixels.resize(rowBytes * static_cast<std::size_t>(size_.y));
    glNamedFramebufferReadBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    // GL rows run bottom to top; images run top to bottom.
    for (int y = 0; y < size_.y / 2; ++y) {
        auto top = image.pixels.begin() + static_cast<std::ptrdiff_t>(y * rowBytes);
        auto bottom = image.pixels.begin() + static_cast<std::ptrdiff_t>((size_.y - 1 - y) * rowBytes);
        std::swap_ranges(top, top + static_cast<std::ptrdiff_t>(rowBytes), bottom);
    }
    return image;
}

} // namespace engine
