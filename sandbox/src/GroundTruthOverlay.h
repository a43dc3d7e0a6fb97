#pragma once

#include "Session.h"

#include <engine/Image.h>
#include <shadowbench/ShadowMetrics.h>

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace sandbox {

/// @brief Both sides' techniques against ray-traced ground truth (shadowbench, Embree) for the current view.
/// Each side's metrics cover the whole view drawn with its technique, so A and B compare like for like.
struct GroundTruthView {
    shadowbench::ShadowMetrics a;
    /// Side B's metrics when the view is split (SandboxSettings::compare).
    std::optional<shadowbench::ShadowMetrics> b;
    /// The shaded view with acne tinted red and leaks blue (band pixels, where edges are not scored, yellow),
    /// each side of the divider tinted with its own technique's errors.
    engine::Image overlay;
    /// The view the overlay belongs to: it is stale once the settings differ.
    SandboxSettings settings;
    glm::ivec2 size{0};

    /// @brief One line of one side's metrics, as the panel and --headless print them.
    [[nodiscard]] static std::string summary(const shadowbench::ShadowMetrics& metrics);
};

/// @brief Measures side A and, when split, side B of `session`'s current view (as its last render() left the
/// scene), tinting `shaded` (the view's image, rows top to bottom). Needs a current GL context; ray casting
/// takes a moment, so it runs on demand only.
GroundTruthView measureGroundTruth(const Session& session, const engine::Image& shaded);

} // namespace sandbox
