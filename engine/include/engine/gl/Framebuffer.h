#pragma once

#include <engine/gl/GlObject.h>
#include <engine/gl/Texture.h>
#include <engine/gl/TextureArray.h>

#include <glm/vec2.hpp>

#include <string_view>

namespace engine::gl {

/// @brief Framebuffer object; attach textures, then check() before drawing.
class Framebuffer {
public:
    /// @brief Creates an empty framebuffer; `label` names it in KHR_debug messages and errors.
    explicit Framebuffer(std::string_view label);
    /// @brief A complete framebuffer that draws depth only, into `depth`; throws GlError when incomplete.
    Framebuffer(std::string_view label, const Texture& depth);

    void attach(GLenum attachment, const Texture& texture, GLint level = 0);
    /// @brief Attaches one layer of an array texture.
    void attach(GLenum attachment, const TextureArray& texture, GLint layer, GLint level = 0);
    /// @brief Selects which colour attachments are drawn to; none for depth-only passes.
    void setDrawBuffers(std::initializer_list<GLenum> buffers);
    /// @brief Throws GlError naming the framebuffer when it is incomplete.
    void check() const;
    void bind() const;
    /// @brief Binds it for a depth pass over `size`: the viewport, a LESS depth test that writes, no face
    /// culling, and the depth cleared to 1.
    void beginDepthPass(glm::ivec2 size) const;

    [[nodiscard]] GLuint id() const { return object_.id(); }

private:
    GlObject<detail::deleteFramebuffer> object_;
    std::string label_;
};

} // namespace engine::gl
