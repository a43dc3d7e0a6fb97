#pragma once

#include "ScissorModule.h"

#include <shadows/ShadowModule.h>

#include <engine/Engine.h>

#include <memory>
#include <optional>

namespace sandbox {

/// @brief What one side of the frame cost and allocated.
struct SideStats {
    engine::FrameStats frame;
    shadows::ShadowStats shadows;
};

/// @brief Stats of one frame: side A, and side B when the frame was split.
struct FrameReport {
    SideStats a;
    std::optional<SideStats> b;
};

/// @brief Draws a split-screen frame: shadow settings A left of the divider, B right of it, in one target.
///
/// Two engine::Engine instances share the current GL context, each with its own ShadowModule (so each side
/// keeps its own shadow maps and compiled variants) followed by a ScissorModule that confines its lighting
/// pass to its side. Both render the full camera projection, so the halves line up pixel for pixel with a
/// single-technique frame of the same view.
class SplitRenderer {
public:
    SplitRenderer();
    ~SplitRenderer();
    SplitRenderer(const SplitRenderer&) = delete;
    SplitRenderer& operator=(const SplitRenderer&) = delete;

    /// @brief Renders `scene` from `camera` into `target`: all of it with `a` when `b` is nullopt, otherwise
    /// columns [0, splitX) with `a` and [splitX, width) with `b`, splitX = round(split * width). Returns the
    /// stats of side A and, when split, of side B. Throws std::invalid_argument for invalid settings.
    FrameReport render(const engine::Scene& scene, engine::EntityId camera, const engine::FrameTarget& target,
                       const shadows::ShadowSettings& a, const std::optional<shadows::ShadowSettings>& b,
                       float split);

    /// @brief The first column of side B: round(split * width), clamped to [0, width].
    [[nodiscard]] static int splitColumn(float split, int width);

    /// @brief Times both sides' passes with `method` (see engine::Engine::setPassTiming), or stops timing.
    void setPassTiming(std::optional<engine::TimingMethod> method);

private:
    struct Side;
    std::unique_ptr<Side> a_;
    std::unique_ptr<Side> b_;
};

} // namespace sandbox
