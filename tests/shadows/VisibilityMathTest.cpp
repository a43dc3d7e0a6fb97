// CPU tests of shaders/shadows/visibility.glsl (compiled as C++ through VisibilityMath.h).
#include <shadows/TapPattern.h>
#include <shadows/VisibilityMath.h>

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

using namespace shadows;
namespace g = shadows::glsl;

namespace {

constexpr float kD24Step = 1.0f / 16777215.0f;

/// Depths of `surface` at the pattern's taps around `centre` (texel units), as the depth map would hold them.
struct Taps {
    float depths[g::GS_MAX_TAPS] = {};
    glm::vec2 offsets[g::GS_MAX_TAPS] = {};
    int count = 0;
};

Taps sample(const TapPattern& pattern, const std::function<float(glm::vec2)>& surface,
            glm::vec2 centre = {}) {
    Taps taps;
    taps.count = static_cast<int>(pattern.offsets.size());
    for (int i = 0; i < taps.count; ++i) {
        taps.offsets[i] = pattern.offsets[static_cast<std::size_t>(i)];
        taps.depths[i] = surface(centre + taps.offsets[i]);
    }
    return taps;
}

float pcfGsm(const TapPattern& pattern, const Taps& taps, float receiverDepth, glm::vec2 pointGradient,
             int correction) {
    float fitRows[6 * g::GS_MAX_TAPS];
    std::copy(pattern.quadraticFitRows.begin(), pattern.quadraticFitRows.end(), fitRows);
    return g::gsPcfGsmVisibility(taps.depths, taps.offsets, taps.count, receiverDepth, pointGradient,
                                 correction, pattern.inverseCovariance, fitRows, 1.0f, kD24Step);
}

struct PatternCase {
    const char* name;
    TapLayout layout;
    int taps;
    float radius;
};

const PatternCase kPatterns[] = {
    {"grid2", TapLayout::Grid, 2, 0.5f},          {"grid4", TapLayout::Grid, 4, 1.5f},
    {"grid8", TapLayout::Grid, 8, 3.5f},          {"poisson8", TapLayout::Poisson, 8, 2.0f},
    {"poisson32", TapLayout::Poisson, 32, 3.0f},  {"poisson64", TapLayout::Poisson, 64, 4.0f},
    {"circular8", TapLayout::Circular8, 8, 1.0f},
};

class PatternTest : public testing::TestWithParam<PatternCase> {
protected:
    TapPattern pattern() const {
        return TapPattern::make(GetParam().layout, GetParam().taps, GetParam().radius);
    }
};

// A plane seen from the light: 0.4 deep at the fragment, sloping 3e-4 per texel in x and -1e-4 in y.
const glm::vec2 kSlope{3e-4f, -1e-4f};
float plane(glm::vec2 texel) {
    return 0.4f + glm::dot(texel, kSlope);
}

} // namespace

TEST_P(PatternTest, AverageGradientRecoversThePlaneExactly) {
    const TapPattern p = pattern();
    const Taps taps = sample(p, plane, {7.25f, -3.5f});
    const glm::vec2 gradient =
        g::gsLeastSquaresGradient(taps.depths, taps.offsets, taps.count, p.inverseCovariance);
    EXPECT_NEAR(gradient.x, kSlope.x, 2e-7f);
    EXPECT_NEAR(gradient.y, kSlope.y, 2e-7f);
}

TEST_P(PatternTest, CorrectedTechniquesSeeALitPlaneAsFullyLit) {
    const TapPattern p = pattern();
    const Taps taps = sample(p, plane);
    const float receiver = plane({}) - 1e-6f; // the lit surface itself, with a tiny GSM bias
    EXPECT_EQ(pcfGsm(p, taps, receiver, kSlope, g::GS_CORRECTION_POINT), 1.0f);
    EXPECT_EQ(pcfGsm(p, taps, receiver, kSlope, g::GS_CORRECTION_AVERAGE), 1.0f);
    EXPECT_EQ(pcfGsm(p, taps, receiver, kSlope, g::GS_CORRECTION_QUADRATIC), 1.0f);
}

TEST_P(PatternTest, NaivePcfOverGsmLosesAboutHalfTheLight) {
    // Reference Fig. 4.2.3: uncorrected taps dip into the shadow volume on one side of every slope.
    const TapPattern p = pattern();
    const Taps taps = sample(p, plane);
    const float naive = pcfGsm(p, taps, plane({}) - 1e-6f, kSlope, g::GS_CORRECTION_NONE);
    EXPECT_GT(naive, 0.3f);
    EXPECT_LT(naive, 0.8f);
}

