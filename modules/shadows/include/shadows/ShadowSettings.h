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
enum class CasterFaces {
    Both,  ///< every triangle: right for meshes of any winding (real models often mix windings)
    Front, ///< triangles facing the light (counter-clockwise seen from it)
    Back,  ///< triangles facing away: the far side of closed meshes, which moves acne off lit surfaces
};

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
/// here; what each field means, its unit, range and when it applies are in the one schema
/// (shadows::settingsSchema(), generated into the settings table of docs/SHADOWS.md).
struct ShadowSettings {
    ShadowTechnique technique = ShadowTechnique::PcfGsmAverageGradient;
    int resolution = 2048;
    DepthFormat depthFormat = DepthFormat::D24;
    CasterFaces casterFaces = CasterFaces::Both;
    float constantBiasTexels = 0.0f;
    float depthBiasSteps = 4.0f;
    float slopeScale = 1.5f;
    float slopeUnits = 2.0f;
    TapLayout pcfLayout = TapLayout::Grid;
    int pcfTaps = 4;
    float pcfRadius = 1.5f;
    bool pcfRotate = false;
    GradientSource gradientSource = GradientSource::CentralDifferences;
    float fuzzyScale = 1.0f;
    AverageGradientForm averageGradientForm = AverageGradientForm::LeastSquares;
    ReceiverPlaneKernel receiverPlaneKernel = ReceiverPlaneKernel::Bilinear2x2;
    bool receiverPlaneClamp = true;
    float normalOffsetTexels = 1.0f;
    bool floorReceiverDepth = false;
    bool texelSnapping = true;
    int momentBlurRadius = 2;
    float vsmMinimumVariance = 1e-6f;
    float lightBleedingReduction = 0.2f;
    // The reference's blog uses 9e-3, which hides more numerical trouble at the cost of light leaking.
    float msmMomentBias = 3e-5f;
    bool msmQuantize16 = false;
    float evsmPositiveExponent = 40.0f;
    float evsmNegativeExponent = 5.0f;
    int jitterTaps = 32;
    int earlyOutTestTaps = 8;
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
/// @brief The step depthBiasSteps counts: the format's step, but no finer than 2^-18, how far the float
/// arithmetic of the two depth paths (shadow pass, lighting pass) was measured to disagree.
float depthBiasStep(DepthFormat format);

} // namespace shadows
