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
    /// Only the light-facing faces of a mesh's closed parts, which store the same depth (engine::hiddenFace),
    /// and both faces of the others: real models often mix windings or leave holes, and are then drawn whole.
    /// Techniques that only compare also leave out flat casters that shadow nothing
    /// (ShadowPlan::leavesOutShadowlessPlanes).
    Auto,
    Both,  ///< every triangle: right for meshes of any winding
    Front, ///< triangles facing the light (counter-clockwise seen from it)
    Back,  ///< triangles facing away: the far side of closed meshes, which moves acne off lit surfaces
};

/// @brief What a directional light's maps are fitted to.
enum class DirectionalFit {
    /// The visible samples of a depth pass of the view (Sample Distribution Shadow Maps, Lauritzen et al.
    /// 2011): the depth range, the cascades' count and each map's rectangle follow what the screen shows.
    Samples,
    /// Mesh bounds: where visible boxes can be shadowed (one map), or the bounding spheres of the view
    /// frustum's slices (cascades).
    Bounds,
};

/// @brief How shadow texels are allocated.
enum class MapAllocation {
    /// Whole maps of `resolution`² fitted to the view (one, or one per cascade or cube face).
    Fitted,
    /// Virtual 16k² maps (a clipmap of levels per directional light, one map with mip levels per spot light
    /// and cube face) whose pages are drawn only where visible pixels ask for them, at the level whose texels
    /// are no larger than a pixel there, in virtualBudgetMiB, cached across frames (docs/SHADOWS.md,
    /// "Virtual maps").
    Virtual,
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
    /// The first shadowed light's visibility as the shading uses it (in a cascade blend band, both cascades'
    /// blended): what the accuracy measurements read.
    Visibility,
    ShadowMap,
    FullKernel,
    /// The map each pixel reads: cascade index (directional) or cube face (point) as colour.
    Maps,
    /// Lloyd's m, the largest extent of one shadow texel in screen pixels: green m <= 1, yellow <= 2, red
    /// > 2.
    Density,
    /// Virtual maps: the clipmap level each pixel reads as colour, page borders dark, pages drawn this frame
    /// bright; grey where no virtual page was read.
    Pages,
    /// The map slot each pixel's lookup read, as a value (-1 where none), in red, and for a virtual page, in
    /// green, the texels from the lookup to the page's nearest edge (-1 elsewhere), in blue the level it read
    /// (a spot map's or cube face's mip level; -1 elsewhere): for measurements that need to know which map or
    /// level a pixel used and whether its kernel straddles pages (float targets).
    Slot,
};

