#pragma once

#include <shadows/EnumNames.h>
#include <shadows/ShadowTechniqueTraits.h>
#include <shadows/TapPattern.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadows {

/// @brief Where the single-fragment depth gradient comes from (GSM reference, "Overview").
enum class GradientSource {
    StoredDerivatives,  ///< dz/dxy written by the depth pass into an RG32F target
    CentralDifferences, ///< central differences of the depth map, four extra lookups
    ScreenSpace,        ///< receiver plane from screen-space derivatives (2x2 Jacobian solve)
};

/// @brief Shadow map depth formats.
enum class DepthFormat { D16, D24, D32F };

/// @brief Which faces (as seen from the light) are rendered into the shadow map.
enum class CasterFaces { Front, Back };

/// @brief Form of the average-gradient computation for PcfGsmAverageGradient.
enum class AverageGradientForm {
    LeastSquares,  ///< any pattern, precomputed inverse covariance
    Circular8,     ///< the reference's unrolled closed form (forces the Circular8 layout)
    Circular8Vec4, ///< the reference's SIMD form (forces the Circular8 layout)
};

/// @brief Kernel of the receiver-plane-bias technique.
enum class ReceiverPlaneKernel {
    Bilinear2x2, ///< textureGather, one bias per texel of the bilinear footprint
    PerTap,      ///< the PCF pattern, one bias per tap
};

/// @brief What the lighting pass shows instead of the shaded colour.
enum class ShadowDebugView {
    None,
    TexelCheckerboard,
    GradientMagnitude,
    Bias,
    Visibility,
    ShadowMap,
    FullKernel
};

/// @brief Every setting of the shadow module. Plain data; ShadowModule::setSettings validates and applies it
/// (changing anything re-initialises the affected resources lazily on the next frame). The defaults are
/// here; units, ranges, labels and help are in the one schema (ShadowSettingsSchema.h).
struct ShadowSettings {
    /// Visibility function. Default PcfGsmAverageGradient.
    ShadowTechnique technique = ShadowTechnique::PcfGsmAverageGradient;
    /// Shadow map width and height in texels, 64..16384. Default 2048.
    int resolution = 2048;
    /// Depth format of the shadow map. Default D24.
    DepthFormat depthFormat = DepthFormat::D24;
    /// Faces rendered into the map. Default Front.
    CasterFaces casterFaces = CasterFaces::Front;
    /// Receiver moved towards the light before the comparison, world units, >= 0. Default 0.002.
    float constantBias = 0.002f;
    /// SlopeScaledBias: glPolygonOffset factor (scales the caster's depth slope), >= 0. Default 1.5.
    float slopeScale = 1.5f;
    /// SlopeScaledBias: glPolygonOffset units (multiples of the format's resolvable step), >= 0. Default 2.
    float slopeUnits = 2.0f;
    /// PCF layout for Pcf, PcfGsm* and ReceiverPlaneBias/PerTap. Default Grid.
    TapLayout pcfLayout = TapLayout::Grid;
    /// Grid: taps per side (2..8); Poisson: tap count (8..64); ignored for Circular8. Default 4.
    int pcfTaps = 4;
    /// Radius of the PCF pattern in texels, > 0. Default 1.5.
    float pcfRadius = 1.5f;
    /// Rotate the pattern per pixel (interleaved gradient noise) to trade banding for noise. Default false.
    bool pcfRotate = false;
    /// Gradient for Gsm, the point-gradient correction and the naive fuzzy width. Default CentralDifferences.
    GradientSource gradientSource = GradientSource::CentralDifferences;
    /// GSM fuzzy band width in texels of depth change, > 0. Default 1.
    float fuzzyScale = 1.0f;
    /// Average-gradient form. Default LeastSquares.
    AverageGradientForm averageGradientForm = AverageGradientForm::LeastSquares;
    /// ReceiverPlaneBias kernel. Default Bilinear2x2.
    ReceiverPlaneKernel receiverPlaneKernel = ReceiverPlaneKernel::Bilinear2x2;
    /// ReceiverPlaneBias: only let the bias move receivers towards the light (min(0, bias)). Default true.
    bool receiverPlaneClamp = true;
    /// NormalOffset: offset along the normal in texel sizes at the receiver, >= 0. Default 1.5.
    float normalOffsetTexels = 1.5f;
    /// Floor the receiver depth to the format's step before hardware comparisons (bias reference). Default
    /// false.
    bool floorReceiverDepth = false;
    /// Snap the directional light's frustum to whole texels so shadows do not shimmer. Default true.
    bool texelSnapping = true;
    /// Vsm, Msm: half-width of the separable box blur of the moments, texels, 0..16. Default 2.
    int momentBlurRadius = 2;
    /// Vsm: smallest variance the Chebyshev bound uses (depth units squared), >= 0. Default 1e-6.
    float vsmMinimumVariance = 1e-6f;
    /// Vsm: light-bleeding reduction, the bound's tail cut off (linstep), 0..0.95. Default 0.2.
    float lightBleedingReduction = 0.2f;
    /// Msm: moment bias towards (0, 0.63, 0, 0.63) (advanced shadow mapping reference), 0..0.5. Default 3e-5;
    /// the reference's blog uses 9e-3, which hides more numerical trouble at the cost of light leaking.
    float msmMomentBias = 3e-5f;
    /// Msm: store the moments in 16-bit unorm through the optimised basis (64 bits per texel) instead of 4 x
    /// 32-bit float. Default false.
    bool msmQuantize16 = false;
    /// Evsm: exponent c+ of the positive warp exp(c+ d). Default 40.
    float evsmPositiveExponent = 40.0f;
    /// Evsm: exponent c- of the negative warp -exp(-c- d). Default 5.
    float evsmNegativeExponent = 5.0f;
    /// JitteredPcf: taps, even, 8..64 (two per jitter texel). Default 32.
    int jitterTaps = 32;
    /// JitteredPcf: test taps taken before deciding whether the pixel needs the full kernel, even, 0 (always
    /// the full kernel) or 4..16. Default 8.
    int earlyOutTestTaps = 8;
    /// Debug output of the lighting pass. Default None.
    ShadowDebugView debugView = ShadowDebugView::None;

