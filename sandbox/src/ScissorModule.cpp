#include "ScissorModule.h"

#include <epoxy/gl.h>

namespace sandbox {

void ScissorModule::setRectangle(glm::ivec2 origin, glm::ivec2 size) {
    origin_ = origin;
    size_ = size;
}

void ScissorModule::prepareFrame(const engine::FrameContext&) {
    // Pre-passes of the modules attached before this one clear and draw whole shadow maps.
    glDisable(GL_SCISSOR_TEST);
}

void ScissorModule::renderPrePasses(const engine::FrameContext&) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(origin_.x, origin_.y, size_.x, size_.y);
}

void ScissorModule::debugDraw(const engine::FrameContext&) {
    glDisable(GL_SCISSOR_TEST);
}

} // namespace sandbox
