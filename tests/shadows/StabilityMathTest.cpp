// Numerical stability of the shared visibility math at the extremes: finite, in [0,1], monotone in bias, and
// the float mirror (what the shader runs) against the same code in double precision.
#include <shadows/TapPattern.h>
#include <shadows/VisibilityMath.h>
#include <shadows/VisibilityMathDouble.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

using namespace shadows;
namespace f = shadows::glsl;
namespace d = shadows::glsl_double;

namespace {

constexpr float kDepthSteps[] = {0.0f, 1.0f / 16777215.0f, 1.0f / 65535.0f};
constexpr float kGradients[] = {0.0f, 1e-30f, 1e-12f, 1e-7f, 1e-4f, 1e-2f, 1.0f, 1e6f, 1e30f};
constexpr float kDepths[] = {0.0f, 1e-7f, 0.25f, 0.5f, 0.999999f, 1.0f};

bool unitRange(float v) {
    return std::isfinite(v) && v >= 0.0f && v <= 1.0f;
}

} // namespace

TEST(StabilityMathTest, FuzzyComparisonIsBoundedMonotoneAndMatchesDouble) {
    double worst = 0.0;
    for (const float step : kDepthSteps) {
        for (const float g : kGradients) {
            for (const float stored : kDepths) {
                float previous = -1.0f;
                // Receiver moving towards the light (more bias): visibility must never drop.
                for (int k = 0; k <= 40; ++k) {
                    const float receiver = stored + 1e-3f - static_cast<float>(k) * 5e-5f;
                    const float v = f::gsFuzzyVisibility(stored, receiver, g, 1.0f, step);
                    ASSERT_TRUE(unitRange(v)) << stored << " " << receiver << " " << g << " " << step;
                    ASSERT_GE(v, previous) << "not monotone in bias at g " << g;
                    previous = v;
                    const double exact = d::gsFuzzyVisibility(stored, receiver, g, 1.0, step);
                    worst = std::max(worst, std::abs(static_cast<double>(v) - exact));
                }
            }
        }
    }
    std::cout << "[ measured ] fuzzy comparison: max |float - double| = " << worst << "\n";
    // Measured 3e-8 (float rounding of diff / width + 1): the bound keeps a wide margin.
    EXPECT_LT(worst, 1e-6);
}

TEST(StabilityMathTest, PcfOverGsmCorrectionsAreBoundedAtExtremeSlopes) {
    const TapPattern pattern = TapPattern::make(TapLayout::Grid, 5, 2.0f);
    float fitRows[6 * f::GS_MAX_TAPS];
    double fitRowsDouble[6 * f::GS_MAX_TAPS];
    std::copy(pattern.quadraticFitRows.begin(), pattern.quadraticFitRows.end(), fitRows);
    std::copy(pattern.quadraticFitRows.begin(), pattern.quadraticFitRows.end(), fitRowsDouble);
    double worst = 0.0;
    for (const float slope : {0.0f, 1e-9f, 1e-5f, 1e-3f, 0.1f, 10.0f}) {
        for (const float base : {0.0f, 0.5f, 1.0f}) {
            float depths[f::GS_MAX_TAPS];
            glm::vec2 offsets[f::GS_MAX_TAPS];
            double depthsDouble[f::GS_MAX_TAPS];
            glm::dvec2 offsetsDouble[f::GS_MAX_TAPS];
            const int n = static_cast<int>(pattern.offsets.size());
            for (int i = 0; i < n; ++i) {
                offsets[i] = pattern.offsets[static_cast<std::size_t>(i)];
                offsetsDouble[i] = glm::dvec2(offsets[i]);
                depths[i] = glm::clamp(base + slope * offsets[i].x, 0.0f, 1.0f);
                depthsDouble[i] = depths[i];
            }
            for (const int correction : {f::GS_CORRECTION_NONE, f::GS_CORRECTION_POINT,
                                         f::GS_CORRECTION_AVERAGE, f::GS_CORRECTION_QUADRATIC}) {
                float previous = -1.0f;
                for (int k = 0; k <= 20; ++k) {
                    const float receiver = base + 1e-3f - static_cast<float>(k) * 1e-4f;
                    const float v = f::gsPcfGsmVisibility(
                        depths, offsets, n, receiver, glm::vec2(slope, 0.0f), correction,
                        pattern.inverseCovariance, fitRows, 1.0f, 1.0f / 16777215.0f);
                    ASSERT_TRUE(unitRange(v)) << "correction " << correction << " slope " << slope;
                    ASSERT_GE(v, previous - 1e-6f) << "correction " << correction << " not monotone in bias";
                    previous = v;
                    const double exact = d::gsPcfGsmVisibility(
                        depthsDouble, offsetsDouble, n, receiver, glm::dvec2(slope, 0.0), correction,
                        glm::dmat2(pattern.inverseCovariance), fitRowsDouble, 1.0, 1.0 / 16777215.0);
                    worst = std::max(worst, std::abs(static_cast<double>(v) - exact));
                }
            }
            float previous = -1.0f;
            for (int k = 0; k <= 20; ++k) {
                const float receiver = base + 1e-3f - static_cast<float>(k) * 1e-4f;
                const float v = f::gsPcfGsmConnectedVisibility(
                    depths, offsets, pattern.nearestFirst.data(), n, pattern.linkDistance, receiver,
                    glm::vec2(slope, 0.0f), 1.0f, 1.0f / 16777215.0f);
                ASSERT_TRUE(unitRange(v)) << "connected, slope " << slope;
                ASSERT_GE(v, previous - 1e-6f) << "connected: not monotone in bias";
                previous = v;
                const double exact =
                    d::gsPcfGsmConnectedVisibility(depthsDouble, offsetsDouble, pattern.nearestFirst.data(),
                                                   n, static_cast<double>(pattern.linkDistance), receiver,
                                                   glm::dvec2(slope, 0.0), 1.0, 1.0 / 16777215.0);
                worst = std::max(worst, std::abs(static_cast<double>(v) - exact));
            }
        }
    }
    std::cout << "[ measured ] PCF over GSM: max |float - double| = " << worst << "\n";
    // Measured 0.010: the least-squares and quadric fits amplify float rounding of depths at slope 10 per
    // texel.
    EXPECT_LT(worst, 0.02);
}