INSTANTIATE_TEST_SUITE_P(Patterns, PatternTest, testing::ValuesIn(kPatterns),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(VisibilityMathTest, NaiveDarkeningApproachesOneHalfForWidePatterns) {
    const TapPattern p = TapPattern::make(TapLayout::Grid, 8, 3.5f);
    const Taps taps = sample(p, plane);
    EXPECT_NEAR(pcfGsm(p, taps, plane({}), kSlope, g::GS_CORRECTION_NONE), 0.5f, 0.08f);
}

TEST(VisibilityMathTest, QuadraticFitRecoversAParaboloid) {
    const TapPattern p = TapPattern::make(TapLayout::Grid, 5, 2.0f);
    ASSERT_TRUE(p.quadraticValid);
    // z = 0.5 + g.o + ½ oᵀHo with Hxx = 2e-4, Hxy = -5e-5, Hyy = 1e-4.
    const glm::vec3 h(2e-4f, -5e-5f, 1e-4f);
    auto paraboloid = [&](glm::vec2 o) {
        return 0.5f + glm::dot(o, kSlope) + 0.5f * h.x * o.x * o.x + h.y * o.x * o.y + 0.5f * h.z * o.y * o.y;
    };
    const Taps taps = sample(p, paraboloid);
    float fitRows[6 * g::GS_MAX_TAPS];
    std::copy(p.quadraticFitRows.begin(), p.quadraticFitRows.end(), fitRows);
    glm::vec3 curvature;
    const glm::vec2 gradient = g::gsQuadraticFit(taps.depths, taps.count, fitRows, curvature);
    EXPECT_NEAR(gradient.x, kSlope.x, 1e-6f);
    EXPECT_NEAR(gradient.y, kSlope.y, 1e-6f);
    EXPECT_NEAR(curvature.x, h.x, 2e-6f);
    EXPECT_NEAR(curvature.y, h.y, 2e-6f);
    EXPECT_NEAR(curvature.z, h.z, 2e-6f);
    // On the paraboloid itself every tap is predicted exactly: fully lit.
    EXPECT_EQ(pcfGsm(p, taps, paraboloid({}) - 1e-6f, kSlope, g::GS_CORRECTION_QUADRATIC), 1.0f);
}

TEST(VisibilityMathTest, ConcaveSurfaceDarkensLessUnderHigherOrderCorrections) {
    // A concave valley (curving towards the light, i.e. depth decreasing away from the fragment), the
    // knob-neck case of Fig. 4.2.5: both planes darken it, the quadric does not. For a parabola and a
    // symmetric pattern the least-squares slope is the tangent's, so the average gradient darkens it as the
    // point one.
    const TapPattern p = TapPattern::make(TapLayout::Grid, 5, 2.0f);
    const glm::vec2 slope(4e-4f, 0.0f);
    auto valley = [&](glm::vec2 o) { return 0.5f + glm::dot(o, slope) - 6e-5f * (o.x * o.x + o.y * o.y); };
    const Taps taps = sample(p, valley, {});
    const float receiver = valley({}) - 1e-6f;
    const float point = pcfGsm(p, taps, receiver, slope, g::GS_CORRECTION_POINT);
    const float average = pcfGsm(p, taps, receiver, slope, g::GS_CORRECTION_AVERAGE);
    const float quadratic = pcfGsm(p, taps, receiver, slope, g::GS_CORRECTION_QUADRATIC);
    EXPECT_LT(point, 1.0f);
    EXPECT_NEAR(average, point, 1e-6f);
    EXPECT_EQ(quadratic, 1.0f);
}

TEST(VisibilityMathTest, Circular8ClosedFormsMatchTheGeneralRegression) {
    const TapPattern p = TapPattern::make(TapLayout::Circular8, 8, 0.7f);
    const Taps taps = sample(p, plane);
    float eight[8];
    std::copy(taps.depths, taps.depths + 8, eight);
    const float displace = 0.7f / std::sqrt(2.0f);
    const glm::vec2 closed = g::gsCircular8Gradient(eight, displace);
    const glm::vec2 simd =
        g::gsCircular8GradientVec4(glm::vec4(eight[0], eight[1], eight[2], eight[3]),
                                   glm::vec4(eight[4], eight[5], eight[6], eight[7]), displace);
    const glm::vec2 general = g::gsLeastSquaresGradient(taps.depths, taps.offsets, 8, p.inverseCovariance);
    EXPECT_NEAR(closed.x, general.x, 1e-7f);
    EXPECT_NEAR(closed.y, general.y, 1e-7f);
    EXPECT_NEAR(simd.x, general.x, 1e-7f);
    EXPECT_NEAR(simd.y, general.y, 1e-7f);
    EXPECT_NEAR(general.x, kSlope.x, 2e-7f);
    EXPECT_FALSE(p.quadraticValid); // all eight taps lie on one circle: no quadric through them
}

struct ExtremeCase {
    const char* name;
    float stored;
    float receiver;
    float gradientMagnitude;
    float minimumWidth;
};

class FuzzyExtremesTest : public testing::TestWithParam<ExtremeCase> {};

TEST_P(FuzzyExtremesTest, StaysFiniteAndInUnitRange) {
    const ExtremeCase& c = GetParam();
    const float v = g::gsFuzzyVisibility(c.stored, c.receiver, c.gradientMagnitude, 1.0f, c.minimumWidth);
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
}

INSTANTIATE_TEST_SUITE_P(Cases, FuzzyExtremesTest,
                         testing::Values(ExtremeCase{"zeroGradientLit", 0.5f, 0.5f, 0.0f, 0.0f},
                                         ExtremeCase{"zeroGradientShadowed", 0.4f, 0.5f, 0.0f, 0.0f},
                                         ExtremeCase{"zeroGradientZeroDiff", 0.5f, 0.5f, 0.0f, kD24Step},
                                         ExtremeCase{"grazingGradient", 0.5f, 0.7f, 1e30f, kD24Step},
                                         ExtremeCase{"hugeDifference", 1.0f, 0.0f, 1e-30f, 0.0f},
                                         ExtremeCase{"denormalGradient", 0.5f, 0.50001f, 1e-42f, 0.0f}),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(VisibilityMathTest, ZeroGradientIsAFiniteHardComparison) {
    // With no gradient the band is one depth step of the format (D16 here, coarse enough for float at 0.5).
    const float step = 1.0f / 65535.0f;
    EXPECT_EQ(g::gsFuzzyVisibility(0.5f, 0.5f, 0.0f, 1.0f, step), 1.0f);
    EXPECT_EQ(g::gsFuzzyVisibility(0.5f, 0.5f + 10.0f * step, 0.0f, 1.0f, step), 0.0f);
    EXPECT_NEAR(g::gsFuzzyVisibility(0.5f, 0.5f + 0.5f * step, 0.0f, 1.0f, step), 0.5f, 1e-3f);
}

TEST(VisibilityMathTest, ReceiverPlaneGradientSolvesTheChainRule) {
    // uv = M xy with M = [[2, 0.5], [-1, 3]] (columns: d/dx, d/dy), z = 0.1 u - 0.2 v: dz/duv must be (0.1,
    // -0.2).
    const glm::vec2 duvdx(2.0f, -1.0f);
    const glm::vec2 duvdy(0.5f, 3.0f);
    const float dzdx = 0.1f * duvdx.x - 0.2f * duvdx.y;
    const float dzdy = 0.1f * duvdy.x - 0.2f * duvdy.y;
    const glm::vec2 g2 = g::gsReceiverPlaneGradient(duvdx, duvdy, dzdx, dzdy);
    EXPECT_NEAR(g2.x, 0.1f, 1e-6f);
    EXPECT_NEAR(g2.y, -0.2f, 1e-6f);
}

TEST(VisibilityMathTest, SingularJacobianGivesZeroGradientNotInfinity) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const auto& [dx, dy] : {std::pair{glm::vec2(1, 2), glm::vec2(2, 4)},          // parallel: det = 0
                                 std::pair{glm::vec2(0, 0), glm::vec2(0, 0)},          // no footprint
                                 std::pair{glm::vec2(1, 1), glm::vec2(1, 1.0000001f)}, // nearly parallel
                                 std::pair{glm::vec2(nan, 0), glm::vec2(0, 1)}}) {
        EXPECT_EQ(g::gsReceiverPlaneGradient(dx, dy, 0.3f, -0.7f), glm::vec2(0.0f));
    }
    // A vanishing but well-conditioned footprint (det underflows to a denormal) stays finite.
    const glm::vec2 tiny = g::gsReceiverPlaneGradient({1e-20f, 0}, {0, 1e-20f}, 0.3e-20f, -0.7e-20f);
    EXPECT_TRUE(std::isfinite(tiny.x) && std::isfinite(tiny.y));
    EXPECT_NEAR(tiny.x, 0.3f, 1e-3f);
}

