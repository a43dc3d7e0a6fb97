#include <shadows/ShadowSettings.h>
#include <shadows/ShadowTechniqueTraits.h>
#include <shadows/VisibilityMath.h>

#include <cmath>

namespace shadows {

namespace {

using T = ShadowTechnique;
using Sampler = MapSampler;

// Footprints of the hardware comparisons (ShadowTechniqueTraits::footprintTexels). A NEAREST comparison reads
// the texel its lookup falls in, whose centre (where the caster's depth was rasterised) is up to half a texel
// diagonal away; a LINEAR one blends the four texel centres around it, up to a diagonal away. PCF's taps each
// follow the receiver's plane (pcf.glsl), so the offset need not reach the kernel's farthest tap: a diagonal
// (more than one NEAREST comparison's reach) met the floor in the most views (docs/SHADOWS.md, "Automatic
// bias"). The adaptive bias's tangent plane, and the fuzzy comparison of GSM and PCF over GSM (one gradient
// width at the linearly filtered depth), hold only for a receiver that is planar over the texel: the same
// half-diagonal offset lifts it over curved and creased ones (terrain's sub-texel relief), and so it does for
// the caster offset, the receiver-plane bias and the moment maps' bounds.
// ShadowSettings::footprintNormalOffset turns these offsets off, for the references' own forms.
constexpr float kNearestReach = 0.70710678f;
constexpr float kBilinearReach = 1.41421356f;
// Relief within a texel (a crease, where the neighbouring facet rises in front of the receiver's plane) is
// what the half-diagonal offset cannot clear for the techniques that compare at one NEAREST or filtered fetch
// along the receiver's plane: the normal offset's, the tangent plane's, GSM's gradient band (zero wide where
// the receiver faces the light). Half a texel towards the light met the floor in every Defaults view for each
// of them, as did a quarter, with less acne and darkening (docs/SHADOWS.md, "Half a texel for relief").
// `slope-scaled` has its slope factor's margin, the filtered techniques a wider footprint, the moments
// variance.
constexpr float kReliefLift = 0.5f;

float nearestReach(const ShadowSettings&) {
    return kNearestReach;
}
float bilinearReach(const ShadowSettings&) {
    return kBilinearReach;
}

/// msm-soft's widest radius, texels, for the shader (gsShadowTechniqueParameters.x).
glm::vec4 momentSoftParameters(const ShadowSettings& settings) {
    return glm::vec4(momentSoftRadiusLimit(settings), 0.0f, 0.0f, 0.0f);
}

glm::vec2 evsmExponents(const ShadowSettings& settings) {
    return {settings.evsmPositiveExponent, settings.evsmNegativeExponent};
}

// msm's four moments: 16-bit through the optimised basis, or 32-bit float.
constexpr MomentStore kMsmMoments{
    "GS_SHADOW_STORE_MOMENTS4",
    [](const ShadowSettings& s) -> GLenum { return quantisesMoments(s) ? GL_RGBA16 : GL_RGBA32F; },
    [](const ShadowSettings& s) {
        return quantisesMoments(s) ? glsl::gsMsmQuantize(glm::vec4(1.0f)) : glm::vec4(1.0f);
    }};

const std::array<ShadowTechniqueTraits, kTechniqueCount> kTable{{
    {.technique = T::HardCompare,
     .name = "hard",
     .summary = "one hardware comparison (NEAREST), no bias unless `constantBiasTexels` is "
                "set: the naive reproduction of acne",
     .reference = "Williams 1978",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"},
     .naive = true},
    {.technique = T::SlopeScaledBias,
     .name = "slope-scaled",
     .summary = "as `hard` plus `glPolygonOffset(slopeScale, slopeUnits)` on the casters (and the receiver "
                "pushed half a texel diagonal along its normal, as every non-naive technique)",
     .reference = "bias reference, \"Alternatives\"",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"},
     .offsetsCasters = true,
     .footprintTexels = nearestReach},
    {.technique = T::HardwarePcf,
     .name = "hw-pcf",
     .summary = "hardware 2×2 bilinear PCF (LINEAR)",
     .sampler = Sampler::CompareLinear,
     .defines = {"GS_SHADOW_SINGLE_COMPARE"},
     .footprintTexels = bilinearReach,
     .biasesDepth = true},
    {.technique = T::Pcf,
     .name = "pcf",
     .summary = "N-tap PCF: grid 2×2..8×8 or Poisson 8..64, optional per-pixel rotation; each tap compared "
                "at the receiver's tangent plane, never deeper than the fragment",
     .reference = "Reeves et al. 1987",
     .defines = {"GS_SHADOW_PCF", "GS_SHADOW_TANGENT_PLANE"},
     .usesTapPattern = true,
     .footprintTexels = bilinearReach,
     .biasesDepth = true},
    {.technique = T::Gsm,
     .name = "gsm",
     .summary = "linear-filtered depth, fuzzy comparison `saturate(diff/|g| + 1)`; g stored by the depth "
                "pass, central differences, or screen-space receiver plane",
     .reference = "GSM reference, \"Overview\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_GSM"},
     .readsPointGradient = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmNaive,
     .name = "pcf-gsm-naive",
     .summary = "PCF over GSM, taps at the fragment's depth (reproduces the darkening)",
     .reference = "GSM reference, Fig. 4.2.3",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_NONE"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .fuzzyComparison = true,
     .naive = true},
    {.technique = T::PcfGsmPointGradient,
     .name = "pcf-gsm-point",
     .summary = "PCF over GSM, taps follow `dot(offset, g)` of the fragment's gradient",
     .reference = "Fig. 4.2.4b",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_POINT"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmAverageGradient,
     .name = "pcf-gsm-average",
     .summary = "PCF over GSM, taps follow the least-squares gradient of the taps' own depths: general "
                "(precomputed inverse covariance), circular-8 closed form, circular-8 vec4 form",
     .reference = "\"Optimizing Texture Look-ups\", \"SIMD\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_AVERAGE"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmQuadratic,
     .name = "pcf-gsm-quadratic",
     .summary = "PCF over GSM, taps follow a least-squares quadric of the taps' depths (precomputed 6×N "
                "pseudo-inverse)",
     .reference = "the reference's \"obvious improvement\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_QUADRATIC"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmNearer,
     .name = "pcf-gsm-nearer",
     .summary =
         "PCF over GSM, each tap compared at the nearer (to the light) of the point- and average-gradient "
         "predictions, so a concave crease darkens no more than under either",
     .reference = "ours: docs/SHADOWS.md, \"Why the average gradient darkens concave regions more\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_NEARER"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true,
     .fuzzyComparison = true},
    {.technique = T::ReceiverPlaneBias,
     .name = "receiver-plane",
     .summary = "dz/duv from screen derivatives (zero where the Jacobian is singular), per-texel bias with "
                "optional `min(0, bias)`, 2×2 bilinear via `textureGather`, or per tap",
     .reference = "bias reference, \"Receiver Plane Depth Bias\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_RECEIVER_PLANE"},
     .footprintTexels = nearestReach,
     .biasesDepth = true},
    {.technique = T::NormalOffset,
     .name = "normal-offset",
     .summary = "one hardware comparison, the receiver pushed along its normal by (half a texel diagonal + "
                "`normalOffsetTexels`) texel sizes × sin(normal, light) and half a texel towards the light",
     .reference = "bias reference, \"Alternatives\"",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"},
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true},
    {.technique = T::Vsm,
     .name = "vsm",
     .summary =
         "moments (z, z²) in RG16 (`moments16`) or RG32F, separable box blur (`momentBlurRadius`), "
         "bilinear lookup, Chebyshev bound with `vsmMinimumVariance`, `lightBleedingReduction` and the "
         "early return where the mean is beyond the receiver",
     .reference = "advanced shadow mapping reference, \"Variance Shadow Maps\"",
     .sampler = Sampler::Moments,
     .defines = {"GS_SHADOW_VSM"},
     .moments = {"GS_SHADOW_STORE_MOMENTS2",
                 [](const ShadowSettings& s) -> GLenum { return s.moments16 ? GL_RG16 : GL_RG32F; },
                 [](const ShadowSettings&) { return glm::vec4(1.0f); }},
     .footprintTexels = nearestReach,
     .chebyshevBound = true},
    {.technique = T::Msm,
     .name = "msm",
     .summary = "4 moments, Hamburger bound via Cholesky with `msmMomentBias` towards (0, 0.63, 0, 0.63); "
                "RGBA16 through the optimised moment basis (`moments16`, 64 bits per texel), or RGBA32F",
     .reference = "same, \"Moment Shadow Maps\"; Peters & Klein 2015",
     .sampler = Sampler::Moments,
     .defines = {"GS_SHADOW_MSM"},
     .moments = kMsmMoments,
     .footprintTexels = nearestReach},
    {.technique = T::Evsm,
     .name = "evsm",
     .summary = "exponential variance shadow map: depth warped to exp(c+ d) and -exp(-c- d) "
                "(`evsmPositiveExponent`, `evsmNegativeExponent`), both warps and their squares in RGBA32F, "
                "filtered like `vsm`'s moments; Chebyshev's bound on each warp, the smaller one wins",
     .reference = "Lauritzen & McCool, \"Layered variance shadow maps\", GI 2008, exponential warping",
     .sampler = Sampler::Moments,
     .defines = {"GS_SHADOW_EVSM"},
     .moments = {"GS_SHADOW_STORE_EVSM", [](const ShadowSettings&) -> GLenum { return GL_RGBA32F; },
                 [](const ShadowSettings& s) { return glsl::gsEvsmMoments(1.0f, evsmExponents(s)); }},
     .shaderParameters = [](const ShadowSettings& s) { return glm::vec4(evsmExponents(s), 0.0f, 0.0f); },
     .footprintTexels = nearestReach,
     .chebyshevBound = true},
    {.technique = T::JitteredPcf,
     .name = "pcf-jittered",
     .summary =
         "`jitterTaps` (8..64) offsets from a stratified 32×32×(taps/2) jitter texture, two offsets "
         "per RGBA16 texel; `earlyOutTestTaps` test taps first, the full kernel only where they "
         "disagree, averaging every tap taken; each tap compared at the receiver's tangent plane, never "
         "deeper than the fragment",
     .reference = "soft shadows reference (whose pseudo-code normalises by the full count even when it stops "
                  "early — we do not)",
     .defines = {"GS_SHADOW_JITTERED", "GS_SHADOW_TANGENT_PLANE"},
     .footprintTexels = bilinearReach,
     .biasesDepth = true,
     .jittered = true},
    {.technique = T::AdaptiveBias,
     .name = "adaptive-bias",
     .summary =
         "one hardware comparison at the depth of the receiver's tangent plane (from its normal) on the "
         "light's ray through the texel's centre (never deeper than the fragment), minus `depthBiasSteps` "
         "format steps; the receiver pushed along its normal by half a texel diagonal × sin(normal, light) "
         "and half a texel towards the light, for receivers that are not planar over the texel",
     .reference = "Dou, Yan, Kerzner, Dai, Wyman, \"Adaptive Depth Bias for Shadow Maps\", JCGT 3(4) 2014",
     .defines = {"GS_SHADOW_ADAPTIVE", "GS_SHADOW_TANGENT_PLANE"},
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true},
    {.technique = T::PcfAdaptiveBias,
     .name = "pcf-adaptive-bias",
     .summary = "`adaptive-bias` for every tap of the PCF pattern, each at its own texel's centre (the same "
                "offsets)",
     .reference = "Ehm et al., WSCG 2015",
     .defines = {"GS_SHADOW_ADAPTIVE_PCF", "GS_SHADOW_TANGENT_PLANE"},
     .usesTapPattern = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true},
    {.technique = T::PcfGsmConnected,
     .name = "pcf-gsm-connected",
     .summary = "PCF over GSM, taps at the point gradient's prediction (never deeper than the fragment); a "
                "failing tap that continues a lit nearer one without a jump is the receiver's own surface "
                "(a concave crease) and counts as lit, since shadows' edges are jumps in the map",
     .reference = "ours: docs/SHADOWS.md, \"Connected taps\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_CONNECTED"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .footprintTexels = nearestReach,
     .reliefLiftTexels = kReliefLift,
     .biasesDepth = true,
     .fuzzyComparison = true},
    {.technique = T::Pcss,
     .name = "pcss",
     .summary =
         "percentage-closer soft shadows: 16 blocker-search taps then 24 filter taps (each a bilinear 2×2 "
         "of comparisons) on Vogel disks turned per pixel by interleaved gradient noise, every tap "
         "compared at the receiver's tangent plane; the search and the penumbra from the light's own size "
         "(a sun's angular diameter, a local light's radius) in world units, converted per map, cascade "
         "and page, up to 64 texels (16 on virtual pages), on a directional map fitted to the view as far as "
         "the light's penumbra reaches over its depth range (up to an eighth of its side); no blocker found: "
         "lit, every tap a blocker: "
         "shadowed; a light of size 0: one comparison",
     .reference = "Fernando, SIGGRAPH 2005 sketch",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCSS", "GS_SHADOW_TANGENT_PLANE"},
     .footprintTexels = bilinearReach,
     .biasesDepth = true,
     .softReachTexels = softReachTexels,
     .softReachFollowsLight = true},
    {.technique = T::PcssScreenPlane,
     .name = "pcss-screen-plane",
     .summary =
         "`pcss` as engines ship it (16 + 24 taps, HDRP's defaults): each tap compared at the receiver's "
         "plane from screen derivatives (receiver-plane depth bias), not its tangent plane; the naive "
         "reproduction `pcss` is measured against",
     .reference = "Fernando 2005; receiver plane: bias reference, \"Receiver Plane Depth Bias\"",
     .sampler = Sampler::DepthLinear,
     .defines = {"GS_SHADOW_PCSS_SCREEN_PLANE", "GS_SHADOW_GRADIENT_SCREEN"},
     .footprintTexels = bilinearReach,
     .biasesDepth = true,
     .naive = true,
     .softReachTexels = softReachTexels,
     .softReachFollowsLight = true},
    {.technique = T::MsmSoft,
     .name = "msm-soft",
     .summary =
         "moment soft shadows: `pcss`'s blocker search, penumbra and filter, each one trilinear fetch of "
         "`msm`'s moments from their mip chain at the width asked (constant cost); the blockers' mean depth "
         "from the Hamburger bound's distribution, each compared behind the spread of the receiver's tangent "
         "plane over the kernel; the moments always in msm's 16-bit basis (as accurate here, half the "
         "memory); `msmMomentBias` applies",
     .reference = "Peters, Münstermann, Wetzstein, Klein, I3D 2016 (summed-area tables there, mips here)",
     .sampler = Sampler::MomentMips,
     .defines = {"GS_SHADOW_MSM_SOFT", "GS_SHADOW_TANGENT_PLANE"},
     .moments = kMsmMoments,
     .shaderParameters = momentSoftParameters,
     .footprintTexels = nearestReach,
     .softReachTexels = momentSoftReachTexels},
}};

} // namespace

