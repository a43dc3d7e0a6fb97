#pragma once

#include "MapAllocator.h"

#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettings.h>

#include <limits>
#include <memory>
#include <span>

namespace shadows {

class VisibleSamples;

/// @brief Whole shadow maps of ShadowSettings::resolution² texels, fitted to the view (LightFrustum.h): one
/// per spot light, one or 2–4 cascades per directional light (to the visible samples of a depth pass of the
/// view, or to mesh bounds), a cube face per point light with visible receivers. Every map is a layer of one
/// ShadowMapArray, reallocated only when the number of maps changes.
class FittedShadowMaps final : public MapAllocator {
public:
    /// @brief Maps for `settings` in the formats of `plan`; directional lights fitted to samples measure them
    /// with `samples` and say once in `warnings` when a view has none.
    FittedShadowMaps(engine::ModuleHost& host, const ShadowSettings& settings, const ShadowPlan& plan,
                     VisibleSamples& samples, OnceWarnings& warnings);
    ~FittedShadowMaps() override;

    void allocate(const AllocationFrame& frame, std::vector<MapSlot>& slots,
                  std::vector<LightMapsBlock>& lights) override;
    engine::DrawnMeshes render(const engine::Scene& scene, const engine::gl::Program& program,
                               std::span<const MapSlot> slots, const CasterOmissions& omissions) override;
    [[nodiscard]] bool holds(std::span<const MapSlot> slots) const override;
    void blurMoments(const engine::gl::Program& blur, GLuint unit) override;
    [[nodiscard]] const ShadowMapArray* sampled() const override { return maps_.get(); }
    [[nodiscard]] std::size_t bytes() const override;

private:
    /// @brief Fits every shadow-casting light's maps (allocate) without allocating them.
    void fit(const AllocationFrame& frame, std::vector<MapSlot>& slots, std::vector<LightMapsBlock>& lights);
    /// @brief Holds maps_ at the side and layers `slots` ask for, reallocating where they differ.
    /// @throws MapAllocationError where the driver cannot allocate them.
    void allocateMaps(std::span<const MapSlot> slots);
    [[nodiscard]] static int largestSide(std::span<const MapSlot> slots);
    /// @brief How far, texels, the kernels read beyond a map of `light`: the plan's, less the soft margin for
    /// a light of no size.
    [[nodiscard]] float kernelReach(const engine::FrameLight& light) const;
    /// @brief The soft part of that reach: none for a light of no size; for a directional light of a
    /// technique that follows it (softReachFollowsLight), as wide as its penumbrae over the map's depth.
    [[nodiscard]] SoftMargin softMargin(const engine::FrameLight& light) const;
    /// @brief The side of the frame's maps: ShadowSettings::resolution, or less where the most maps its
    /// shadow-casting lights may take would not fit in ShadowSettings::fittedBudgetMiB at it (said once).
    [[nodiscard]] int budgetedSide(const engine::FrameContext& frame);
    /// Fits directional light `light`'s maps to the visible samples into `maps` and `slots`, at the side
    /// the view needs with `sizeToView` (ShadowSettings::fittedTexelPixels) up to `resolution`, else at
    /// `resolution`; false, having added nothing, when the view has no sample.
    bool fitToVisibleSamples(const AllocationFrame& frame, const engine::FrameLight& light, int resolution,
                             bool sizeToView, std::vector<MapSlot>& slots, LightMapsBlock& maps);
    /// Fits directional light `light`'s maps of `resolution`² to the mesh bounds in view.
    void fitToBounds(const AllocationFrame& frame, const engine::FrameLight& light, int resolution,
                     std::optional<glm::vec2> visibleRange, std::vector<MapSlot>& slots,
                     LightMapsBlock& maps) const;

    engine::ModuleHost& host_;
    ShadowSettings settings_;
    ShadowPlan plan_;
    VisibleSamples& samples_;
    OnceWarnings& warnings_;
    std::unique_ptr<ShadowMapArray> maps_; // one layer per slot
    std::vector<MapSlot> drawn_;           // the slots maps_ was last drawn for; empty when it holds none
    // Below the smallest side the driver could not allocate (allocate); every side until one fails.
    int allocatableSide_ = std::numeric_limits<int>::max();
};

} // namespace shadows
