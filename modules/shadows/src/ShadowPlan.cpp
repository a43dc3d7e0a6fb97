#include <shadows/ShadowPlan.h>

#include <algorithm>
#include <cmath>

namespace shadows {

GLenum glDepthFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16:
        return GL_DEPTH_COMPONENT16;
    case DepthFormat::D24:
        return GL_DEPTH_COMPONENT24;
    case DepthFormat::D32F:
        return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT24;
}

namespace {

/// The technique's options that select shader code (after the plan's normal offset, whose bit follows it).
void addOptionDefines(const ShadowSettings& settings, ShadowPlan& plan) {
    std::vector<std::string_view>& defines = plan.lightingDefines;
    if (settings.technique == ShadowTechnique::ReceiverPlaneBias &&
        settings.receiverPlaneKernel == ReceiverPlaneKernel::PerTap) {
        defines.push_back("GS_SHADOW_RPB_PER_TAP");
    }
    if (quantisesMoments(settings)) {
        defines.push_back("GS_SHADOW_MSM_QUANTIZED");
        plan.depthDefines.push_back("GS_SHADOW_MSM_QUANTIZED");
    }
    if (plan.traits->jittered && settings.earlyOutTestTaps > 0) {
        defines.push_back("GS_SHADOW_EARLY_OUT");
    }
    if (settings.technique == ShadowTechnique::PcfGsmAverageGradient) {
        if (settings.averageGradientForm == AverageGradientForm::Circular8) {
            defines.push_back("GS_SHADOW_AVG_CIRCULAR8");
        } else if (settings.averageGradientForm == AverageGradientForm::Circular8Vec4) {
            defines.push_back("GS_SHADOW_AVG_VEC4");
        }
    }
    if (plan.sampler == MapSampler::CompareNearest || plan.sampler == MapSampler::CompareLinear) {
        defines.push_back("GS_SHADOW_SAMPLER_COMPARE");
    }
    if (plan.readsPointGradient) {
        constexpr std::string_view kGradientDefines[] = {
            "GS_SHADOW_GRADIENT_STORED", "GS_SHADOW_GRADIENT_CENTRAL", "GS_SHADOW_GRADIENT_SCREEN"};
        defines.push_back(kGradientDefines[static_cast<std::size_t>(settings.gradientSource)]);
    }
    if (plan.usesTapPattern && settings.pcfRotate) {
        defines.push_back("GS_SHADOW_ROTATE");
    }
    if (plan.normalOffsetTexels > 0.0f) {
        defines.push_back("GS_SHADOW_NORMAL_OFFSET");
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
                                                  "GS_SHADOW_DEBUG_KERNEL",
                                                  "GS_SHADOW_DEBUG_MAPS",
                                                  "GS_SHADOW_DEBUG_DENSITY",
                                                  "GS_SHADOW_DEBUG_PAGES",
                                                  "GS_SHADOW_DEBUG_SLOT"};
    if (settings.debugView != ShadowDebugView::None) {
        defines.push_back(kDebugDefines[static_cast<std::size_t>(settings.debugView)]);
    }
}

std::size_t bytesPerTexel(GLenum format) {
    switch (format) {
    case GL_RG16:
        return 4;
    case GL_RG32F:
    case GL_RGBA16:
        return 8;
    case GL_RGBA32F:
        return 16;
    default:
        return 0;
    }
}

} // namespace