TEST(StabilityMathTest, FilteredBoundsAreBoundedAndMonotoneInDepth) {
    double worstMsm = 0.0;
    for (const float z1 : {0.0f, 0.3f, 0.999f}) {
        for (const float weight : {0.0f, 0.5f, 1.0f}) {
            const glm::vec4 moments = weight * f::gsMsmMoments(z1) + (1.0f - weight) * f::gsMsmMoments(0.8f);
            const glm::vec2 vsmMoments(moments.x, moments.y);
            float previousVsm = 2.0f;
            float previousMsm = 2.0f;
            for (int k = 0; k <= 50; ++k) {
                const float receiver = static_cast<float>(k) / 50.0f;
                const float vsm = f::gsChebyshevVisibility(vsmMoments, receiver, 1e-6f, 0.2f);
                const float msm = f::gsMsmVisibility(moments, receiver, 3e-5f);
                ASSERT_TRUE(unitRange(vsm) && unitRange(msm)) << z1 << " " << weight << " " << receiver;
                // Deeper receivers are never more visible.
                ASSERT_LE(vsm, previousVsm + 1e-6f);
                ASSERT_LE(msm, previousMsm + 2e-3f) << z1 << " " << weight << " " << receiver;
                previousVsm = vsm;
                previousMsm = msm;
                worstMsm =
                    std::max(worstMsm, std::abs(static_cast<double>(msm) -
                                                d::gsMsmVisibility(glm::dvec4(moments), receiver, 3e-5)));
            }
        }
    }
    std::cout << "[ measured ] MSM: max |float - double| = " << worstMsm << "\n";
    // Measured 4.6e-4: the Cholesky solve of nearly singular Hankel matrices in float.
    EXPECT_LT(worstMsm, 0.002);
}

TEST(StabilityMathTest, ReceiverPlaneStaysFiniteForEveryJacobian) {
    const float tiny = std::numeric_limits<float>::denorm_min();
    const float huge = std::numeric_limits<float>::max();
    const float inf = std::numeric_limits<float>::infinity();
    for (const float a : {0.0f, tiny, 1e-20f, 1.0f, 1e20f, huge}) {
        for (const float b : {0.0f, tiny, 1.0f, huge, inf}) {
            const glm::vec2 g = f::gsReceiverPlaneGradient({a, b}, {b, a}, 1.0f, -1.0f);
            EXPECT_TRUE(std::isfinite(g.x) && std::isfinite(g.y)) << a << " " << b;
            const float depth = f::gsReceiverPlaneTapDepth(0.5f, {0.5f, -0.5f}, g, true);
            EXPECT_TRUE(std::isfinite(depth) || std::isinf(g.x)) << a << " " << b;
        }
    }
}
