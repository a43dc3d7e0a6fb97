#pragma once

#include <engine/Image.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace shadowbench {

/// @brief The index of pixel (`x`, `y`) in an image of `size`, rows from the bottom.
inline std::size_t pixelIndex(glm::ivec2 size, int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
}

/// @brief What each receiver pixel is in the ground truth.
enum class PixelClass : std::uint8_t {
    Ignored,  ///< background, or a surface facing away from the light by its smoothed normal or its facet
    Band,     ///< within the boundary band around a true shadow edge (not scored for acne/leak)
    Lit,      ///< truly lit, outside the band
    Shadowed, ///< truly shadowed by another surface, outside the band
};

/// @brief What a pixel shows, for scoring.
enum class Surface : std::uint8_t {
    None,       ///< background
    Receiver,   ///< faces the light by its smoothed normal and by its facet: scored
    FacingAway, ///< faces away from the light by either: dark whatever the shadows, an edge of the light
                ///< where it meets a lit receiver (a convex corner, a terminator)
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

/// @brief How finely the shadow maps sample what the screen shows: Lloyd et al.'s m (the largest extent of
/// one shadow texel in screen pixels, shadows::glsl::gsTexelFootprintPixels) over the truly lit receiver
/// pixels (see texelDensity).
struct TexelDensity {
    /// Lit receiver pixels with a footprint (held by a map, with a neighbour on the same surface).
    std::size_t pixels = 0;
    /// Fraction of them with m <= 1: a texel per pixel or finer.
    double atMostOnePixel = 0.0;
    double median = 0.0;
    double percentile99 = 0.0;
    double percentile999 = 0.0;
};

/// @brief Virtual maps: errors of scored pixels (lit or shadowed, outside the band) whose lookup lies within
/// a page's border of its edge, so that its kernel straddles two pages, against those of the others.
struct SeamErrors {
    std::size_t pixels = 0;
    /// Fraction of them whose visibility is off the truth's by more than 0.5.
    double errorRate = 0.0;
    std::size_t interiorPixels = 0;
    double interiorErrorRate = 0.0;
};

/// @brief The seam errors of `visibility` against `truth` over the scored pixels of `classes`, a pixel at a
/// seam where its `pageEdges` (texels to its page's edge, ShadowDebugView::Slot; negative: no page) is below
/// `reachTexels`.
SeamErrors seamErrors(std::span<const PixelClass> classes, std::span<const float> truth,
                      std::span<const float> visibility, std::span<const float> pageEdges, float reachTexels);

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
    /// Filled by the benchmark for our maps (it knows their projections); empty for the peer's.
    TexelDensity density;
    /// Virtual maps only (pixels 0 otherwise).
    SeamErrors seams;
};

/// @brief Where each pixel lies across the light's rays, so that the boundary band can be measured in shadow
/// texels, as the map sees the receivers: a surface almost edge-on to the light spreads one texel over many
/// pixels, and no map of that resolution can place an edge within it.
struct LightPlane {
    /// World position of each pixel (the G-buffer's).
    std::span<const glm::vec3> positions;
    /// World size of a shadow texel at each pixel (of the finest map holding it); 0 where no map holds it.
    std::span<const float> texelSizes;
    /// A sun: `direction` is where its light travels. Otherwise a spot or point light at `position`.
    bool directional = true;
    glm::vec3 direction{0.0f, -1.0f, 0.0f};
    glm::vec3 position{0.0f};
    /// Per pixel, where given: whether its shadow's edge lies within the band of it across the light's rays,
    /// anywhere, not only at the image's pixels (RayTracedVisibility::edgeWithin); a receiver so marked is in
    /// the band.
    std::span<const std::uint8_t> edgeWithinBand{};

    /// @brief How far pixel `j` lies from pixel `i` across the light's rays, in shadow texels at `i`: the
    /// distance between the two rays (a spot or point light's: at `i`'s distance from it); infinite when `i`
    /// has no texel size or `j` lies behind the light.
    [[nodiscard]] float texelsBetween(std::size_t i, std::size_t j) const;
};

/// @brief Per-pixel classes of the receivers (`surfaces`); a receiver is in the band when a pixel of the
/// other truth (a receiver's truth thresholded at 0.5; a surface facing away is dark) is one of its 8
/// neighbours, or lies within `bandTexels` shadow texels of it across the light's rays (`plane`) and within
/// `windowPixels` pixels of it on screen (the search's reach); a receiver is also in the band where
/// `plane.edgeWithinBand` marks it (the other side of its edge may be hidden from the camera).
std::vector<PixelClass> classify(glm::ivec2 size, std::span<const float> truth,
                                 std::span<const Surface> surfaces, const LightPlane& plane, float bandTexels,
                                 int windowPixels = 32);

/// @brief Per-pixel classes of the receivers (`surfaces`) with the band measured on screen, as a viewer sees
/// it: a receiver is in the band when a pixel of the other truth (as in classify) lies within `bandPixels`
/// pixels of it (between pixel centres; its 8 neighbours always), or where `edgeWithinBand` marks it (the
/// other side of its edge hidden from the camera; empty: nowhere).
std::vector<PixelClass> classifyByScreenBand(glm::ivec2 size, std::span<const float> truth,
                                             std::span<const Surface> surfaces, float bandPixels,
                                             std::span<const std::uint8_t> edgeWithinBand = {});

/// @brief Summary of per-pixel texel footprints (`footprints`, pixels; negative: none) over the truly lit
/// receivers (`classes` Lit or Band with `truth` >= 0.5). The median and 99th percentile are nearest-rank.
TexelDensity texelDensity(std::span<const PixelClass> classes, std::span<const float> truth,
                          std::span<const float> footprints);

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
