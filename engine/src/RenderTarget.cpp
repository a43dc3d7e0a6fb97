#include <engine/RenderTarget.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace engine {

RenderTarget::RenderTarget(glm::ivec2 size, ColorFormat format)
    : size_(size), format_(format), color_(format == ColorFormat::Srgb8 ? GL_SRGB8_ALPHA8 : GL_RGBA32F, size),
      depth_(GL_DEPTH_COMPONENT24, size), framebuffer_("render target") {
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, color_);
    framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
    framebuffer_.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    framebuffer_.check();
}

void RenderTarget::bind() const {
    framebuffer_.bind();
    glViewport(0, 0, size_.x, size_.y);
}

namespace {

/// Reads the colour attachment of `framebuffer` as `type` and flips rows to top-to-bottom order.
template <typename T>
std::vector<T> readRows(GLuint framebuffer, glm::ivec2 size, GLenum type) {
    const std::size_t rowItems = static_cast<std::size_t>(size.x) * 4;
    std::vector<T> data(rowItems * static_cast<std::size_t>(size.y));
    glNamedFramebufferReadBuffer(framebuffer, GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, type, data.data());
    // GL rows run bottom to top; images run top to bottom.
    for (int y = 0; y < size.y / 2; ++y) {
        auto top = data.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * rowItems);
        auto bottom =
            data.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(size.y - 1 - y) * rowItems);
        std::swap_ranges(top, top + static_cast<std::ptrdiff_t>(rowItems), bottom);
    }
    return data;
}

} // namespace

Image RenderTarget::readPixels() const {
    Image image;
    image.size = size_;
    image.pixels = readRows<std::uint8_t>(framebuffer_.id(), size_, GL_UNSIGNED_BYTE);
    return image;
}

std::vector<float> RenderTarget::readPixelsFloat() const {
    return readRows<float>(framebuffer_.id(), size_, GL_FLOAT);
}

} // namespace engine