ShadowPlan ShadowPlan::resolve(const ShadowSettings& settings) {
    ShadowPlan plan;
    plan.traits = &traitsOf(settings.technique);
    plan.sampler = plan.traits->sampler;
    plan.usesTapPattern = plan.traits->usesTapPattern;
    if (settings.technique == ShadowTechnique::ReceiverPlaneBias &&
        settings.receiverPlaneKernel == ReceiverPlaneKernel::PerTap) {
        plan.sampler = MapSampler::CompareNearest;
        plan.usesTapPattern = true;
    }
    plan.lightingDefines = {"GS_SHADOWS"};
    for (const std::string_view define : plan.traits->defines) {
        if (!define.empty()) {
            plan.lightingDefines.push_back(define);
        }
    }
    plan.readsPointGradient = plan.traits->readsPointGradient && !settings.usesCircular8Average();
    plan.storesGradient =
        plan.readsPointGradient && settings.gradientSource == GradientSource::StoredDerivatives;
    if (plan.storesGradient) {
        plan.depthDefines.push_back("GS_SHADOW_STORE_GRADIENT");
    }
    if (plan.traits->footprintTexels) {
        plan.normalOffsetTexels =
            (settings.footprintNormalOffset ? plan.traits->footprintTexels(settings) : 0.0f) +
            settings.normalOffsetTexels;
    }
    plan.constantBiasTexels =
        settings.constantBiasTexels + (settings.footprintNormalOffset ? plan.traits->reliefLiftTexels : 0.0f);
    addOptionDefines(settings, plan);
    if (const MomentStore& moments = plan.traits->moments; moments.format) {
        plan.momentsFormat = moments.format(settings);
        plan.momentBytesPerTexel = bytesPerTexel(plan.momentsFormat);
        plan.momentsClear = moments.farPlane(settings);
        plan.depthDefines.push_back(moments.define);
        plan.sharesDepthLayer = settings.mapAllocation == MapAllocation::Fitted;
    }
    if (plan.traits->shaderParameters) {
        plan.shaderParameters = plan.traits->shaderParameters(settings);
    }
    plan.depthFormat = glDepthFormat(settings.depthFormat);
    plan.depthBytesPerTexel = settings.depthFormat == DepthFormat::D16 ? 2 : 4;
    plan.offsetsCasters = plan.traits->offsetsCasters;
    if (plan.traits->biasesDepth) {
        plan.depthBias = settings.depthBiasSteps * depthBiasStep(settings.depthFormat);
        plan.depthBiasFloor = settings.depthBiasSteps * kArithmeticDepthStep;
    }
    plan.blursMoments = plan.momentsFormat != 0 && settings.momentBlurRadius > 0;
    if (plan.sampler == MapSampler::MomentMips) {
        plan.momentLevels = 1 + static_cast<int>(std::log2(momentSoftRadiusLimit(settings)));
    }
    plan.needsJitterTexture = plan.traits->jittered;
    plan.leavesOutShadowlessPlanes =
        settings.casterFaces == CasterFaces::Auto && !plan.traits->naive &&
        (plan.sampler == MapSampler::CompareNearest || plan.sampler == MapSampler::CompareLinear) &&
        plan.momentsFormat == 0 && !plan.readsPointGradient;
    // Two texels cover a bilinear footprint and central differences around any tap.
    plan.softReachTexels = plan.traits->softReachTexels ? plan.traits->softReachTexels(settings) : 0.0f;
    const float taps = plan.usesTapPattern || plan.traits->jittered ? settings.pcfRadius : 0.0f;
    const float blur = plan.momentsFormat != 0 ? static_cast<float>(settings.momentBlurRadius) : 0.0f;
    plan.kernelReachTexels = 2.0f + plan.softReachTexels + taps + blur;
    // A bilinear lookup (a hardware 2x2 comparison, filtered depth or moments) blurs an edge over two texels.
    plan.filterRadiusTexels = taps + blur + (plan.sampler == MapSampler::CompareNearest ? 0.0f : 0.5f);
    return plan;
}

int ShadowPlan::momentLevelsAt(int resolution) const {
    int levels = 1;
    while (levels < momentLevels && (resolution >> levels) > 0) {
        ++levels;
    }
    return levels;
}

std::size_t ShadowPlan::mapBytes(int resolution, int layers) const {
    const auto side = static_cast<std::size_t>(std::max(resolution, 0));
    const std::size_t texels = side * side;
    const auto count = static_cast<std::size_t>(std::max(layers, 0));
    std::size_t total =
        (sharesDepthLayer ? std::min<std::size_t>(count, 1) : count) * texels * depthBytesPerTexel;
    if (storesGradient) {
        total += count * texels * 8;
    } else if (momentsFormat != 0) {
        std::size_t chain = 0;
        for (int level = 0; level < momentLevelsAt(resolution); ++level) {
            const std::size_t levelSide = side >> level;
            chain += levelSide * levelSide * momentBytesPerTexel;
        }
        total += count * chain;
        if (blursMoments) {
            total += texels * momentBytesPerTexel; // the blur's one temporary layer
        }
    }
    return total;
}

int budgetedResolution(const ShadowPlan& plan, int resolution, int layers, std::size_t budgetBytes) {
    while (resolution > kSmallestMapSide && plan.mapBytes(resolution, layers) > budgetBytes) {
        resolution /= 2;
    }
    return resolution;
}

} // namespace shadows
