#pragma once

#include <engine/Module.h>

#include <glm/vec2.hpp>

namespace sandbox {

/// @brief Restricts an engine's lighting pass to a rectangle of the frame, so that two engines can draw the
/// two sides of one split-screen frame.
///
/// Attach it after the shadow module: it turns the scissor test on at the end of the pre-passes (the shadow
/// maps must be drawn and cleared whole) and off again after the lighting pass. The lighting pass's glClear
/// honours the scissor, so the other side of the frame is left untouched.
class ScissorModule final : public engine::Module {
public:
    [[nodiscard]] std::string_view name() const override { return "sandbox-scissor"; }

    /// @brief The rectangle the lighting pass may touch: lower-left corner and size in pixels (GL
    /// convention).
    void setRectangle(glm::ivec2 origin, glm::ivec2 size);

    void prepareFrame(const engine::FrameContext& frame) override;
    void renderPrePasses(const engine::FrameContext& frame) override;
    void debugDraw(const engine::FrameContext& frame) override;

private:
    glm::ivec2 origin_{0};
    glm::ivec2 size_{0};
};

} // namespace sandbox