TEST(VisibilityMathTest, FloorToStepRemovesRoundingUpward) {
    const float step = 1.0f / 65535.0f;
    const float depth = 1000.6f * step; // rounds up to 1001 steps, floors to 1000
    EXPECT_FLOAT_EQ(g::gsFloorToStep(depth, step), 1000.0f * step);
    EXPECT_LE(g::gsFloorToStep(depth, step), depth);
    EXPECT_EQ(g::gsFloorToStep(depth, 0.0f), depth);
}

TEST(VisibilityMathTest, ReceiverPlaneClampOnlyMovesTowardsTheLight) {
    const glm::vec2 gradient(1e-3f, 0.0f);
    EXPECT_FLOAT_EQ(g::gsReceiverPlaneTapDepth(0.5f, {0.5f, 0.0f}, gradient, false), 0.5005f);
    EXPECT_FLOAT_EQ(g::gsReceiverPlaneTapDepth(0.5f, {0.5f, 0.0f}, gradient, true), 0.5f);
    EXPECT_FLOAT_EQ(g::gsReceiverPlaneTapDepth(0.5f, {-0.5f, 0.0f}, gradient, true), 0.4995f);
}

TEST(VisibilityMathTest, BilinearBlendFollowsGatherOrder) {
    // Gather: x (-,+), y (+,+), z (+,-), w (-,-). At weights (0,0) we are at the (-,-) texel.
    const glm::vec4 v(0.1f, 0.2f, 0.3f, 0.4f);
    EXPECT_FLOAT_EQ(g::gsBilinear(v, {0, 0}), 0.4f);
    EXPECT_FLOAT_EQ(g::gsBilinear(v, {1, 0}), 0.3f);
    EXPECT_FLOAT_EQ(g::gsBilinear(v, {0, 1}), 0.1f);
    EXPECT_FLOAT_EQ(g::gsBilinear(v, {1, 1}), 0.2f);
}

TEST(FilteredShadowMathTest, ChebyshevMatchesTheClosedFormBound) {
    // Mean 0.4, variance 0.01: at depth 0.6 the bound is 0.01 / (0.01 + 0.04) = 0.2.
    const glm::vec2 moments(0.4f, 0.01f + 0.16f);
    EXPECT_NEAR(g::gsChebyshevVisibility(moments, 0.6f, 0.0f, 0.0f), 0.2f, 1e-5f);
    EXPECT_EQ(g::gsChebyshevVisibility(moments, 0.4f, 0.0f, 0.0f), 1.0f); // mean beyond the receiver: lit
    EXPECT_EQ(g::gsChebyshevVisibility(moments, 0.1f, 0.0f, 0.0f), 1.0f);
    // Bleeding reduction 0.1 maps 0.2 to (0.2 - 0.1) / 0.9.
    EXPECT_NEAR(g::gsChebyshevVisibility(moments, 0.6f, 0.0f, 0.1f), 0.1f / 0.9f, 1e-5f);
    // Zero variance with a minimum: finite and in range.
    const float v = g::gsChebyshevVisibility(glm::vec2(0.5f, 0.25f), 0.5001f, 1e-6f, 0.0f);
    EXPECT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f);
    EXPECT_LT(g::gsChebyshevVisibility(glm::vec2(0.5f, 0.25f), 0.6f, 0.0f, 0.0f), 1e-20f);
}

TEST(FilteredShadowMathTest, EvsmCutsTheLightBleedingOfVsm) {
    // Half the filter region at depth 0.2, half at 0.5; a receiver at 0.6 is behind both. VSM's bound still
    // lets a third of the light through; the exponential warps leave under 1 %.
    const glm::vec2 exponents(40.0f, 5.0f);
    const glm::vec4 evsm = 0.5f * (g::gsEvsmMoments(0.2f, exponents) + g::gsEvsmMoments(0.5f, exponents));
    const glm::vec2 vsm(0.35f, 0.5f * (0.04f + 0.25f));
    EXPECT_GT(g::gsChebyshevVisibility(vsm, 0.6f, 1e-6f, 0.0f), 0.25f);
    EXPECT_LT(g::gsEvsmVisibility(evsm, 0.6f, exponents, 1e-6f, 0.0f), 0.01f);
}

TEST(FilteredShadowMathTest, EvsmSeesItsOwnDepthAndTheFarPlaneAsLit) {
    const glm::vec2 exponents(40.0f, 5.0f);
    for (const float depth : {0.0f, 0.3f, 0.7f, 0.999f}) {
        EXPECT_EQ(g::gsEvsmVisibility(g::gsEvsmMoments(depth, exponents), depth, exponents, 1e-6f, 0.2f),
                  1.0f);
        // A cleared texel holds the far plane: nothing in front of it is shadowed.
        EXPECT_EQ(g::gsEvsmVisibility(g::gsEvsmMoments(1.0f, exponents), depth, exponents, 1e-6f, 0.2f),
                  1.0f);
    }
    // Well behind a single occluder: shadowed.
    EXPECT_LT(g::gsEvsmVisibility(g::gsEvsmMoments(0.4f, exponents), 0.5f, exponents, 1e-6f, 0.2f), 0.01f);
}

