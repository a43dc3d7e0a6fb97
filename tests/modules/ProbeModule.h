#pragma once

#include <engine/Module.h>

#include <string>
#include <vector>

/// @brief Test module: records every hook call and scales each light's visibility by `visibilityScale`
/// through a shader chunk, so tests can observe both the hook order and the chunk's effect.
class ProbeModule final : public engine::Module {
public:
    [[nodiscard]] std::string_view name() const override { return "probe"; }
    void attach(engine::ModuleHost& host) override;
    void detach() override;
    [[nodiscard]] std::vector<engine::ShaderChunk> shaderChunks() const override;
    void prepareFrame(const engine::FrameContext& frame) override;
    void renderPrePasses(const engine::FrameContext& frame) override;
    [[nodiscard]] engine::ShaderVariantKey variantBits(const engine::DrawContext& draw) const override;
    void bindLightingResources(const engine::gl::Program& program, const engine::DrawContext& draw) override;
    void debugDraw(const engine::FrameContext& frame) override;

    std::vector<std::string> events;
    float visibilityScale = 0.5f;

private:
    engine::ShaderVariantKey flag_ = 0;
};
