#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettings.h>
#include <shadows/TapPattern.h>

#include <engine/Module.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/VertexArray.h>

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace shadows {

struct ShadowMapTarget;
class ShadowSamplers;
class JitterTexture;

/// @brief Resource and frame counters of the shadow module.
struct ShadowStats {
    /// Shadow maps drawn in the last frame (one per shadow-casting light with visible receivers).
    int shadowMaps = 0;
    /// GPU memory of the allocated shadow maps (depth plus any gradient target), bytes.
    std::size_t bytes = 0;
};

/// @brief The shadow module: shadow maps for shadow-casting lights and the lighting-pass visibility of the
/// technique in ShadowSettings. Link it and `Engine::addModule`, or load it as module "shadows".
///
/// Settings changes take effect lazily on the next frame (osgShadow style): resources are (re)allocated only
/// for lights that cast shadows and only of the kinds the technique needs; shader variants compile on first
/// draw.
class ShadowModule final : public engine::Module {
public:
    ShadowModule();
    explicit ShadowModule(const ShadowSettings& settings);
    ~ShadowModule() override;

    [[nodiscard]] std::string_view name() const override { return "shadows"; }

    /// @brief Validates and applies `settings`. Throws std::invalid_argument listing each bad field.
    void setSettings(const ShadowSettings& settings);
    [[nodiscard]] const ShadowSettings& settings() const { return settings_; }
    /// @brief What the passes do for the current settings (resolved by setSettings).
    [[nodiscard]] const ShadowPlan& plan() const { return plan_; }
    [[nodiscard]] ShadowStats stats() const;
    /// @brief The projection of the shadow map of engine light `lightIndex` in the last frame, if it has one.
    [[nodiscard]] std::optional<LightProjection> lightProjection(int lightIndex) const;

    void attach(engine::ModuleHost& host) override;
    void detach() override;
    [[nodiscard]] std::vector<engine::ShaderChunk> shaderChunks() const override;
    void prepareFrame(const engine::FrameContext& frame) override;
    void renderPrePasses(const engine::FrameContext& frame) override;
    [[nodiscard]] engine::ShaderVariantKey variantBits(const engine::DrawContext& draw) const override;
    void bindLightingResources(const engine::gl::Program& program, const engine::DrawContext& draw) override;

private:
    void releaseResources();
    void filterMoments();
    /// Writes this frame's GsShadowBlock: the maps' projections, each light's map and the settings' scalars.
    void uploadBlock(const std::vector<int>& slotOfLight);
    [[nodiscard]] engine::ShaderVariantKey variantKey(const std::vector<std::string_view>& defines) const;

    ShadowSettings settings_;
    ShadowPlan plan_;
    TapPattern pattern_;
    engine::ModuleHost* host_ = nullptr;
    std::unique_ptr<ShadowSamplers> samplers_;
    std::vector<GLuint> mapUnits_;
    std::vector<GLuint> gradientUnits_;
    GLuint jitterUnit_ = 0;
    std::unique_ptr<JitterTexture> jitter_;
    std::unique_ptr<engine::gl::VertexArray> fullscreenVertexArray_;
    std::vector<std::unique_ptr<ShadowMapTarget>> maps_;
    std::unique_ptr<engine::gl::Buffer> shadowBlock_;
    engine::ShaderVariantKey lightingKey_ = 0;
    engine::ShaderVariantKey depthKey_ = 0;
    std::map<GLuint, std::uint64_t> uploadedFrame_; // program -> frame whose uniforms it holds
    std::uint64_t frameIndex_ = 0;
    bool dirty_ = true;
};

} // namespace shadows