TEST(FilteredShadowMathTest, EvsmIsFiniteAndBoundedAtTheLargestExponents) {
    const glm::vec2 exponents(42.0f, 42.0f);
    for (float occluder = 0.0f; occluder <= 1.0f; occluder += 0.125f) {
        const glm::vec4 moments =
            0.5f * (g::gsEvsmMoments(occluder, exponents) + g::gsEvsmMoments(1.0f, exponents));
        ASSERT_TRUE(std::isfinite(moments.y) && std::isfinite(moments.w)) << occluder;
        for (float depth = 0.0f; depth <= 1.0f; depth += 0.0625f) {
            const float v = g::gsEvsmVisibility(moments, depth, exponents, 1e-6f, 0.0f);
            ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << occluder << " " << depth << " " << v;
        }
    }
}

TEST(FilteredShadowMathTest, MsmRecoversATwoDepthMixture) {
    // 30 % of the filter region at depth 0.3, 70 % at 0.7.
    const glm::vec4 moments = 0.3f * g::gsMsmMoments(0.3f) + 0.7f * g::gsMsmMoments(0.7f);
    const float bias = 1e-6f;
    EXPECT_NEAR(g::gsMsmVisibility(moments, 0.2f, bias), 1.0f, 1e-3f); // in front of both occluders
    EXPECT_NEAR(g::gsMsmVisibility(moments, 0.5f, bias), 0.7f, 0.02f); // behind the nearer 30 %
    EXPECT_NEAR(g::gsMsmVisibility(moments, 0.9f, bias), 0.0f, 0.02f); // behind both
}

TEST(FilteredShadowMathTest, MsmIsFiniteForConstantDepthTexels) {
    // A constant-depth texel has singular moments (rank-1 Hankel matrix).
    for (const float z : {0.0f, 1e-4f, 0.25f, 0.5f, 0.999f, 1.0f}) {
        for (const float bias : {0.0f, 3e-5f, 9e-3f}) {
            for (const float receiver : {0.0f, z - 1e-3f, z, z + 1e-3f, 1.0f}) {
                const float v = g::gsMsmVisibility(g::gsMsmMoments(z), receiver, bias);
                EXPECT_TRUE(std::isfinite(v)) << z << " " << bias << " " << receiver;
                EXPECT_GE(v, 0.0f);
                EXPECT_LE(v, 1.0f);
            }
        }
    }
}

TEST(MomentSoftMathTest, BlockerOfATwoDepthMixtureIsTheNearerDepth) {
    // 40 % of the search region a blocker at depth 0.3, the rest the receiver's surface at 0.7.
    const glm::vec4 moments = 0.4f * g::gsMsmMoments(0.3f) + 0.6f * g::gsMsmMoments(0.7f);
    float fraction = -1.0f;
    EXPECT_NEAR(g::gsMsmBlocker(moments, 0.69f, 1e-6f, fraction), 0.3f, 0.01f);
    EXPECT_NEAR(fraction, 0.4f, 0.01f);
    // Its fraction is Hamburger's shadow intensity there.
    EXPECT_NEAR(fraction, 1.0f - g::gsMsmVisibility(moments, 0.69f, 1e-6f), 1e-4f);
}

TEST(MomentSoftMathTest, BlockersAtTwoDepthsAverageByWeight) {
    // Three depths, the farthest the receiver's: the bound's distribution is exactly this one, so the
    // blockers' mean is (0.3 * 0.2 + 0.5 * 0.5) / 0.8.
    const glm::vec4 moments =
        0.3f * g::gsMsmMoments(0.2f) + 0.5f * g::gsMsmMoments(0.5f) + 0.2f * g::gsMsmMoments(0.8f);
    float fraction = -1.0f;
    EXPECT_NEAR(g::gsMsmBlocker(moments, 0.8f, 1e-7f, fraction), 0.3875f, 0.01f);
    EXPECT_NEAR(fraction, 0.8f, 0.01f);
}

TEST(MomentSoftMathTest, NothingInFrontOfTheReceiverIsNoBlocker) {
    const glm::vec4 moments = 0.5f * g::gsMsmMoments(0.6f) + 0.5f * g::gsMsmMoments(0.9f);
    float fraction = -1.0f;
    EXPECT_EQ(g::gsMsmBlocker(moments, 0.5f, 3e-5f, fraction), 0.5f);
    EXPECT_EQ(fraction, 0.0f);
}

TEST(MomentSoftMathTest, BlockerIsFiniteAndInRangeForSingularAndExtremeMoments) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const float z : {0.0f, 1e-4f, 0.25f, 0.5f, 0.999f, 1.0f}) {
        for (const float bias : {0.0f, 3e-5f, 9e-3f}) {
            for (const float receiver : {0.0f, z - 1e-3f, z, z + 1e-3f, 1.0f}) {
                float fraction = -1.0f;
                const float blocker = g::gsMsmBlocker(g::gsMsmMoments(z), receiver, bias, fraction);
                EXPECT_TRUE(std::isfinite(blocker)) << z << " " << bias << " " << receiver;
                EXPECT_GE(fraction, 0.0f);
                EXPECT_LE(fraction, 1.0f);
                EXPECT_LE(blocker, std::max(receiver, 0.0f) + 1e-3f) << z << " " << bias << " " << receiver;
            }
        }
    }
    float fraction = -1.0f;
    g::gsMsmBlocker(glm::vec4(nan), 0.5f, 3e-5f, fraction);
    EXPECT_EQ(fraction, 0.0f);
    g::gsMsmBlocker(g::gsMsmMoments(0.5f), nan, 3e-5f, fraction);
    EXPECT_EQ(fraction, 0.0f);
}

