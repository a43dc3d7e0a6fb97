// The plan: a technique's row resolved against its options, once (no GL).
#include <shadows/ShadowPlan.h>
#include <shadows/VisibilityMath.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace shadows;

namespace {

bool has(const std::vector<std::string_view>& defines, std::string_view define) {
    return std::count(defines.begin(), defines.end(), define) == 1;
}

} // namespace

TEST(ShadowPlanTest, DefinesFollowOptionsOnlyWhereTheyApply) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::HardCompare};
    settings.pcfRotate = true; // no pattern: no rotation variant
    ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_FALSE(has(plan.lightingDefines, "GS_SHADOW_ROTATE"));
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_SAMPLER_COMPARE"));
    EXPECT_TRUE(plan.depthDefines.empty());

    settings.technique = ShadowTechnique::Gsm;
    settings.gradientSource = GradientSource::ScreenSpace;
    plan = ShadowPlan::resolve(settings);
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_GRADIENT_SCREEN"));
    EXPECT_FALSE(has(plan.lightingDefines, "GS_SHADOW_SAMPLER_COMPARE"));
    EXPECT_FALSE(plan.storesGradient);

    settings.gradientSource = GradientSource::StoredDerivatives;
    plan = ShadowPlan::resolve(settings);
    EXPECT_TRUE(plan.storesGradient);
    EXPECT_TRUE(has(plan.depthDefines, "GS_SHADOW_STORE_GRADIENT"));
}

TEST(ShadowPlanTest, TheAverageGradientsCircular8FormsReadNoPointGradient) {
    // They fit their own gradient from the 8 taps: no gradient source applies, and none is computed or
    // stored.
    ShadowSettings settings;
    settings.technique = ShadowTechnique::PcfGsmAverageGradient;
    settings.gradientSource = GradientSource::StoredDerivatives;
    EXPECT_TRUE(ShadowPlan::resolve(settings).readsPointGradient);
    EXPECT_TRUE(ShadowPlan::resolve(settings).storesGradient);
    for (const AverageGradientForm form :
         {AverageGradientForm::Circular8, AverageGradientForm::Circular8Vec4}) {
        settings.averageGradientForm = form;
        const ShadowPlan plan = ShadowPlan::resolve(settings);
        EXPECT_FALSE(plan.readsPointGradient);
        EXPECT_FALSE(plan.storesGradient);
        EXPECT_FALSE(has(plan.lightingDefines, "GS_SHADOW_GRADIENT_STORED"));
    }
}

TEST(ShadowPlanTest, ReceiverPlanePerTapComparesInHardwareOverThePattern) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::ReceiverPlaneBias};
    EXPECT_EQ(ShadowPlan::resolve(settings).sampler, MapSampler::DepthLinear);
    EXPECT_FALSE(ShadowPlan::resolve(settings).usesTapPattern);
    settings.receiverPlaneKernel = ReceiverPlaneKernel::PerTap;
    const ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.sampler, MapSampler::CompareNearest);
    EXPECT_TRUE(plan.usesTapPattern);
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_RPB_PER_TAP"));
}

TEST(ShadowPlanTest, QuantisedMomentsAreDeclaredOnceForBothPasses) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::Msm};
    settings.moments16 = false;
    ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.momentsFormat, static_cast<GLenum>(GL_RGBA32F));
    EXPECT_EQ(plan.momentBytesPerTexel, 16u);
    EXPECT_EQ(plan.momentsClear, glm::vec4(1.0f));
    EXPECT_FALSE(has(plan.lightingDefines, "GS_SHADOW_MSM_QUANTIZED"));
    settings.moments16 = true; // the default
    plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.momentsFormat, static_cast<GLenum>(GL_RGBA16));
    EXPECT_EQ(plan.momentBytesPerTexel, 8u);
    EXPECT_EQ(plan.momentsClear, glsl::gsMsmQuantize(glm::vec4(1.0f)));
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_MSM_QUANTIZED"));
    EXPECT_TRUE(has(plan.depthDefines, "GS_SHADOW_MSM_QUANTIZED"));
    EXPECT_TRUE(has(plan.depthDefines, "GS_SHADOW_STORE_MOMENTS4"));
}

TEST(ShadowPlanTest, VsmMomentsAreRG16UnlessMoments16IsOff) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::Vsm};
    ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.momentsFormat, static_cast<GLenum>(GL_RG16));
    EXPECT_EQ(plan.momentBytesPerTexel, 4u);
    EXPECT_EQ(plan.mapBytes(2048, 1), 2048u * 2048u * (4u + 4u)); // D24 + RG16: 32 MiB
    settings.moments16 = false;
    plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.momentsFormat, static_cast<GLenum>(GL_RG32F));
    EXPECT_EQ(plan.momentBytesPerTexel, 8u);
    // evsm does not take the setting: its warps overflow 16-bit floats at the default exponents.
    settings.technique = ShadowTechnique::Evsm;
    settings.moments16 = true;
    EXPECT_EQ(ShadowPlan::resolve(settings).momentsFormat, static_cast<GLenum>(GL_RGBA32F));
}

