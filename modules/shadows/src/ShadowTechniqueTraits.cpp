#include <shadows/ShadowTechniqueTraits.h>

namespace shadows {

namespace {

using T = ShadowTechnique;
using S = MapSampler;

constexpr std::array<ShadowTechniqueTraits, kTechniqueCount> kTable{{
    {.technique = T::HardCompare,
     .name = "hard",
     .summary = "one hardware comparison (sampler2DShadow, NEAREST) + constant bias",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"}},
    {.technique = T::SlopeScaledBias,
     .name = "slope-scaled",
     .summary = "as hard, with glPolygonOffset(slopeScale, slopeUnits) on the casters",
     .defines = {"GS_SHADOW_SINGLE_COMPARE"},
     .offsetsCasters = true},
    {.technique = T::HardwarePcf,
     .name = "hw-pcf",
     .summary = "hardware 2x2 bilinear PCF (sampler2DShadow, LINEAR)",
     .sampler = S::CompareLinear,
     .defines = {"GS_SHADOW_SINGLE_COMPARE"}},
    {.technique = T::Pcf,
     .name = "pcf",
     .summary = "N-tap PCF: grid or Poisson pattern, optional per-pixel rotation",
     .defines = {"GS_SHADOW_PCF"},
     .usesTapPattern = true},
    {.technique = T::Gsm,
     .name = "gsm",
     .summary = "gradient shadow map: linear-filtered depth, fuzzy comparison saturate(diff / |g| + 1)",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_GSM"},
     .readsPointGradient = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmNaive,
     .name = "pcf-gsm-naive",
     .summary = "PCF over GSM, every tap at the fragment's depth (reproduces the darkening)",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_NONE"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmPointGradient,
     .name = "pcf-gsm-point",
     .summary = "PCF over GSM, taps follow the fragment's gradient",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_POINT"},
     .readsPointGradient = true,
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmAverageGradient,
     .name = "pcf-gsm-average",
     .summary = "PCF over GSM, taps follow the least-squares gradient of the taps' own depths",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_AVERAGE"},
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::PcfGsmQuadratic,
     .name = "pcf-gsm-quadratic",
     .summary = "PCF over GSM, taps follow a least-squares quadric of the taps' depths",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_QUADRATIC"},
     .usesTapPattern = true,
     .fuzzyComparison = true},
    {.technique = T::ReceiverPlaneBias,
     .name = "receiver-plane",
     .summary = "receiver-plane depth bias from screen derivatives, 2x2 gather or per PCF tap",
     .sampler = S::DepthLinear,
     .defines = {"GS_SHADOW_RECEIVER_PLANE"}},
    {.technique = T::NormalOffset,
     .name = "normal-offset",
     .summary = "receiver pushed along its normal by normalOffsetTexels texel sizes",
     .defines = {"GS_SHADOW_SINGLE_COMPARE", "GS_SHADOW_NORMAL_OFFSET"}},
    {.technique = T::Vsm,
     .name = "vsm",
     .summary = "variance shadow map: blurred, mipmapped (z, z^2), Chebyshev bound",
     .sampler = S::Moments,
     .defines = {"GS_SHADOW_VSM"},
     .stores = MapContent::TwoMoments},
    {.technique = T::Msm,
     .name = "msm",
     .summary = "moment shadow map: 4 moments, Hamburger bound (32-bit float or 16-bit quantised)",
     .sampler = S::Moments,
     .defines = {"GS_SHADOW_MSM"},
     .stores = MapContent::FourMoments},
    {.technique = T::JitteredPcf,
     .name = "pcf-jittered",
     .summary = "PCF over a stratified jitter texture, optional early-out on a few test taps",
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

} // namespace shadows
