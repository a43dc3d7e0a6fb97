#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/SampleDistribution.h>

#include <engine/Module.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Program.h>
#include <engine/gl/Texture.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace shadows {

/// @brief What the camera sees, for Sample Distribution Shadow Maps: the view's depth at the frame's size
/// (the lighting pass's depth pre-pass where the host shares it, else a depth-only pass of its own), reduced
/// on the GPU (shaders/shadows/samples.comp) to the visible samples' view-depth range and the light-space box
/// of the samples in each candidate cascade slice. Drawn and read back within the frame, before the shadow
/// maps: no latency, so a camera cut fits the new view at once. The reduction is the larger part of the
/// sample pass's cost on a software rasteriser, and the cascades' nine slices most of it, so they are
/// measured only when asked for.
class VisibleSamples {
public:
    /// @brief The reduction of one frame.
    struct Bounds {
        glm::vec2 viewDepth{0.0f};
        std::array<glm::vec2, kSampleSlices> sliceDepths{};
        std::array<LightRect, kSampleSlices> slices{};
        /// Whether the cascades' slices (1 on) were measured (measureCascadeSlices); else only slice 0, the
        /// whole range's, was, and the others are empty.
        bool cascadeSlices = false;
    };

    /// @brief Draws the view of `fit` over `frame.scene` into the sample depth image (reallocated when the
    /// frame's size changes) and reduces it for a light whose maps use `worldToLight` (affine), with the
    /// cascade split scheme's `weight` and `blend`: the view-depth range, the slices' depths and slice 0's
    /// box, in one pass. nullopt when no sample holds a surface or their depths are not finite (an empty
    /// view, a degenerate projection). Leaves the frame's framebuffer and viewport bound.
    std::optional<Bounds> measure(engine::ModuleHost& host, const engine::FrameContext& frame,
                                  const FitView& fit, const glm::mat4& worldToLight, float weight,
                                  float blend);
    /// @brief Reduces the cascades' slices (1 on) of `bounds`, the last measure's result, from the same depth
    /// image, view and light, and sets `bounds.cascadeSlices`.
    void measureCascadeSlices(engine::ModuleHost& host, Bounds& bounds);

    /// @brief Draws the view of `fit` over `frame.scene` into the sample depth image only (what measure does
    /// first; virtual maps mark their pages from it). When `fit` is the frame's own view, takes the lighting
    /// pass's depth pre-pass instead (ModuleHost::viewDepth) where the host offers it. Leaves the frame's
    /// framebuffer and viewport bound.
    void draw(engine::ModuleHost& host, const engine::FrameContext& frame, const FitView& fit);
    /// @brief The sample depth image of the last draw (the frame's size): the host's view depth, or this
    /// pass's own (GL_DEPTH_COMPONENT32F); 0 before the first draw.
    [[nodiscard]] GLuint depthTexture() const {
        return sharedDepth_ != 0 ? sharedDepth_ : depth_ ? depth_->id() : 0;
    }
    /// @brief Whether the last draw took the host's view depth rather than drawing its own.
    [[nodiscard]] bool sharedDepth() const { return sharedDepth_ != 0; }
    /// @brief Draws so far (each measure draws once), so a caller can tell whether a step drew.
    [[nodiscard]] std::uint64_t draws() const { return draws_; }

    /// @brief The sample depth image of the last measure (window depths, rows from the bottom), for tests
    /// of the reduction against its CPU mirror.
    [[nodiscard]] std::vector<float> readDepth() const;
    [[nodiscard]] glm::ivec2 size() const { return size_; }

private:
    // The bounds buffer (samples.comp's GsSampleBounds): the depth range, then per slice min x, y, z, max x,
    // y, z and the sample count.
    static constexpr int kSliceWords = 7;
    static constexpr std::size_t kBoundsWords = 2 + kSampleSlices * kSliceWords;
    enum class Reduction { Whole, CascadeSlices };
    const engine::gl::Program& reduction(engine::ModuleHost& host, Reduction pass);
    /// Runs `program` over the depth image into the bounds buffer, starting from cleared words; returns them.
    std::array<std::uint32_t, kBoundsWords> reduce(const engine::gl::Program& program);
    /// Slices [first, end) of `bounds` from the buffer's words.
    static void readSlices(const std::array<std::uint32_t, kBoundsWords>& words, int first, int end,
                           Bounds& bounds);

    glm::ivec2 size_{0};
    // The host's view depth the last draw took, 0 when it drew its own into depth_.
    GLuint sharedDepth_ = 0;
    std::uint64_t draws_ = 0;
    std::optional<engine::gl::Texture> depth_;
    std::optional<engine::gl::Framebuffer> framebuffer_;
    std::optional<engine::gl::Buffer> bounds_;
    // The last measure's window texel (x, y, depth, 1) to light space (homogeneous, w the world point's) and
    // to the view depth over that w.
    glm::mat4 texelToLight_{1.0f};
    glm::vec4 texelToViewDepth_{0.0f};
    // Compiled on first use: only directional lights fitted to samples need them.
    std::unique_ptr<engine::gl::Program> wholeProgram_;
    std::unique_ptr<engine::gl::Program> cascadeSlicesProgram_;
};

} // namespace shadows