TEST(ShadowPlanTest, DepthFormatsAndCasterOffsets) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::SlopeScaledBias};
    settings.depthFormat = DepthFormat::D16;
    ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.depthFormat, static_cast<GLenum>(GL_DEPTH_COMPONENT16));
    EXPECT_EQ(plan.depthBytesPerTexel, 2u);
    EXPECT_TRUE(plan.offsetsCasters);
    EXPECT_FALSE(plan.needsJitterTexture);
    settings = ShadowSettings{.technique = ShadowTechnique::JitteredPcf};
    settings.depthFormat = DepthFormat::D32F;
    plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.depthFormat, static_cast<GLenum>(GL_DEPTH_COMPONENT32F));
    EXPECT_TRUE(plan.needsJitterTexture);
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_EARLY_OUT"));
    settings.earlyOutTestTaps = 0;
    EXPECT_FALSE(has(ShadowPlan::resolve(settings).lightingDefines, "GS_SHADOW_EARLY_OUT"));
}

TEST(ShadowPlanTest, MomentsAreBlurredOnlyForAMomentTechniqueWithABlurRadius) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::Evsm};
    EXPECT_FALSE(ShadowPlan::resolve(settings).blursMoments); // the default: hardware filtering only
    settings.momentBlurRadius = 2;
    EXPECT_TRUE(ShadowPlan::resolve(settings).blursMoments);
    settings.technique = ShadowTechnique::Pcf; // no moments, nothing to blur
    EXPECT_FALSE(ShadowPlan::resolve(settings).blursMoments);
}

TEST(ShadowPlanTest, SoftMomentsHaveAMipChainUpToTheirWidestRadius) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::MsmSoft};
    ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.sampler, MapSampler::MomentMips);
    // Radius 64 texels at most on a whole map (level 6, whose kernel reaches 96), 8 on virtual pages.
    EXPECT_EQ(momentSoftRadiusLimit(settings), 64.0f);
    EXPECT_EQ(plan.momentLevels, 7);
    EXPECT_GE(plan.kernelReachTexels, kMomentKernelReach * momentSoftRadiusLimit(settings));
    EXPECT_EQ(plan.shaderParameters.x, 64.0f);
    settings.mapAllocation = MapAllocation::Virtual;
    plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.momentLevels, 4);
    EXPECT_LE(kMomentKernelReach * momentSoftRadiusLimit(settings), plan.kernelReachTexels);
    // Always msm's quantised basis, stored and read the same way.
    EXPECT_EQ(plan.momentsFormat, static_cast<GLenum>(GL_RGBA16));
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_MSM_QUANTIZED"));
    EXPECT_TRUE(has(plan.depthDefines, "GS_SHADOW_STORE_MOMENTS4"));
    // Every other technique's moments keep their one level.
    for (const ShadowTechnique technique :
         {ShadowTechnique::Msm, ShadowTechnique::Evsm, ShadowTechnique::Vsm}) {
        EXPECT_EQ(ShadowPlan::resolve(ShadowSettings{.technique = technique}).momentLevels, 1);
    }
}

TEST(ShadowPlanTest, AdaptiveBiasTakesTheNearestComparisonsNormalOffset) {
    for (const ShadowTechnique technique :
         {ShadowTechnique::AdaptiveBias, ShadowTechnique::PcfAdaptiveBias}) {
        ShadowSettings settings = ShadowSettings{.technique = technique};
        const ShadowPlan plan = ShadowPlan::resolve(settings);
        EXPECT_NEAR(plan.normalOffsetTexels, 0.70710678f, 1e-6f); // half a texel diagonal
        EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_NORMAL_OFFSET"));
        settings.normalOffsetTexels = 1.0f; // the margin applies to them too
        EXPECT_NEAR(ShadowPlan::resolve(settings).normalOffsetTexels, 1.70710678f, 1e-6f);
    }
}

