#include "ProbeModule.h"

#include <engine/gl/Program.h>

void ProbeModule::attach(engine::ModuleHost& host) {
    events.push_back("attach");
    flag_ = host.variantFlag("GS_PROBE");
}

void ProbeModule::detach() {
    events.push_back("detach");
}

std::vector<engine::ShaderChunk> ProbeModule::shaderChunks() const {
    return {
        {"declarations", "probe/declarations", "#ifdef GS_PROBE\nuniform float uProbeVisibility;\n#endif"},
        {"light_visibility", "probe/visibility", "#ifdef GS_PROBE\nvisibility *= uProbeVisibility;\n#endif"}};
}

void ProbeModule::prepareFrame(const engine::FrameContext& frame) {
    events.push_back("prepareFrame:" + std::to_string(frame.lights.size()) + " lights");
}

void ProbeModule::renderPrePasses(const engine::FrameContext&) {
    events.push_back("renderPrePasses");
}

engine::ShaderVariantKey ProbeModule::variantBits(const engine::DrawContext&) const {
    return flag_;
}

void ProbeModule::bindLightingResources(const engine::gl::Program& program, const engine::DrawContext& draw) {
    events.push_back("bindLightingResources:" + draw.mesh.name);
    program.set("uProbeVisibility", visibilityScale);
}

void ProbeModule::debugDraw(const engine::FrameContext&) {
    events.push_back("debugDraw");
}