float softReachTexels(const ShadowSettings& settings) {
    return settings.mapAllocation == MapAllocation::Virtual ? 16.0f : 64.0f;
}

bool quantisesMoments(const ShadowSettings& settings) {
    return settings.technique == ShadowTechnique::MsmSoft ||
           (settings.technique == ShadowTechnique::Msm && settings.moments16);
}

float momentSoftReachTexels(const ShadowSettings& settings) {
    return settings.mapAllocation == MapAllocation::Virtual ? 16.0f : 96.0f;
}

float momentSoftRadiusLimit(const ShadowSettings& settings) {
    return std::exp2(std::floor(std::log2(momentSoftReachTexels(settings) / kMomentKernelReach)));
}

std::span<const ShadowTechniqueTraits> techniqueTable() {
    return kTable;
}

const ShadowTechniqueTraits& traitsOf(ShadowTechnique technique) {
    return kTable[static_cast<std::size_t>(technique)];
}

std::string techniqueMarkdownTable() {
    std::string table = "| name | what | from |\n| --- | --- | --- |\n";
    for (const ShadowTechniqueTraits& traits : kTable) {
        table += "| `" + std::string(traits.name) + "` | " + std::string(traits.summary) + " | " +
                 std::string(traits.reference) + " |\n";
    }
    return table;
}

} // namespace shadows