/// @brief Every setting of the shadow module. Plain data; ShadowModule::setSettings validates and applies it
/// (changing anything re-initialises the affected resources lazily on the next frame). The defaults are
/// here; what each field means, its unit, range and when it applies are in the one schema
/// (shadows::settingsSchema(), generated into the settings table of docs/SHADOWS.md).
struct ShadowSettings {
    /// Visibility function; the default is the one the rule of docs/RESULTS.md, "Defaults", recommends
    /// (tools/shadowbench/default_rule.py: the floor in the most views, then memory, then error x time).
    ShadowTechnique technique = ShadowTechnique::SlopeScaledBias;
    /// Width and height of each shadow map, texels.
    int resolution = 2048;
    /// Depth format of the shadow maps.
    DepthFormat depthFormat = DepthFormat::D24;
    /// Faces drawn into the shadow map.
    CasterFaces casterFaces = CasterFaces::Auto;
    /// Receiver moved towards the light before comparing, shadow texel sizes at the receiver.
    float constantBiasTexels = 0.0f;
    /// Comparison depth lowered by this many depth steps (depthBiasStep).
    float depthBiasSteps = 16.0f;
    /// glPolygonOffset factor on the casters (SlopeScaledBias).
    float slopeScale = 1.5f;
    /// glPolygonOffset units on the casters (SlopeScaledBias).
    float slopeUnits = 2.0f;
    /// Layout of the PCF taps.
    TapLayout pcfLayout = TapLayout::Grid;
    /// Taps per side of a grid, or the number of Poisson taps.
    int pcfTaps = 4;
    /// Radius of the tap pattern (and of jittered offsets), texels. The default keeps the kernel's penumbra
    /// inside the two texels a shadow's edge may blur over (docs/SHADOWS.md, "The filter inside the edge's
    /// band").
    float pcfRadius = 0.75f;
    /// Rotates the pattern per pixel: noise instead of banding.
    bool pcfRotate = false;
    /// Where the fragment's depth gradient comes from. The default is the receiver's own plane: differences
    /// of the map straddle a caster's silhouette, and the jump widens the fuzzy comparison into a leak
    /// (docs/SHADOWS.md, "The receiver's own gradient").
    GradientSource gradientSource = GradientSource::ScreenSpace;
    /// Width of the GSM fuzzy comparison band, texels.
    float fuzzyScale = 1.0f;
    /// Form of the average-gradient solve.
    AverageGradientForm averageGradientForm = AverageGradientForm::LeastSquares;
    /// Kernel of the receiver-plane bias.
    ReceiverPlaneKernel receiverPlaneKernel = ReceiverPlaneKernel::Bilinear2x2;
    /// Clamps the receiver-plane bias to min(0, bias).
    bool receiverPlaneClamp = true;
    /// Pushes the receiver along its normal by the technique's comparison footprint (docs/SHADOWS.md,
    /// "Automatic bias"); off, only normalOffsetTexels, as the references' techniques have it.
    bool footprintNormalOffset = true;
    /// Margin beyond the comparison's footprint of the normal offset, texel sizes.
    float normalOffsetTexels = 0.0f;
    /// Floors the receiver depth to the format's step before comparing.
    bool floorReceiverDepth = false;
    /// What directional maps are fitted to: the visible depth samples, or mesh bounds.
    DirectionalFit directionalFit = DirectionalFit::Samples;
    /// How directional lights' texels are allocated: whole fitted maps, or virtual pages.
    MapAllocation mapAllocation = MapAllocation::Fitted;
    /// Memory of the whole (fitted) maps, all lights together, MiB: the maps' side is halved until the most
    /// maps the frame's lights may take fit in it (budgetedResolution).
    int fittedBudgetMiB = 1024;
    /// Memory of the virtual maps' page pool, all lights together, MiB.
    int virtualBudgetMiB = 64;
    /// Side of a virtual page, texels.
    int virtualPageSize = 128;
    /// Largest extent on screen, pixels, of a texel of the level a virtual page is drawn at (Lloyd's m).
    float virtualTexelPixels = 1.0f;
    /// Largest size on screen, pixels, of a texel of a directional map fitted to the samples, at each
    /// cascade's nearest sample, divided by 1 + 2 × the technique's filter radius (ShadowPlan::
    /// filterRadiusTexels): the map takes the smallest power-of-two side, up to `resolution`, that meets it
    /// (viewResolution); 0: always `resolution`. Frames with spot or point lights or a second sun, and the
    /// soft techniques, keep `resolution`.
    float fittedTexelPixels = 0.25f;
    /// Keeps the last frame's maps while nothing they are drawn from changes (virtual maps: once an update
    /// drew no page); a moving view keeps whole maps while their placements hold its samples.
    bool reuseUnchangedMaps = true;
    /// Snaps directional frustums to whole texels (no shimmer).
    bool texelSnapping = true;
    /// Cascades of each directional light's map (1: one map over where visible receivers can be shadowed; 0:
    /// chosen from the visible depth range, automaticCascadeCount).
    int cascadeCount = 0;
    /// Weight of the logarithmic scheme in the cascades' practical split scheme (0: uniform splits).
    float cascadeSplitWeight = 0.9f;
    /// Fraction of each cascade's depth span, at its far end, blended into the next cascade.
    float cascadeBlend = 0.1f;
    /// Half-width of the moments' separable box blur, texels; 0 (the default) leaves the moments to the
    /// hardware's bilinear and trilinear filtering (docs/SHADOWS.md, "The filter inside the edge's band").
    int momentBlurRadius = 0;
    /// Smallest variance the Chebyshev bound uses.
    float vsmMinimumVariance = 1e-6f;
    /// Tail of the Chebyshev bound cut off (linstep). 0.4 is the least of 0.2, 0.3 and 0.4 with which `vsm`
    /// kept no light inside `terrain`'s shadows under a low sun (docs/SHADOWS.md, "Automatic bias").
    float lightBleedingReduction = 0.4f;
    /// Bias of the moments towards (0, 0.63, 0, 0.63) (Msm). The reference's blog uses 9e-3, which hides more
    /// numerical trouble at the cost of light leaking.
    float msmMomentBias = 3e-5f;
    /// Stores the moments in 16-bit unorm (Vsm: z and z² in RG16; Msm: RGBA16 through the optimised basis):
    /// on the Defaults views as accurate as 32-bit floats at half the memory, though a long depth range
    /// quantises coarser (docs/RESULTS.md, "Filtered families").
    bool moments16 = true;
    /// Every light's size (LightComponent::angularDiameter, radius) times this, for the soft techniques
    /// (Pcss, PcssScreenPlane, MsmSoft): 0 casts hard shadows. A sun's angular diameter stays below 90°.
    float lightSizeScale = 1.0f;
    /// c+ of the warp exp(c+ d) (Evsm).
    float evsmPositiveExponent = 40.0f;
    /// c- of the warp -exp(-c- d) (Evsm).
    float evsmNegativeExponent = 5.0f;
    /// Stratified taps per pixel (PcfJittered).
    int jitterTaps = 32;
    /// Taps taken before deciding on the full kernel; 0: always full (PcfJittered).
    int earlyOutTestTaps = 8;
    /// What the lighting pass shows instead of the shaded colour.
    ShadowDebugView debugView = ShadowDebugView::None;

    /// @brief Empty when the settings are usable, otherwise one line per problem naming the field.
    [[nodiscard]] std::vector<std::string> validate() const;
    /// @brief The tap pattern these settings select (Circular8 forms force the Circular8 layout).
    [[nodiscard]] TapPattern tapPattern() const;
    /// @brief Whether the average gradient runs in a circular-8 form: its own 8-tap layout and its own
    /// gradient, fitted from those taps.
    [[nodiscard]] bool usesCircular8Average() const;

    /// @brief Field-wise equality.
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
std::span<const EnumName<DirectionalFit>> enumNames();
template <>
std::span<const EnumName<MapAllocation>> enumNames();
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
/// @brief The step depthBiasSteps counts in the stored depth: the format's step; for D32F the spacing of
/// floats just below 1 (2^-24), where a perspective map's depths crowd.
float depthBiasStep(DepthFormat format);
/// @brief How far the float arithmetic of the two depth paths (shadow pass, lighting pass) was measured to
/// disagree, as a fraction of an orthographic map's depth range (2^-18): a distance along the light's axis,
/// so depthBiasSteps of it bound the bias from below in every map only after conversion by the map's
/// projection (receiver.glsl).
inline constexpr float kArithmeticDepthStep = 1.0f / 262144.0f;

} // namespace shadows
