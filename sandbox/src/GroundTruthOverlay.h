#pragma once

#include "Session.h"

#include <engine/Image.h>
#include <shadowbench/ShadowMetrics.h>

#include <glm/vec2.hpp>

#include <string>

namespace sandbox {

/// @brief Side A's technique against ray-traced ground truth (shadowbench, Embree) for the current view.
struct GroundTruthView {
    shadowbench::ShadowMetrics metrics;
    /// The shaded view with acne tinted red and leaks blue (band pixels, where edges are not scored, yellow).
    engine::Image overlay;
    /// The view the overlay belongs to: it is stale once the settings differ.
    SandboxSettings settings;
    glm::ivec2 size{0};

    /// @brief One line of the metrics, as the panel and --headless print them.
    [[nodiscard]] std::string summary() const;
};

/// @brief Measures side A of `session`'s current view (as its last render() left the scene) at `size`,
/// tinting `shaded` (the view's image, rows top to bottom, same size). Needs a current GL context; ray
/// casting takes a moment, so it runs on demand only.
GroundTruthView measureGroundTruth(const Session& session, const engine::Image& shaded);

} // namespace sandbox
