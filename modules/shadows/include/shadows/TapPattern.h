#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <array>
#include <string>
#include <vector>

namespace shadows {

/// @brief Layouts of PCF taps.
enum class TapLayout {
    Grid,      ///< n x n regular grid spanning [-radius, radius]² (n = 2..8).
    Poisson,   ///< Poisson-disk points inside the radius (8..64), fixed seed.
    Circular8, ///< The GSM multisampling reference's 8-tap pattern (4 axial at sqrt(2)·d, 4 diagonal at (±d,
               ///< ±d)).
};

/// @brief A PCF tap pattern plus what the least-squares fits over it need, precomputed on the CPU.
struct TapPattern {
    /// Most taps a pattern has; the shaders' arrays are this long.
    static constexpr int kMaxTaps = 64;

    /// The layout the offsets follow.
    TapLayout layout = TapLayout::Grid;
    /// Offsets in texels, in the pattern's own frame.
    std::vector<glm::vec2> offsets;
    /// (sum (o - mean)(o - mean)^T)^-1; zero when the offsets do not span the plane.
    glm::mat2 inverseCovariance{0.0f};
    /// Rows of the 6 x N least-squares pseudo-inverse for f(o) = a + g.o + ½ oᵀHo, coefficients ordered
    /// (a, gx, gy, Hxx, Hxy, Hyy); laid out row-major with a stride of kMaxTaps (see visibility.glsl).
    std::array<float, 6 * kMaxTaps> quadraticFitRows{};
    /// Tap indices nearest the centre first (ties by index), for connected PCF over GSM.
    std::vector<int> nearestFirst;
    /// Texels within which two taps count as neighbours for connected PCF over GSM: 1.5 times the largest
    /// distance from a tap to its nearest other tap (a grid's diagonal neighbours included).
    float linkDistance = 0.0f;
    /// False when the taps cannot determine a quadric (e.g. all on one circle); the fit rows then carry the
    /// linear fit only (curvature rows zero).
    bool quadraticValid = false;

    /// @brief Builds a pattern; `taps` is n for Grid (taps n² ) and the point count for Poisson; ignored for
    /// Circular8. `radius` is in texels (> 0). Throws std::invalid_argument naming the bad parameter.
    static TapPattern make(TapLayout layout, int taps, float radius);
};

/// @brief "grid", "poisson", "circular8".
std::string toString(TapLayout layout);

} // namespace shadows

namespace shadows {

/// @brief Offsets of jittered PCF, stored as the soft shadows reference does: a size x size x pairs texture
/// whose RGBA texels hold two offsets (rg, ba) in [0,1] (offset = 2·value − 1, times the radius).
struct JitterTexels {
    /// Width and height of the tile, pixels.
    int size = 32;
    /// Texels per pixel (depth of the texture): two taps each.
    int pairs = 0;
    /// size·size·pairs texels, x fastest, then y, then pair; 16-bit unorm components.
    std::vector<glm::u16vec4> texels;
};

/// @brief Stratified jitter for `taps` taps: the [-1,1]² box is split into a cols x rows grid of strata (the
/// most square factorisation of `taps`), every pixel of the size² tile gets one random point per stratum
/// (fixed seed), and strata are visited in a coprime-stride order so the first taps — the early-out test taps
/// — spread over the whole box instead of filling its first rows.
JitterTexels makeJitterTexels(int taps, int size = 32);

/// @brief The stratum (column, row, of cols x rows) tap `tap` lies in, in the order makeJitterTexels uses.
glm::ivec2 jitterStratum(int tap, int taps, glm::ivec2& grid);

} // namespace shadows