    /// @brief Empty when the settings are usable, otherwise one line per problem naming the field.
    [[nodiscard]] std::vector<std::string> validate() const;
    /// @brief The tap pattern these settings select (Circular8 forms force the Circular8 layout).
    [[nodiscard]] TapPattern tapPattern() const;

    bool operator==(const ShadowSettings&) const = default;
};

// The one name table of each settings enum (ShadowEnumNames.cpp; techniques from the technique table).
template <>
std::span<const EnumName<ShadowTechnique>> enumNames();
template <>
std::span<const EnumName<TapLayout>> enumNames();
template <>
std::span<const EnumName<GradientSource>> enumNames();
template <>
std::span<const EnumName<DepthFormat>> enumNames();
template <>
std::span<const EnumName<CasterFaces>> enumNames();
template <>
std::span<const EnumName<AverageGradientForm>> enumNames();
template <>
std::span<const EnumName<ReceiverPlaneKernel>> enumNames();
template <>
std::span<const EnumName<ShadowDebugView>> enumNames();

/// @brief Stable technique names for CLIs and files (from shadows::techniqueTable()).
std::string_view toString(ShadowTechnique technique);
std::optional<ShadowTechnique> techniqueFromString(std::string_view name);
/// @brief Every technique in declaration order.
const std::vector<ShadowTechnique>& allTechniques();

std::string_view toString(DepthFormat format);
std::optional<DepthFormat> depthFormatFromString(std::string_view name);
std::string_view toString(GradientSource source);
std::optional<GradientSource> gradientSourceFromString(std::string_view name);
std::string_view toString(ShadowDebugView view);
std::optional<ShadowDebugView> debugViewFromString(std::string_view name);

/// @brief Depth step of a format: 1/65535 (D16), 1/16777215 (D24), 0 for D32F (float, no fixed step).
float depthStep(DepthFormat format);

} // namespace shadows
