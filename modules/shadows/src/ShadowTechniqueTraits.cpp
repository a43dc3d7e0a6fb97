#include <shadows/ShadowSettings.h>
#include <shadows/ShadowTechniqueTraits.h>
#include <shadows/VisibilityMath.h>

namespace shadows {

namespace {

using T = ShadowTechnique;
using S = MapSampler;

glm::vec2 evsmExponents(const ShadowSettings& settings) {
    return {settings.evsmPositiveExponent, settings.evsmNegativeExponent};
}

const std::array<ShadowTechniqueTraits, kTechniqueCount> kTable{{
    {.technique = T::HardCompare,
     .name = "hard",
     .summary = "one hardware comparison (sampler2DShadow, NEAREST) + constant bias (world units)",
     .reference = "Williams 1978",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"}},
    {.technique = T::SlopeScaledBias,
     .name = "slope-scaled",
     .summary = "as `hard` plus `glPolygonOffset(slopeScale, slopeUnits)` on the casters",
     .reference = "bias reference, \"Alternatives\"",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"},
     .offsetsCasters = true},
    {.technique = T::HardwarePcf,
     .name = "hw-pcf",
     .summary = "hardware 2×2 bilinear PCF (sampler2DShadow, LINEAR)",
     .sampler = S::CompareLinear,
     .defines = {"GS_SHADOW_SINGLE_COMPARE"}},
    {.technique = T::Pcf,
     .name = "pcf",
     .summary = "N-tap PCF: grid 2×2..8×8 or Poisson 8..64, optional per-pixel rotation",
     .reference = "Reeves et al. 1987",
     .defines = {"GS_SHADOW_PCF"},
     .usesTapPattern = true},
    {.technique = T::Gsm,
     .name = "gsm",
     .summary = "linear-filtered depth, fuzzy comparison `saturate(diff/|g| + 1)`; g stored by the depth "
                "pass, central differences, or screen-space receiver plane",
     .reference = "GSM reference, \"Overview\"",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_GSM"},
     .readsPointGradient = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmNaive,
     .name = "pcf-gsm-naive",
     .summary = "PCF over GSM, taps at the fragment's depth (reproduces the darkening)",
     .reference = "GSM reference, Fig. 4.2.3",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_NONE"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmPointGradient,
     .name = "pcf-gsm-point",
     .summary = "PCF over GSM, taps follow `dot(offset, g)` of the fragment's gradient",
     .reference = "Fig. 4.2.4b",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_POINT"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmAverageGradient,
     .name = "pcf-gsm-average",
     .summary = "PCF over GSM, taps follow the least-squares gradient of the taps' own depths: general "
                "(precomputed inverse covariance), circular-8 closed form, circular-8 vec4 form",
     .reference = "\"Optimizing Texture Look-ups\", \"SIMD\"",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_AVERAGE"},
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmQuadratic,
     .name = "pcf-gsm-quadratic",
     .summary = "PCF over GSM, taps follow a least-squares quadric of the taps' depths (precomputed 6×N "
                "pseudo-inverse)",
     .reference = "the reference's \"obvious improvement\"",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_QUADRATIC"},
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::ReceiverPlaneBias,
     .name = "receiver-plane",
     .summary = "dz/duv from screen derivatives (zero where the Jacobian is singular), per-texel bias with "
                "optional `min(0, bias)`, 2×2 bilinear via `textureGather`, or per tap",
     .reference = "bias reference, \"Receiver Plane Depth Bias\"",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_RECEIVER_PLANE"}},
    {.technique = T::NormalOffset,
     .name = "normal-offset",
     .summary = "receiver pushed along its normal by `normalOffsetTexels` texel sizes",
     .reference = "bias reference, \"Alternatives\"",
     .defines = {"GS_SHADOW_SINGLE_COMPARE", "GS_SHADOW_NORMAL_OFFSET"}},
    {.technique = T::Vsm,
     .name = "vsm",
     .summary = "moments (z, z²) in RG32F, separable box blur (`momentBlurRadius`), mipmaps, trilinear "
                "lookup, Chebyshev bound with `vsmMinimumVariance`, `lightBleedingReduction` and the early "
                "return where the mean is beyond the receiver",
     .reference = "advanced shadow mapping reference, \"Variance Shadow Maps\"",
     .sampler = S::Moments,
     .defines = {"GS_SHADOW_VSM"},
     .moments = {"GS_SHADOW_STORE_MOMENTS2", [](const ShadowSettings&) -> GLenum { return GL_RG32F; },
                 [](const ShadowSettings&) { return glm::vec4(1.0f); }},
     .chebyshevBound = true},
    {.technique = T::Msm,
     .name = "msm",
     .summary = "4 moments, Hamburger bound via Cholesky with `msmMomentBias` towards (0, 0.63, 0, 0.63); "
                "RGBA32F, or RGBA16 through the optimised moment basis (`msmQuantize16`, 64 bits per texel)",
     .reference = "same, \"Moment Shadow Maps\"; Peters & Klein 2015",
     .sampler = S::Moments,
     .defines = {"GS_SHADOW_MSM"},
     .moments = {"GS_SHADOW_STORE_MOMENTS4",
                 [](const ShadowSettings& s) -> GLenum { return s.msmQuantize16 ? GL_RGBA16 : GL_RGBA32F; },
                 [](const ShadowSettings& s) {
                     return s.msmQuantize16 ? glsl::gsMsmQuantize(glm::vec4(1.0f)) : glm::vec4(1.0f);
                 }}},
    {.technique = T::Evsm,
     .name = "evsm",
     .summary = "exponential variance shadow map: depth warped to exp(c+ d) and -exp(-c- d) "
                "(`evsmPositiveExponent`, `evsmNegativeExponent`), both warps and their squares in RGBA32F, "
                "filtered like `vsm`'s moments; Chebyshev's bound on each warp, the smaller one wins",
     .reference = "Lauritzen & McCool, \"Layered variance shadow maps\", GI 2008, exponential warping",
     .sampler = S::Moments,
     .defines = {"GS_SHADOW_EVSM"},
     .moments = {"GS_SHADOW_STORE_EVSM", [](const ShadowSettings&) -> GLenum { return GL_RGBA32F; },
                 [](const ShadowSettings& s) { return glsl::gsEvsmMoments(1.0f, evsmExponents(s)); }},
     .shaderParameters = [](const ShadowSettings& s) { return glm::vec4(evsmExponents(s), 0.0f, 0.0f); },
     .chebyshevBound = true},
    {.technique = T::JitteredPcf,
     .name = "pcf-jittered",
     .summary = "`jitterTaps` (8..64) offsets from a stratified 32×32×(taps/2) jitter texture, two offsets "
                "per RGBA16 texel; `earlyOutTestTaps` test taps first, the full kernel only where they "
                "disagree, averaging every tap taken",
     .reference = "soft shadows reference (whose pseudo-code normalises by the full count even when it stops "
                  "early — we do not)",
     .defines = {"GS_SHADOW_JITTERED"},
     .jittered = true},
}};

} // namespace

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
