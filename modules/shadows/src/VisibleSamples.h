#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/SampleDistribution.h>

#include <engine/Module.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Program.h>
#include <engine/gl/Texture.h>

#include <memory>
#include <optional>
#include <vector>

namespace shadows {

/// @brief What the camera sees, for Sample Distribution Shadow Maps: a depth-only pass of the view at the
/// frame's size, reduced on the GPU (shaders/shadows/samples.comp) to the visible samples' view-depth range
/// and the light-space box of the samples in each candidate cascade slice. Drawn and read back within the
/// frame, before the shadow maps: no latency, so a camera cut fits the new view at once.
class VisibleSamples {
public:
    /// @brief The reduction of one frame.
    struct Bounds {
        glm::vec2 viewDepth{0.0f};
        std::array<glm::vec2, kSampleSlices> sliceDepths{};
        std::array<LightRect, kSampleSlices> slices{};
    };

    /// @brief Draws the view of `fit` over `frame.scene` into the sample depth image (reallocated when the
    /// frame's size changes) and reduces it for a light whose maps use `worldToLight`, with the cascade split
    /// scheme's `weight` and `blend`. nullopt when no sample holds a surface or their depths are not finite
    /// (an empty view, a degenerate projection). Leaves the frame's framebuffer and viewport bound.
    std::optional<Bounds> measure(engine::ModuleHost& host, const engine::FrameContext& frame,
                                  const FitView& fit, const glm::mat4& worldToLight, float weight,
                                  float blend);

    /// @brief Draws the view of `fit` over `frame.scene` into the sample depth image only (what measure does
    /// first; virtual maps mark their pages from it). Leaves the frame's framebuffer and viewport bound.
    void draw(engine::ModuleHost& host, const engine::FrameContext& frame, const FitView& fit);
    /// @brief The sample depth image (GL_DEPTH_COMPONENT32F, the frame's size), 0 before the first draw.
    [[nodiscard]] GLuint depthTexture() const { return depth_ ? depth_->id() : 0; }

    /// @brief The sample depth image of the last measure (window depths, rows from the bottom), for tests
    /// of the reduction against its CPU mirror.
    [[nodiscard]] std::vector<float> readDepth() const;
    [[nodiscard]] glm::ivec2 size() const { return size_; }

private:
    const engine::gl::Program& reduction(engine::ModuleHost& host, bool depthRange);

    glm::ivec2 size_{0};
    std::optional<engine::gl::Texture> depth_;
    std::optional<engine::gl::Framebuffer> framebuffer_;
    std::optional<engine::gl::Buffer> bounds_;
    // Compiled on first use: only directional lights fitted to samples need them.
    std::unique_ptr<engine::gl::Program> depthRangeProgram_;
    std::unique_ptr<engine::gl::Program> lightRectsProgram_;
};

} // namespace shadows
