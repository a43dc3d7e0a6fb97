#pragma once

#include <shadowbench/ShadowMetrics.h>

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace shadowbench {

/// @brief Errors of a soft shadow against a soft ground truth (see softShadowMetrics).
struct SoftShadowMetrics {
    /// Receivers in the penumbra mask: 0.02 < truth < 0.98, dilated by kPenumbraDilation pixels.
    std::size_t penumbraPixels = 0;
    double penumbraRmse = 0.0;
    double penumbraMae = 0.0;
    /// Receivers in the umbra (truth <= 0.02) outside the mask, and those of them rendered lit (> 0.5).
    std::size_t umbraPixels = 0;
    std::size_t falseLit = 0;
    /// Receivers wholly lit (truth >= 0.98) outside the mask, and those of them rendered shadowed (< 0.5).
    std::size_t litPixels = 0;
    std::size_t falseShadow = 0;
    /// Penumbra width: at each sample of the truth's 0.5 iso-line whose true penumbra is at least the
    /// minimum wide, the rendered width along the same line against the true one, |rendered - true| pixels.
    std::size_t widthSamples = 0;
    /// Samples whose rendered profile has no 0.1 to 0.9 crossing near the true edge (counted apart).
    std::size_t widthMissing = 0;
    double widthErrorMedian = 0.0;
    double widthErrorP95 = 0.0;
    /// Median of rendered over true width: above 1 the penumbrae are too wide, below too narrow.
    double widthRatioMedian = 0.0;
    /// Each measured sample's true and rendered width, pixels.
    std::vector<glm::vec2> widths;
    /// Each measured sample's pixel (x, y), in the order of `widths`.
    std::vector<glm::ivec2> widthPixels;
    /// Where a penumbra crosses from one map to another (a cascade seam; seamWidthJumps): pairs of samples
    /// within kSeamPairReach pixels reading different maps, and how much the rendered width changes between
    /// them beyond the truth's change, pixels (median, largest). No pairs: no seam crosses a measured
    /// penumbra.
    std::size_t seamPairs = 0;
    double seamJumpMedian = 0.0;
    double seamJumpMax = 0.0;
};

/// @brief How near, in pixels (each axis), two width samples on either side of a seam are paired.
inline constexpr int kSeamPairReach = 3;

/// @brief Pixels the penumbra mask is dilated by.
inline constexpr float kPenumbraDilation = 2.0f;

/// @brief The width in pixels between the `low` and `high` iso-lines of `visibility` through `from` along the
/// unit `direction` (towards the lit side): from the 0.5 crossing nearest `from` within `reach` pixels, down
/// to where it falls to `low` and up to where it rises to `high`, bilinearly over receivers (`classes` other
/// than Ignored; a profile leaving them ends there). Negative when a crossing is not found within `reach`.
float penumbraWidth(glm::ivec2 size, std::span<const PixelClass> classes, std::span<const float> visibility,
                    glm::vec2 from, glm::vec2 direction, float reach, float low = 0.1f, float high = 0.9f);

/// @brief Fills `metrics`' seam figures from `slots`, the map each pixel read (ShadowDebugView::Slot;
/// negative where none): every pair of its width samples within kSeamPairReach pixels whose slots differ, the
/// jump
/// |(rendered_a - rendered_b) - (true_a - true_b)|.
void seamWidthJumps(glm::ivec2 size, std::span<const float> slots, SoftShadowMetrics& metrics);

/// @brief The soft-shadow errors of `visibility` against the soft `truth` over the receivers of `classes`:
/// RMSE and MAE over the penumbra mask, false-lit umbra and false-shadow lit pixels outside it, and the
/// penumbra-width error at the truth's edge samples whose true width is at least `minimumWidth` pixels.
SoftShadowMetrics softShadowMetrics(glm::ivec2 size, std::span<const PixelClass> classes,
                                    std::span<const float> truth, std::span<const float> visibility,
                                    float minimumWidth = 4.0f);

} // namespace shadowbench
