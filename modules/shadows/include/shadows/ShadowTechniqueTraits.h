#pragma once

#include <epoxy/gl.h>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace shadows {

/// @brief The visibility functions the module can run; each selectable at run time.
enum class ShadowTechnique {
    HardCompare,           ///< 1. one hardware comparison (sampler2DShadow, NEAREST), no bias: naive
    SlopeScaledBias,       ///< 2. as 1, with slope-scaled polygon offset on the casters
    HardwarePcf,           ///< 3. hardware 2x2 bilinear PCF (sampler2DShadow, LINEAR)
    Pcf,                   ///< 4. N-tap PCF (grid or Poisson), optional per-pixel rotation
    Gsm,                   ///< 5. single-tap gradient shadow map: linear depth, fuzzy comparison
    PcfGsmNaive,           ///< 6. PCF over GSM, taps compared at the fragment's depth (reproduces Fig. 4.2.3)
    PcfGsmPointGradient,   ///< 7. PCF over GSM, taps follow the fragment's gradient
    PcfGsmAverageGradient, ///< 8. PCF over GSM, taps follow the least-squares gradient of the taps
    PcfGsmQuadratic,       ///< 9. PCF over GSM, taps follow a least-squares quadric of the taps
    PcfGsmNearer,          ///< PCF over GSM, each tap at the nearer of the point and average predictions
    ReceiverPlaneBias,     ///< 10. receiver-plane depth bias from screen derivatives
    NormalOffset,          ///< 11. receiver pushed along its normal, one hardware comparison
    Vsm,                   ///< variance shadow map: (z, z²), Chebyshev bound
    Msm,          ///< moment shadow map: 4 moments, Hamburger bound (32-bit float or 16-bit quantised)
    Evsm,         ///< exponential variance shadow map: two warped depths and their squares, Chebyshev on each
    JitteredPcf,  ///< PCF over a stratified jitter texture, optional early-out on a few test taps
    AdaptiveBias, ///< one comparison at the receiver's tangent plane's depth at the texel centre
    PcfAdaptiveBias, ///< the same for every PCF tap
    PcfGsmConnected, ///< PCF over GSM, taps continuing the receiver's surface without a jump count as lit
    Pcss,            ///< percentage-closer soft shadows: blocker search, penumbra from the light's size, PCF
    PcssScreenPlane, ///< the same with each tap compared at a plane from screen derivatives: naive
    MsmSoft,         ///< moment soft shadows: PCSS's search and filter as two fetches of mip-filtered moments
};

/// @brief Number of ShadowTechnique values (keep in step with the last enumerator).
inline constexpr std::size_t kTechniqueCount = static_cast<std::size_t>(ShadowTechnique::MsmSoft) + 1;

/// @brief How the lighting pass samples a technique's shadow map.
enum class MapSampler {
    CompareNearest, ///< sampler2DShadow, one hardware comparison per lookup
    CompareLinear,  ///< sampler2DShadow with LINEAR filtering: hardware 2x2 PCF
    DepthLinear,    ///< sampler2D returning linearly filtered depth (GSM, gathers)
    Moments,        ///< bilinear sampler2D over the moments target (VSM, MSM)
    MomentMips, ///< trilinear sampler2D over the moments target's mip chain, at the width asked (msm-soft)
};

struct ShadowSettings;

/// @brief The filtered moments a technique's shadow pass stores per texel besides the depth buffer: blurred
/// where asked, and read through MapSampler::Moments (or MomentMips, over their mip chain).
struct MomentStore {
    /// Depth-pass define under which the technique's file defines gsShadowStore(depth).
    std::string_view define;
    /// Colour format of the moments target for these settings (e.g. GL_RGBA16 when MSM quantises).
    GLenum (*format)(const ShadowSettings&);
    /// What empty texels hold: the far plane (depth 1) as stored.
    glm::vec4 (*farPlane)(const ShadowSettings&);
};

