#pragma once

#include <engine/Module.h>
#include <engine/gl/GlObject.h>
#include <shadows/ShadowSettings.h>

#include <glm/mat4x4.hpp>

namespace shadowbench {

/// @brief What one probe fetch is: a bilinear read of a depth map (what GSM and the moment techniques read),
/// or a hardware comparison with 2x2 PCF (what `hw-pcf` and the PCF kernels read).
enum class FetchKind { Filtered, Compare };

/// @brief The depth map a probe reads: its side in texels and its depth format. Its bytes per texel and
/// texels per pixel set how much memory one read per fragment moves.
struct ProbeMap {
    int size = 2048;
    shadows::DepthFormat format = shadows::DepthFormat::D24;
};

/// @brief The cost model's reference: a lighting-pass module that makes exactly `fetches` reads of a depth
/// array (ProbeMap, 2048² D24 by default, the default technique's map) per light and fragment, at coordinates
/// projected like a shadow map's, and nothing else; the lighting pass's time against the fetch count gives
/// one fetch's cost on this renderer.
class FetchProbe final : public engine::Module {
public:
    /// The fetch counts a probe can make (one variant each).
    static constexpr int kCounts[] = {1, 2, 4, 8, 16};
    /// The maps besides the default's whose one comparison read the cost model measures (SceneCost::
    /// oneCompareReadByMap): smaller sides, and the other depth formats at 2048².
    static constexpr ProbeMap kOtherMaps[] = {{512, shadows::DepthFormat::D24},
                                              {1024, shadows::DepthFormat::D24},
                                              {2048, shadows::DepthFormat::D16},
                                              {2048, shadows::DepthFormat::D32F}};

    /// @param worldToMap world -> map texture coordinates and depth (a light's orthographic fit).
    FetchProbe(FetchKind kind, int fetches, const glm::mat4& worldToMap, ProbeMap map = {});

    [[nodiscard]] std::string_view name() const override { return "fetch-probe"; }
    void attach(engine::ModuleHost& host) override;
    [[nodiscard]] std::vector<engine::ShaderChunk> shaderChunks() const override;
    [[nodiscard]] engine::ShaderVariantKey variantBits(const engine::DrawContext& draw) const override;
    void bindLightingResources(const engine::gl::Program& program, const engine::DrawContext& draw) override;

    /// @brief Changes the count (one of kCounts) for the next frame.
    void setFetches(int fetches);

private:
    FetchKind kind_;
    int fetches_;
    glm::mat4 worldToMap_;
    ProbeMap mapFormat_;
    engine::ModuleHost* host_ = nullptr;
    GLuint unit_ = 0;
    engine::gl::GlObject<engine::gl::detail::deleteTexture> map_;
    engine::gl::GlObject<engine::gl::detail::deleteSampler> sampler_;
};

} // namespace shadowbench
