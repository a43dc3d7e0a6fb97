#pragma once

#include <engine/Image.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace shadowbench {

/// @brief What each receiver pixel is in the ground truth.
enum class PixelClass : std::uint8_t {
    Ignored,  ///< background or a surface facing away from the light
    Band,     ///< within the boundary band around a true shadow edge (not scored for acne/leak)
    Lit,      ///< truly lit, outside the band
    Shadowed, ///< truly shadowed by another surface, outside the band
};

/// @brief Distances in pixels from each edge pixel of one image to the nearest edge pixel of another.
struct EdgeDistances {
    /// Edge pixels the distances start from.
    std::size_t count = 0;
    double mean = 0.0;
    double percentile95 = 0.0;
};

/// @brief Where a rendered shadow's edges lie against the truth's (see edgePlacement).
struct EdgePlacement {
    /// From each true edge pixel to the nearest rendered one: large when an edge is missing or displaced
    /// (peter-panning, a shrunken or swollen shadow).
    EdgeDistances trueToRendered;
    /// From each rendered edge pixel to the nearest true one: large for edges that should not be there
    /// (speckle lines of acne, leaks).
    EdgeDistances renderedToTrue;
};

/// @brief One technique's errors against ground truth over one image (see computeMetrics for definitions).
struct ShadowMetrics {
    std::size_t receivers = 0;
    std::size_t band = 0;
    std::size_t lit = 0;
    std::size_t shadowed = 0;
    std::size_t acne = 0;
    std::size_t leak = 0;
    std::size_t concave = 0;
    double acneRate = 0.0;
    double leakRate = 0.0;
    double darkening = 0.0;
    double concaveDarkening = 0.0;
    double meanAbsoluteError = 0.0;
    double rootMeanSquareError = 0.0;
    EdgePlacement edges;
};

/// @brief Per-pixel classes: receivers are `receiver[i] != 0`; a receiver is in the band when a receiver with
/// the other truth lies within `bandRadius` pixels (square window; the truth is thresholded at 0.5).
std::vector<PixelClass> classify(glm::ivec2 size, std::span<const float> truth,
                                 std::span<const std::uint8_t> receiver, int bandRadius);

/// @brief Errors of `visibility` against `truth` over `classes`:
/// acne rate = lit pixels with visibility < 0.5 / lit pixels; leak rate = shadowed pixels with visibility >
/// 0.5 / shadowed pixels; darkening = mean (1 - visibility) over lit pixels; concave darkening = the same
/// over lit pixels with `concave[i] != 0`; MAE and RMSE of visibility - truth over every receiver (band
/// included).
ShadowMetrics computeMetrics(std::span<const PixelClass> classes, std::span<const float> truth,
                             std::span<const float> visibility, std::span<const std::uint8_t> concave);

/// @brief Edge pixels of a visibility image: receivers (`classes[i] != Ignored`) below 0.5 with a 4-neighbour
/// receiver at or above 0.5 (the shadowed side only, so a shadow shifted by k pixels is k pixels away).
std::vector<std::uint8_t> edgePixels(glm::ivec2 size, std::span<const PixelClass> classes,
                                     std::span<const float> visibility);

/// @brief Distances from the true edges (`truth`) to the rendered ones (`visibility`) and back, in pixels
/// (Euclidean, between pixel centres). When one side has edges and the other none, each distance is the
/// image diagonal; with no edges on the starting side the count, mean and percentile are 0.
EdgePlacement edgePlacement(glm::ivec2 size, std::span<const PixelClass> classes,
                            std::span<const float> truth, std::span<const float> visibility);

/// @brief Pixels on concave surfaces, from a G-buffer: the normal turns towards the surface along some screen
/// axis (d n . d p < -threshold |d p|², outward normals). Needs both neighbours covered.
std::vector<std::uint8_t> concaveMask(glm::ivec2 size, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals,
                                      std::span<const std::uint8_t> covered, float threshold);

/// @brief Classification image: acne red, leak blue, correctly lit white, correctly shadowed dark grey, band
/// yellow-grey, ignored black.
engine::Image classificationImage(glm::ivec2 size, std::span<const PixelClass> classes,
                                  std::span<const float> visibility);

/// @brief |visibility - truth| over receivers as a black (0) → red → yellow → white (1) heat map.
engine::Image errorHeatMap(glm::ivec2 size, std::span<const PixelClass> classes, std::span<const float> truth,
                           std::span<const float> visibility);

} // namespace shadowbench