/// @brief What a technique needs, whatever its options: one row per technique (techniqueTable()).
/// ShadowPlan resolves a row and the settings into what the passes do.
struct ShadowTechniqueTraits {
    /// The technique this row describes.
    ShadowTechnique technique;
    /// Stable name for CLIs and files.
    std::string_view name;
    /// What it does, for the techniques tables of docs/SHADOWS.md and the README (Markdown).
    std::string_view summary;
    /// Where it comes from, for the same tables; empty where nothing is cited.
    std::string_view reference = {};
    /// How the lighting pass samples the depth map (ShadowPlan may override it for an option).
    MapSampler sampler = MapSampler::CompareNearest;
    /// Lighting-pass defines (besides GS_SHADOWS) that select the technique's function
    /// gsShadowSample_<Technique> in shaders/shadows/techniques/: its family's, and the technique's own where
    /// a family shares code.
    std::array<std::string_view, 2> defines = {};
    /// The filtered moments the shadow pass stores; none (a null format) for depth-only maps.
    MomentStore moments = {};
    /// The technique's own parameters for its shader function (gsShadowTechniqueParameters), from the
    /// settings; null when it has none beyond the shared block.
    glm::vec4 (*shaderParameters)(const ShadowSettings&) = nullptr;
    /// Reads a per-fragment depth gradient (ShadowSettings::gradientSource applies).
    bool readsPointGradient = false;
    /// Uses the PCF tap pattern (pcfLayout, pcfTaps, pcfRadius, pcfRotate apply).
    bool usesTapPattern = false;
    /// Renders casters with slope-scaled polygon offset.
    bool offsetsCasters = false;
    /// How far, in texels, the technique's comparisons reach from the receiver's own position in the map (its
    /// kernel's footprint). Such a technique pushes the receiver along its normal to clear its own surface
    /// over that reach (ShadowSettings::footprintNormalOffset; normalOffsetTexels adds a margin;
    /// depthBiasSteps applies); null for the naive techniques, which have no offset.
    float (*footprintTexels)(const ShadowSettings&) = nullptr;
    /// Texel sizes the receiver is also moved towards the light where ShadowSettings::footprintNormalOffset
    /// is on: the margin for relief within a texel of the techniques that compare along the receiver's plane
    /// at one fetch (docs/SHADOWS.md, "Half a texel for relief").
    float reliefLiftTexels = 0.0f;
    /// Lowers its comparison depth by depthBiasSteps steps of the depth format.
    bool biasesDepth = false;
    /// Compares at receiver depths from a gradient with a fuzzy band (fuzzyScale applies).
    bool fuzzyComparison = false;
    /// Takes its taps from the stratified jitter texture.
    bool jittered = false;
    /// Bounds visibility by Chebyshev's inequality on filtered moments (vsmMinimumVariance and
    /// lightBleedingReduction apply).
    bool chebyshevBound = false;
    /// A deliberately naive reproduction (of acne, of darkening): exempt from the accuracy floors its
    /// defaults are held to elsewhere.
    bool naive = false;
    /// Texels beyond the receiver its kernel may read besides a tap pattern's (a soft shadow's widest
    /// penumbra) for these settings: maps keep that margin, and virtual pages that border; null for none.
    float (*softReachTexels)(const ShadowSettings&) = nullptr;
    /// Reads each map's own reach (gsShadowSoftReachTexels): a directional map fitted to the samples widens
    /// its margin to the light's widest penumbra over its depth range (SoftMargin), beyond softReachTexels.
    bool softReachFollowsLight = false;
};

/// @brief Map reads of the soft techniques' lookup at most: the blocker search's taps, then the filter's
/// (GS_PCSS_SEARCH_TAPS, GS_PCSS_FILTER_TAPS in shaders/shadows/techniques/pcss.glsl); the search alone where
/// it finds no blocker or only blockers.
inline constexpr int kPcssSearchTaps = 16;
inline constexpr int kPcssFilterTaps = 24;

/// @brief Map reads of msm-soft's lookup at most: the search region's moments, then the penumbra's; one where
/// the search finds no blocker or only blockers.
inline constexpr int kMomentSoftFetches = 2;

/// @brief How far a mip level's bilinear kernel reaches, in that level's texels: its nearest texels' centres
/// lie within one of the lookup, and each averages half a texel around its centre.
inline constexpr float kMomentKernelReach = 1.5f;

/// @brief msm-soft's reach, texels: its width costs no fetches, so on whole maps half as far again as
/// `pcss`'s (a margin of 96 texels, 5 % of a 2048² map's side); on virtual pages the same 16.
float momentSoftReachTexels(const ShadowSettings& settings);

/// @brief msm-soft's widest penumbra radius, texels: a mip level's kernel at radius 2^L reaches 1.5 2^L, so
/// the largest power of two whose kernel stays within its reach (64 on whole maps, 8 on virtual pages); the
/// moments' mip chain ends at its level.
float momentSoftRadiusLimit(const ShadowSettings& settings);

/// @brief The widest penumbra radius, in texels, the soft techniques search and filter over at least: a
/// virtual page's texel spans about a pixel, so 16 (its border holds them); a whole map's may be far finer,
/// so 64, and a directional map fitted to the samples as far as its light's penumbra reaches (SoftMargin).
float softReachTexels(const ShadowSettings& settings);

/// @brief Whether `technique` stores msm's four moments (msmMomentBias applies).
constexpr bool storesFourMoments(ShadowTechnique technique) {
    return technique == ShadowTechnique::Msm || technique == ShadowTechnique::MsmSoft;
}

/// @brief Whether the four moments are stored in the 16-bit optimised basis: msm's where moments16 asks,
/// msm-soft's always (its figures equal the 32-bit ones on the soft scenes, at half the memory of a mip chain
/// a third larger).
bool quantisesMoments(const ShadowSettings& settings);

/// @brief Every technique's row, in ShadowTechnique order.
std::span<const ShadowTechniqueTraits> techniqueTable();

/// @brief The row of `technique`.
const ShadowTechniqueTraits& traitsOf(ShadowTechnique technique);

/// @brief The techniques table of docs/SHADOWS.md and the README (Markdown), one row per technique.
std::string techniqueMarkdownTable();

} // namespace shadows
