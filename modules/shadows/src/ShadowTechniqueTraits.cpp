#include <shadows/ShadowTechniqueTraits.h>

namespace shadows {

std::span<const ShadowTechniqueTraits> techniqueTable() {
    using T = ShadowTechnique;
    using S = MapSampler;
    static const std::vector<ShadowTechniqueTraits> table = {
        {T::HardCompare, "hard", S::CompareNearest, {"GS_SHADOW_SINGLE_COMPARE"}, false, false, false},
        {T::SlopeScaledBias,
         "slope-scaled",
         S::CompareNearest,
         {"GS_SHADOW_SINGLE_COMPARE"},
         false,
         false,
         true},
        {T::HardwarePcf, "hw-pcf", S::CompareLinear, {"GS_SHADOW_SINGLE_COMPARE"}, false, false, false},
        {T::Pcf, "pcf", S::CompareNearest, {"GS_SHADOW_PCF"}, false, true, false},
        {T::Gsm, "gsm", S::DepthLinear, {"GS_SHADOW_GSM"}, true, false, false},
        {T::PcfGsmNaive, "pcf-gsm-naive", S::DepthLinear, {"GS_SHADOW_PCF_GSM"}, true, true, false},
        {T::PcfGsmPointGradient,
         "pcf-gsm-point",
         S::DepthLinear,
         {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_POINT"},
         true,
         true,
         false},
        {T::PcfGsmAverageGradient,
         "pcf-gsm-average",
         S::DepthLinear,
         {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_AVERAGE"},
         false,
         true,
         false},
        {T::PcfGsmQuadratic,
         "pcf-gsm-quadratic",
         S::DepthLinear,
         {"GS_SHADOW_PCF_GSM", "GS_SHADOW_CORRECTION_QUADRATIC"},
         false,
         true,
         false},
        {T::ReceiverPlaneBias,
         "receiver-plane",
         S::DepthLinear,
         {"GS_SHADOW_RECEIVER_PLANE"},
         false,
         false,
         false},
        {T::NormalOffset,
         "normal-offset",
         S::CompareNearest,
         {"GS_SHADOW_SINGLE_COMPARE", "GS_SHADOW_NORMAL_OFFSET"},
         false,
         false,
         false},
        {T::Vsm, "vsm", S::Moments, {"GS_SHADOW_VSM"}, false, false, false, 2},
        {T::Msm, "msm", S::Moments, {"GS_SHADOW_MSM"}, false, false, false, 4},
        {T::JitteredPcf, "pcf-jittered", S::CompareNearest, {"GS_SHADOW_JITTERED"}, false, false, false},
    };
    return table;
}

ShadowTechniqueTraits techniqueTraits(const ShadowSettings& settings) {
    ShadowTechniqueTraits traits = techniqueTable()[static_cast<std::size_t>(settings.technique)];
    if (settings.technique == ShadowTechnique::ReceiverPlaneBias &&
        settings.receiverPlaneKernel == ReceiverPlaneKernel::PerTap) {
        traits.sampler = MapSampler::CompareNearest;
        traits.usesTapPattern = true;
        traits.defines.push_back("GS_SHADOW_RPB_PER_TAP");
    }
    if (settings.technique == ShadowTechnique::Msm && settings.msmQuantize16) {
        traits.defines.push_back("GS_SHADOW_MSM_QUANTIZED");
    }
    if (settings.technique == ShadowTechnique::JitteredPcf && settings.earlyOutTestTaps > 0) {
        traits.defines.push_back("GS_SHADOW_EARLY_OUT");
    }
    if (settings.technique == ShadowTechnique::PcfGsmAverageGradient) {
        if (settings.averageGradientForm == AverageGradientForm::Circular8) {
            traits.defines.push_back("GS_SHADOW_AVG_CIRCULAR8");
        } else if (settings.averageGradientForm == AverageGradientForm::Circular8Vec4) {
            traits.defines.push_back("GS_SHADOW_AVG_VEC4");
        }
    }
    return traits;
}

std::vector<std::string_view> lightingDefines(const ShadowSettings& settings) {
    const ShadowTechniqueTraits traits = techniqueTraits(settings);
    std::vector<std::string_view> defines = {"GS_SHADOWS"};
    defines.insert(defines.end(), traits.defines.begin(), traits.defines.end());
    if (traits.sampler == MapSampler::CompareNearest || traits.sampler == MapSampler::CompareLinear) {
        defines.push_back("GS_SHADOW_SAMPLER_COMPARE");
    }
    if (traits.readsPointGradient) {
        constexpr std::string_view kGradientDefines[] = {
            "GS_SHADOW_GRADIENT_STORED", "GS_SHADOW_GRADIENT_CENTRAL", "GS_SHADOW_GRADIENT_SCREEN"};
        defines.push_back(kGradientDefines[static_cast<std::size_t>(settings.gradientSource)]);
    }
    if (traits.usesTapPattern && settings.pcfRotate) {
        defines.push_back("GS_SHADOW_ROTATE");
    }
    if (settings.floorReceiverDepth) {
        defines.push_back("GS_SHADOW_FLOOR");
    }
    constexpr std::string_view kDebugDefines[] = {"",
                                                  "GS_SHADOW_DEBUG_TEXELS",
                                                  "GS_SHADOW_DEBUG_GRADIENT",
                                                  "GS_SHADOW_DEBUG_BIAS",
                                                  "GS_SHADOW_DEBUG_VISIBILITY",
                                                  "GS_SHADOW_DEBUG_MAP",
                                                  "GS_SHADOW_DEBUG_KERNEL"};
    if (settings.debugView != ShadowDebugView::None) {
        defines.push_back(kDebugDefines[static_cast<std::size_t>(settings.debugView)]);
    }
    return defines;
}

} // namespace shadows