TEST(FilteredShadowMathTest, QuantisedMomentsRoundTripWithinTheSixteenBitBound) {
    const glm::mat4 inverse = glm::inverse(g::GS_MSM_QUANTIZE);
    // The bound: half a 16-bit step through the inverse transform (its largest absolute row sum).
    float rowSum = 0.0f;
    for (int r = 0; r < 4; ++r) {
        float sum = 0.0f;
        for (int c = 0; c < 4; ++c) {
            sum += std::abs(inverse[c][r]);
        }
        rowSum = std::max(rowSum, sum);
    }
    const float bound = rowSum * 0.5f / 65535.0f + 1e-6f;
    for (int i = 0; i <= 100; ++i) {
        const float z = static_cast<float>(i) / 100.0f;
        const glm::vec4 quantised = g::gsMsmQuantize(g::gsMsmMoments(z));
        for (int c = 0; c < 4; ++c) {
            EXPECT_GE(quantised[c], -1e-4f);
            EXPECT_LE(quantised[c], 1.0f + 1e-4f);
        }
        const glm::vec4 stored = glm::round(glm::clamp(quantised, 0.0f, 1.0f) * 65535.0f) / 65535.0f;
        const glm::vec4 back = g::gsMsmDequantize(stored, inverse);
        const glm::vec4 exact = g::gsMsmMoments(z);
        for (int c = 0; c < 4; ++c) {
            EXPECT_NEAR(back[c], exact[c], bound) << "z " << z << " moment " << c;
        }
    }
}

// ---- Automatic bias: normal offset and the adaptive depth bias's tangent plane ----

struct FacetCase {
    const char* name;
    float scale; // of the screen derivatives: a pixel's world size
};

class FacetNormalTest : public ::testing::TestWithParam<FacetCase> {};

TEST_P(FacetNormalTest, IsTheUnitNormalFacingTheViewerAtEveryScale) {
    // A facet tilted off every axis, its derivatives at the case's scale: dPdx × dPdy, unit length.
    const float s = GetParam().scale;
    const glm::vec3 dPdx = s * glm::vec3(1.0f, 0.2f, -0.1f);
    const glm::vec3 dPdy = s * glm::vec3(0.3f, 0.1f, 1.0f);
    const glm::vec3 expected =
        glm::normalize(glm::cross(glm::vec3(1.0f, 0.2f, -0.1f), glm::vec3(0.3f, 0.1f, 1.0f)));
    const glm::vec3 facet = g::gsFacetNormal(dPdx, dPdy, glm::vec3(0.0f, 1.0f, 0.0f));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(facet[c], expected[c], 1e-6f) << GetParam().name << " component " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Scales, FacetNormalTest,
                         ::testing::Values(FacetCase{"Unit", 1.0f}, FacetCase{"Millimetre", 1e-3f},
                                           FacetCase{"Tiny", 1e-20f}, FacetCase{"Huge", 1e30f}),
                         [](const ::testing::TestParamInfo<FacetCase>& facet) { return facet.param.name; });

TEST(FacetNormalEdgeTest, KeepsTheShadingNormalWhereTheFacetHasNoArea) {
    const glm::vec3 shading(0.0f, 0.0f, 1.0f);
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 d(1.0f, 2.0f, 3.0f);
    EXPECT_EQ(g::gsFacetNormal(glm::vec3(0.0f), glm::vec3(0.0f), shading), shading) << "no derivatives";
    EXPECT_EQ(g::gsFacetNormal(d, 2.0f * d, shading), shading) << "edge-on: parallel derivatives";
    EXPECT_EQ(g::gsFacetNormal(1e-39f * d, 1e-39f * glm::vec3(3.0f, 1.0f, 2.0f), shading), shading)
        << "subnormal derivatives";
    EXPECT_EQ(g::gsFacetNormal(glm::vec3(inf, 0.0f, 0.0f), d, shading), shading) << "infinite";
    EXPECT_EQ(g::gsFacetNormal(glm::vec3(nan, 0.0f, 0.0f), d, shading), shading) << "NaN first";
    EXPECT_EQ(g::gsFacetNormal(d, glm::vec3(0.0f, nan, 0.0f), shading), shading) << "NaN second";
}

TEST(AutomaticBiasMathTest, NormalOffsetIsZeroFacingTheLightAndTheReachEdgeOn) {
    EXPECT_FLOAT_EQ(g::gsNormalOffset(3.0f, 1.0f), 0.0f);
    EXPECT_FLOAT_EQ(g::gsNormalOffset(3.0f, -1.0f), 0.0f);
    EXPECT_FLOAT_EQ(g::gsNormalOffset(3.0f, 0.0f), 3.0f);
    EXPECT_NEAR(g::gsNormalOffset(2.0f, std::cos(0.5f)), 2.0f * std::sin(0.5f), 1e-6f);
    // Rounding may push |cos| past 1: still finite, still zero.
    EXPECT_FLOAT_EQ(g::gsNormalOffset(2.0f, 1.0000001f), 0.0f);
}

TEST(AutomaticBiasMathTest, NormalOffsetClearsAPlaneOverTheReachAtEveryAngle) {
    // 2D: a plane through the origin at angle theta to an orthographic light shining along -y. A receiver at
    // the origin is offset by h along the normal; a lookup `reach` away (across the light) must find the
    // plane no nearer to the light than the offset receiver.
    const float reach = 2.5f;
    for (float theta = 0.0f; theta < 1.5707f; theta += 0.01f) {
        const glm::vec2 normal(-std::sin(theta), std::cos(theta));
        const float h = g::gsNormalOffset(reach, normal.y);
        const glm::vec2 receiver = h * normal;
        for (const float side : {-1.0f, 1.0f}) {
            const float x = receiver.x + side * reach;
            const float planeHeight = x * std::tan(theta); // the plane's height (towards the light) there
            EXPECT_GE(receiver.y + 1e-4f, planeHeight) << "theta " << theta;
        }
    }
}

