#pragma once

#include <engine/Module.h>
#include <engine/gl/GlObject.h>

#include <glm/mat4x4.hpp>

namespace shadowbench {

/// @brief What one probe fetch is: a bilinear read of a depth map (what GSM and the moment techniques read),
/// or a hardware comparison with 2x2 PCF (what `hw-pcf` and the PCF kernels read).
enum class FetchKind { Filtered, Compare };

/// @brief The cost model's reference: a lighting-pass module that makes exactly `fetches` reads of a 2048²
/// depth array per light and fragment, at coordinates projected like a shadow map's, and nothing else; the
/// lighting pass's time against the fetch count gives one fetch's cost on this renderer.
class FetchProbe final : public engine::Module {
public:
    /// The fetch counts a probe can make (one variant each).
    static constexpr int kCounts[] = {1, 2, 4, 8, 16};

    /// @param worldToMap world -> map texture coordinates and depth (a light's orthographic fit).
    FetchProbe(FetchKind kind, int fetches, const glm::mat4& worldToMap);

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
    engine::ModuleHost* host_ = nullptr;
    GLuint unit_ = 0;
    engine::gl::GlObject<engine::gl::detail::deleteTexture> map_;
    engine::gl::GlObject<engine::gl::detail::deleteSampler> sampler_;
};

} // namespace shadowbench