TEST(ShadowPlanTest, TechniquesComparingAlongTheReceiversPlaneLiftItForReliefWithinATexel) {
    for (const ShadowTechnique technique :
         {ShadowTechnique::NormalOffset, ShadowTechnique::AdaptiveBias, ShadowTechnique::PcfAdaptiveBias,
          ShadowTechnique::Gsm, ShadowTechnique::PcfGsmPointGradient, ShadowTechnique::PcfGsmAverageGradient,
          ShadowTechnique::PcfGsmQuadratic, ShadowTechnique::PcfGsmNearer,
          ShadowTechnique::PcfGsmConnected}) {
        ShadowSettings settings = ShadowSettings{.technique = technique};
        EXPECT_EQ(ShadowPlan::resolve(settings).constantBiasTexels, 0.5f);
        settings.constantBiasTexels = 1.0f; // the user's constant bias adds to it
        EXPECT_EQ(ShadowPlan::resolve(settings).constantBiasTexels, 1.5f);
        settings.footprintNormalOffset = false; // the reference's form: only the user's
        EXPECT_EQ(ShadowPlan::resolve(settings).constantBiasTexels, 1.0f);
    }
    // The others have a margin of their own; the naive reproductions have none unless asked for.
    for (const ShadowTechnique technique :
         {ShadowTechnique::HardCompare, ShadowTechnique::PcfGsmNaive, ShadowTechnique::SlopeScaledBias,
          ShadowTechnique::Pcf, ShadowTechnique::HardwarePcf, ShadowTechnique::Vsm}) {
        EXPECT_EQ(ShadowPlan::resolve(ShadowSettings{.technique = technique}).constantBiasTexels, 0.0f);
    }
}

TEST(ShadowPlanTest, TheFootprintNormalOffsetCanBeTurnedOffLeavingOnlyTheMargin) {
    ShadowSettings settings = ShadowSettings{.technique = ShadowTechnique::PcfGsmPointGradient};
    EXPECT_NEAR(ShadowPlan::resolve(settings).normalOffsetTexels, 0.70710678f, 1e-6f);
    settings.footprintNormalOffset = false; // the reference's form: no offset, no variant bit
    ShadowPlan plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.normalOffsetTexels, 0.0f);
    EXPECT_FALSE(has(plan.lightingDefines, "GS_SHADOW_NORMAL_OFFSET"));
    settings.normalOffsetTexels = 0.5f; // a margin alone still offsets
    plan = ShadowPlan::resolve(settings);
    EXPECT_EQ(plan.normalOffsetTexels, 0.5f);
    EXPECT_TRUE(has(plan.lightingDefines, "GS_SHADOW_NORMAL_OFFSET"));
}

TEST(ShadowPlanTest, OnlyTechniquesThatCompareLeaveOutPlanesThatShadowNothing) {
    // A texel left at the far plane reads as lit to a comparison, but moves filtered depths, moments and
    // gradient fits; and the naive reproductions show their acne on exactly those planes.
    for (std::size_t i = 0; i < kTechniqueCount; ++i) {
        ShadowSettings settings{.technique = static_cast<ShadowTechnique>(i)};
        const ShadowPlan plan = ShadowPlan::resolve(settings);
        const bool compares =
            plan.sampler == MapSampler::CompareNearest || plan.sampler == MapSampler::CompareLinear;
        EXPECT_EQ(plan.leavesOutShadowlessPlanes, compares && !plan.traits->naive && plan.momentsFormat == 0)
            << toString(settings.technique);
        settings.casterFaces = CasterFaces::Both;
        EXPECT_FALSE(ShadowPlan::resolve(settings).leavesOutShadowlessPlanes) << toString(settings.technique);
    }
    EXPECT_TRUE(
        ShadowPlan::resolve({.technique = ShadowTechnique::SlopeScaledBias}).leavesOutShadowlessPlanes);
    EXPECT_FALSE(ShadowPlan::resolve({.technique = ShadowTechnique::HardCompare}).leavesOutShadowlessPlanes);
    EXPECT_FALSE(ShadowPlan::resolve({.technique = ShadowTechnique::Gsm}).leavesOutShadowlessPlanes);
    EXPECT_FALSE(ShadowPlan::resolve({.technique = ShadowTechnique::Evsm}).leavesOutShadowlessPlanes);
    ShadowSettings perTap{.technique = ShadowTechnique::ReceiverPlaneBias};
    EXPECT_FALSE(ShadowPlan::resolve(perTap).leavesOutShadowlessPlanes);
    perTap.receiverPlaneKernel = ReceiverPlaneKernel::PerTap;
    EXPECT_TRUE(ShadowPlan::resolve(perTap).leavesOutShadowlessPlanes);
}