namespace {
/// Orthographic light looking down -z onto the unit square of texture space, depth 0 at z = 1, 1 at z = -1.
glm::mat4 orthographicMap() {
    glm::mat4 m(1.0f);
    m[0][0] = 0.5f;
    m[1][1] = 0.5f;
    m[2][2] = -0.5f;
    m[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    return m;
}
} // namespace

TEST(AdaptiveBiasMathTest, PlaneFacingAnOrthographicLightHasZeroGradient) {
    const glm::vec2 gradient =
        g::gsTangentPlaneGradient(orthographicMap(), {0.1f, -0.2f, 0.3f}, {0.0f, 0.0f, 1.0f}, 1024.0f);
    EXPECT_EQ(gradient, glm::vec2(0.0f));
}

TEST(AdaptiveBiasMathTest, TiltedPlaneGradientIsItsSlopePerTexel) {
    // Tilted by theta about y: z falls by tan(theta) per world unit in x; texture x spans 2 world units in
    // 1024 texels, depth spans 2 world units in 1.
    const float theta = 0.7f;
    const glm::vec3 normal(std::sin(theta), 0.0f, std::cos(theta));
    const glm::vec2 gradient =
        g::gsTangentPlaneGradient(orthographicMap(), {0.0f, 0.0f, 0.0f}, normal, 1024.0f);
    EXPECT_NEAR(gradient.x, std::tan(theta) * (2.0f / 1024.0f) * 0.5f, 1e-7f);
    EXPECT_NEAR(gradient.y, 0.0f, 1e-9f);
}

TEST(AdaptiveBiasMathTest, EdgeOnAndDegenerateNormalsGiveZeroNotInfinity) {
    EXPECT_EQ(g::gsTangentPlaneGradient(orthographicMap(), {}, {1.0f, 0.0f, 0.0f}, 1024.0f), glm::vec2(0.0f));
    EXPECT_EQ(g::gsTangentPlaneGradient(orthographicMap(), {}, {0.0f, 0.0f, 0.0f}, 1024.0f), glm::vec2(0.0f));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(g::gsTangentPlaneGradient(orthographicMap(), {}, {nan, 0.0f, 1.0f}, 1024.0f), glm::vec2(0.0f));
}

TEST(AdaptiveBiasMathTest, GrazingPlaneGradientIsLargeButFinite) {
    const float theta = 1.5707f; // 0.005° from edge-on
    const glm::vec2 gradient =
        g::gsTangentPlaneGradient(orthographicMap(), {}, {std::sin(theta), 0.0f, std::cos(theta)}, 1024.0f);
    EXPECT_TRUE(std::isfinite(gradient.x));
    EXPECT_GT(gradient.x, 1.0f); // more than the whole depth range per texel
}

TEST(AdaptiveBiasMathTest, PerspectiveMapPredictsThePlaneDepthExactlyAcrossTexels) {
    // A spot light at the origin looking down -z, 60° field of view, near 0.5, far 50; texture-space bias.
    const glm::mat4 bias =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    const glm::mat4 map = bias * glm::perspective(1.0472f, 1.0f, 0.5f, 50.0f);
    const float resolution = 512.0f;
    const glm::vec3 point(0.3f, -0.2f, -6.0f);
    const glm::vec3 normal = glm::normalize(glm::vec3(0.4f, 0.2f, 1.0f));
    const glm::vec2 gradient = g::gsTangentPlaneGradient(map, point, normal, resolution);
    const auto project = [&](const glm::vec3& p) {
        const glm::vec4 clip = map * glm::vec4(p, 1.0f);
        return glm::vec3(clip) / clip.w;
    };
    const glm::vec3 origin = project(point);
    // Points of the plane several texels away: their depth must be the affine prediction (in double-free
    // float, to a few ulps of the depth).
    const glm::vec3 tangent = glm::normalize(glm::cross(normal, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 bitangent = glm::cross(normal, tangent);
    for (const glm::vec2 step : {glm::vec2(0.02f, 0.0f), glm::vec2(0.0f, 0.03f), glm::vec2(-0.05f, 0.04f)}) {
        const glm::vec3 there = project(point + step.x * tangent + step.y * bitangent);
        const glm::vec2 texels = (glm::vec2(there) - glm::vec2(origin)) * resolution;
        ASSERT_GT(glm::length(texels), 0.5f);
        EXPECT_NEAR(there.z, origin.z + glm::dot(texels, gradient), 2e-6f);
    }
}

TEST(VisibilityMathTest, NearerCorrectionDarkensAConcaveCreaseNoMoreThanEitherReference) {
    // Two planes meeting in a concave crease 1.2 texels to the fragment's right: beyond it the surface rises
    // towards the light (depth falls) past the fragment's own depth. The point gradient is the fragment's own
    // plane's.
    const TapPattern p = TapPattern::make(TapLayout::Grid, 4, 1.5f);
    const glm::vec2 own(3e-4f, 1e-4f);
    auto crease = [&](glm::vec2 o) {
        const float beyond = std::max(o.x - 1.2f, 0.0f);
        return 0.5f + glm::dot(o, own) - 4e-3f * beyond;
    };
    const Taps taps = sample(p, crease, {});
    const float receiver = crease({});
    const float point = pcfGsm(p, taps, receiver, own, g::GS_CORRECTION_POINT);
    const float average = pcfGsm(p, taps, receiver, own, g::GS_CORRECTION_AVERAGE);
    const float nearer = pcfGsm(p, taps, receiver, own, g::GS_CORRECTION_NEARER);
    EXPECT_LT(point, 1.0f);   // the taps beyond the crease fail under the point gradient...
    EXPECT_LT(average, 1.0f); // ...and some on the fragment's own side under the average's
    EXPECT_GE(nearer, std::max(point, average));
    // On a plane it is exact, like both references.
    auto plane = [&](glm::vec2 o) { return 0.5f + glm::dot(o, own); };
    const Taps flat = sample(p, plane, {});
    EXPECT_EQ(pcfGsm(p, flat, plane({}) - 1e-6f, own, g::GS_CORRECTION_NEARER), 1.0f);
}

TEST(VisibilityMathTest, EveryCorrectionKeepsAReceiverUnderASilhouetteInShadow) {
    // A receiver in the shadow of two casters, which the taps see on both sides of the nearer one's
    // silhouette: 0.40 left of x = 0.3, 0.46 right of it, 0.01 in front of the receiver. The taps'
    // least-squares gradient fits the jump; as a fuzzy width it lets the receiver through (terrain under a 1°
    // sun leaked there), so every correction's width is the fragment's own gradient.
    const TapPattern p = TapPattern::make(TapLayout::Grid, 4, 0.75f);
    const glm::vec2 own(1e-4f, 0.0f);
    auto casters = [](glm::vec2 o) { return o.x < 0.3f ? 0.40f : 0.46f; };
    const Taps taps = sample(p, casters, {});
    const glm::vec2 fit =
        g::gsLeastSquaresGradient(taps.depths, taps.offsets, taps.count, p.inverseCovariance);
    EXPECT_GT(pcfGsm(p, taps, 0.47f, fit, g::GS_CORRECTION_POINT), 0.1f);
    for (const int correction : {g::GS_CORRECTION_POINT, g::GS_CORRECTION_AVERAGE, g::GS_CORRECTION_QUADRATIC,
                                 g::GS_CORRECTION_NEARER}) {
        EXPECT_EQ(pcfGsm(p, taps, 0.47f, own, correction), 0.0f) << "correction " << correction;
    }
}

namespace {

float connected(const TapPattern& pattern, const Taps& taps, float receiverDepth, glm::vec2 gradient) {
    return g::gsPcfGsmConnectedVisibility(taps.depths, taps.offsets, pattern.nearestFirst.data(), taps.count,
                                          pattern.linkDistance, receiverDepth, gradient, 1.0f, kD24Step);
}

} // namespace

TEST(VisibilityMathTest, ConnectedTapsLightAConcaveCreaseEveryOtherCorrectionDarkens) {
    // A crease 0.6 texels right of the fragment whose far face rises (slope -6e-4 per texel against the
    // fragment's 3e-4) past the fragment's depth: every prediction through the fragment fails there, but the
    // stored depth runs on without a jump.
    for (const TapPattern& p :
         {TapPattern::make(TapLayout::Grid, 4, 1.5f), TapPattern::make(TapLayout::Grid, 5, 2.0f),
          TapPattern::make(TapLayout::Poisson, 16, 1.5f)}) {
        const glm::vec2 own(3e-4f, 1e-4f);
        auto crease = [&](glm::vec2 o) {
            return 0.5f + glm::dot(o, own) - 9e-4f * std::max(o.x - 0.6f, 0.0f);
        };
        const Taps taps = sample(p, crease, {});
        const float receiver = crease({}) - 1e-6f;
        EXPECT_LT(pcfGsm(p, taps, receiver, own, g::GS_CORRECTION_NEARER), 1.0f);
        EXPECT_EQ(connected(p, taps, receiver, own), 1.0f) << toString(p.layout);
    }
}

TEST(VisibilityMathTest, ConnectedTapsKeepAShadowsEdge) {
    // An occluder's edge 0.3 texels right of the fragment: beyond it the map jumps 0.01 nearer the light. The
    // jump joins nothing, so those taps stay shadowed exactly as under the point gradient; a fragment under
    // the occluder stays in shadow.
    const TapPattern p = TapPattern::make(TapLayout::Grid, 4, 1.5f);
    const glm::vec2 own(3e-4f, 1e-4f);
    auto edge = [&](glm::vec2 o) { return 0.5f + glm::dot(o, own) - (o.x > 0.3f ? 0.01f : 0.0f); };
    const Taps taps = sample(p, edge, {});
    const float receiver = 0.5f - 1e-6f;
    const float point = pcfGsm(p, taps, receiver, own, g::GS_CORRECTION_POINT);
    EXPECT_NEAR(point, 0.5f, 1e-6f);
    EXPECT_EQ(connected(p, taps, receiver, own), point);
    const Taps under = sample(p, edge, {3.0f, 0.0f});
    EXPECT_NEAR(connected(p, under, receiver + dot(glm::vec2(3.0f, 0.0f), own), own), 0.0f, 1e-6f);
    // A facing plane (zero gradient) with the same edge: still the same split, and nothing divides by zero.
    auto flatEdge = [](glm::vec2 o) { return o.x > 0.3f ? 0.49f : 0.5f; };
    EXPECT_NEAR(connected(p, sample(p, flatEdge, {}), receiver, {}), 0.5f, 1e-6f);
}

TEST(VisibilityMathTest, NoTapIsComparedDeeperThanTheFragment) {
    // Only what lies nearer the light than the fragment can occlude it. Two cases where a downhill prediction
    // meets a surface that is deeper than the fragment but nearer than the prediction: corrections that
    // follow the fragment's own gradient must see it lit (the fitted ones also bend their gradient to the
    // other surface, which the concave-crease tests cover).
    const TapPattern p = TapPattern::make(TapLayout::Grid, 4, 1.5f);
    const glm::vec2 steep(2e-3f, 0.0f);
    // A convex limb: the receiver falls away steeply and ends 0.8 texels to the right, where the map shows
    // the background 1e-3 behind the fragment, short of the 3e-3 the gradient extrapolates to.
    auto limb = [&](glm::vec2 o) { return o.x < 0.8f ? 0.5f + glm::dot(o, steep) : 0.501f; };
    // A mild concave crease whose far side rises, but stays deeper than the fragment.
    auto crease = [&](glm::vec2 o) {
        return 0.5f + glm::dot(o, steep) - 1.5e-3f * std::max(o.x - 0.8f, 0.0f);
    };
    for (const auto& surface :
         {std::function<float(glm::vec2)>(limb), std::function<float(glm::vec2)>(crease)}) {
        const Taps taps = sample(p, surface, {});
        for (const int correction : {g::GS_CORRECTION_POINT, g::GS_CORRECTION_NEARER}) {
            EXPECT_EQ(pcfGsm(p, taps, surface({}) - 1e-6f, steep, correction), 1.0f)
                << "correction " << correction;
        }
    }
}

TEST(TexelFootprintMathTest, OneTexelPerPixelIsOne) {
    EXPECT_FLOAT_EQ(g::gsTexelFootprintPixels(glm::vec2(1.0f, 0.0f), glm::vec2(0.0f, 1.0f)), 1.0f);
    // Rotation and mirroring do not change a texel's extent.
    const float c = std::cos(0.7f);
    const float s = std::sin(0.7f);
    EXPECT_NEAR(g::gsTexelFootprintPixels(glm::vec2(c, s), glm::vec2(s, -c)), 1.0f, 1e-6f);
}

TEST(TexelFootprintMathTest, IsTheLargestExtentOfATexelOnScreen) {
    // Two texels per pixel: a texel is half a pixel wide.
    EXPECT_FLOAT_EQ(g::gsTexelFootprintPixels(glm::vec2(2.0f, 0.0f), glm::vec2(0.0f, 2.0f)), 0.5f);
    // Stretched along y on screen (a receiver the light grazes): 0.1 texel per pixel there, so a texel spans
    // 10 pixels, however fine it is along x.
    EXPECT_FLOAT_EQ(g::gsTexelFootprintPixels(glm::vec2(4.0f, 0.0f), glm::vec2(0.0f, 0.1f)), 10.0f);
    // A shear: 1/sigma_min of [[1, 1], [0, 1]] is the golden ratio.
    EXPECT_NEAR(g::gsTexelFootprintPixels(glm::vec2(1.0f, 0.0f), glm::vec2(1.0f, 1.0f)),
                0.5f * (1.0f + std::sqrt(5.0f)), 1e-5f);
}

TEST(TexelFootprintMathTest, IsScaleInvariantAndFiniteAtTheExtremes) {
    for (const float scale : {1e-29f, 1e-12f, 1e12f, 1e30f}) {
        const float m = g::gsTexelFootprintPixels(glm::vec2(scale, 0.0f), glm::vec2(0.0f, 2.0f * scale));
        EXPECT_NEAR(m * scale, 1.0f, 1e-5f) << scale;
    }
}

TEST(TexelFootprintMathTest, SingularOrInvalidDerivativesAreUnbounded) {
    EXPECT_EQ(g::gsTexelFootprintPixels(glm::vec2(0.0f), glm::vec2(0.0f)), g::GS_FOOTPRINT_UNBOUNDED);
    // Both screen axes move along one line in the map: edge-on.
    EXPECT_EQ(g::gsTexelFootprintPixels(glm::vec2(1.0f, 2.0f), glm::vec2(2.0f, 4.0f)),
              g::GS_FOOTPRINT_UNBOUNDED);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(g::gsTexelFootprintPixels(glm::vec2(nan, 0.0f), glm::vec2(0.0f, 1.0f)),
              g::GS_FOOTPRINT_UNBOUNDED);
    EXPECT_EQ(g::gsTexelFootprintPixels(glm::vec2(inf, 0.0f), glm::vec2(0.0f, 1.0f)),
              g::GS_FOOTPRINT_UNBOUNDED);
}

TEST(PcssMathTest, PenumbraRadiusFollowsSimilarTriangles) {
    const float unlimited = 1e30f;
    // A sun of angular radius θ: (receiver - blocker) tan θ.
    const float tangent = std::tan(0.02f);
    EXPECT_NEAR(g::gsPcssRadius(5.0f, 3.0f, tangent, false, unlimited), 2.0f * tangent, 1e-7f);
    // A sphere of radius 0.1 two units from the blocker, one unit past it: 0.1 (3 - 2) / 2.
    EXPECT_NEAR(g::gsPcssRadius(3.0f, 2.0f, 0.1f, true, unlimited), 0.05f, 1e-7f);
    // The search: the blocker at the map's nearest distance bounds every penumbra the receiver can have.
    EXPECT_GT(g::gsPcssRadius(3.0f, 0.5f, 0.1f, true, unlimited),
              g::gsPcssRadius(3.0f, 2.0f, 0.1f, true, unlimited));
    EXPECT_EQ(g::gsPcssRadius(3.0f, 0.5f, 0.1f, true, 0.25f), 0.25f);
}

TEST(PcssMathTest, AZeroSizeLightOrNoBlockerInFrontGivesNoPenumbra) {
    EXPECT_EQ(g::gsPcssRadius(5.0f, 3.0f, 0.0f, false, 1e30f), 0.0f);
    EXPECT_EQ(g::gsPcssRadius(5.0f, 3.0f, 0.0f, true, 1e30f), 0.0f);
    EXPECT_EQ(g::gsPcssRadius(3.0f, 3.0f, 0.1f, true, 1e30f), 0.0f);
    EXPECT_EQ(g::gsPcssRadius(3.0f, 4.0f, 0.1f, false, 1e30f), 0.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(g::gsPcssRadius(nan, 1.0f, 0.1f, true, 1e30f), 0.0f);
    EXPECT_EQ(g::gsPcssRadius(3.0f, 1.0f, nan, true, 1e30f), 0.0f);
    // A blocker at the light itself (distance 0) stays finite, at the limit.
    EXPECT_EQ(g::gsPcssRadius(3.0f, 0.0f, 0.1f, true, 8.0f), 8.0f);
}

TEST(PcssMathTest, VogelTapsFillTheUnitDiskEvenly) {
    constexpr int kCount = 24;
    glm::vec2 mean(0.0f);
    int inner = 0;
    for (int i = 0; i < kCount; ++i) {
        const glm::vec2 tap = g::gsVogelTap(i, kCount, 0.7f);
        EXPECT_LE(glm::length(tap), 1.0f);
        mean += tap / float(kCount);
        inner += glm::length(tap) < std::sqrt(0.5f);
    }
    EXPECT_LT(glm::length(mean), 0.1f); // no side favoured
    EXPECT_EQ(inner, kCount / 2);       // half the taps in the inner half of the area
    // Turning the disk turns every tap.
    const glm::vec2 a = g::gsVogelTap(5, kCount, 0.0f);
    const glm::vec2 b = g::gsVogelTap(5, kCount, 1.0f);
    EXPECT_NEAR(glm::length(a), glm::length(b), 1e-6f);
    EXPECT_NEAR(std::atan2(b.y, b.x) - std::atan2(a.y, a.x), 1.0f, 1e-5f);
}