TEST(ShadowPlanTest, MapBytesCountEveryTargetTheTechniqueStores) {
    constexpr std::size_t kSide = 2048u * 2048u;
    EXPECT_EQ(ShadowPlan::resolve(ShadowSettings{}).mapBytes(2048, 3), 3u * kSide * 4u); // D24
    // GSM reading stored derivatives: their RG32F target beside the depth.
    ShadowSettings stored{.technique = ShadowTechnique::Gsm};
    stored.gradientSource = GradientSource::StoredDerivatives;
    ASSERT_TRUE(ShadowPlan::resolve(stored).storesGradient);
    EXPECT_EQ(ShadowPlan::resolve(stored).mapBytes(2048, 2), 2u * kSide * (4u + 8u));
    // EVSM's RGBA32F moments: the 80 MiB a 2048² map holds.
    EXPECT_EQ(ShadowPlan::resolve(ShadowSettings{.technique = ShadowTechnique::Evsm}).mapBytes(2048, 1),
              80u << 20);
    // Whole maps of a moment technique share one depth layer, and a blur adds its one temporary layer of
    // moments, however many maps there are.
    ShadowSettings blurred{.technique = ShadowTechnique::Evsm};
    blurred.momentBlurRadius = 2;
    ASSERT_TRUE(ShadowPlan::resolve(blurred).sharesDepthLayer);
    EXPECT_EQ(ShadowPlan::resolve(blurred).mapBytes(2048, 2), (16u << 20) + 2u * (64u << 20) + (64u << 20));
    // A virtual atlas keeps a depth layer per layer.
    blurred.mapAllocation = MapAllocation::Virtual;
    ASSERT_FALSE(ShadowPlan::resolve(blurred).sharesDepthLayer);
    EXPECT_EQ(ShadowPlan::resolve(blurred).mapBytes(2048, 2), 2u * (80u << 20) + (64u << 20));
    // Depth-only and gradient maps sample their depth: a layer each.
    EXPECT_FALSE(ShadowPlan::resolve(ShadowSettings{}).sharesDepthLayer);
    EXPECT_FALSE(ShadowPlan::resolve(stored).sharesDepthLayer);
    // msm-soft's mip chain: 7 levels of RGBA16 moments.
    std::size_t mipTexels = 0;
    for (std::size_t side = 2048; side >= 32; side /= 2) {
        mipTexels += side * side;
    }
    EXPECT_EQ(ShadowPlan::resolve(ShadowSettings{.technique = ShadowTechnique::MsmSoft}).mapBytes(2048, 1),
              kSide * 4u + mipTexels * 8u);
    EXPECT_EQ(ShadowPlan::resolve(ShadowSettings{}).mapBytes(2048, 0), 0u);
}

struct BudgetCase {
    const char* name;
    ShadowTechnique technique;
    int layers;
    std::size_t budgetMiB;
    int side;
};

class BudgetedResolutionTest : public testing::TestWithParam<BudgetCase> {};

TEST_P(BudgetedResolutionTest, HalvesTheSideUntilTheMapsFit) {
    const BudgetCase& c = GetParam();
    const ShadowPlan plan = ShadowPlan::resolve(ShadowSettings{.technique = c.technique});
    const int side = budgetedResolution(plan, 2048, c.layers, c.budgetMiB << 20);
    EXPECT_EQ(side, c.side);
    // The largest that fits: twice the side would not (unless it is the resolution asked for).
    if (side > 64) {
        EXPECT_LE(plan.mapBytes(side, c.layers), c.budgetMiB << 20);
    }
    if (side < 2048) {
        EXPECT_GT(plan.mapBytes(2 * side, c.layers), c.budgetMiB << 20);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BudgetedResolutionTest,
    testing::Values(
        // Eight point lights' 48 faces in 16 MiB each: 768 MiB, within the default budget.
        BudgetCase{"depth_48_faces_fit", ShadowTechnique::SlopeScaledBias, 48, 1024, 2048},
        // The same under EVSM, 64 MiB of moments each beside their one shared depth layer (3.02 GiB): 1024²
        // (772 MiB).
        BudgetCase{"evsm_48_faces_halved", ShadowTechnique::Evsm, 48, 1024, 1024},
        // The room's two point lights under EVSM: 784 MiB, which fits.
        BudgetCase{"evsm_12_faces_fit", ShadowTechnique::Evsm, 12, 1024, 2048},
        BudgetCase{"evsm_12_faces_in_100_MiB", ShadowTechnique::Evsm, 12, 100, 512},
        // The smallest budget holds 48 EVSM maps of 64².
        BudgetCase{"evsm_48_faces_in_4_MiB", ShadowTechnique::Evsm, 48, 4, 64},
        // Below that the side stops at 64, over the budget.
        BudgetCase{"stops_at_64", ShadowTechnique::Evsm, 48, 1, 64},
        BudgetCase{"no_maps", ShadowTechnique::Evsm, 0, 4, 2048}),
    [](const testing::TestParamInfo<BudgetCase>& budget) { return std::string(budget.param.name); });
