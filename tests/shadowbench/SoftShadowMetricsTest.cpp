// The soft-shadow metrics on synthetic penumbrae of known widths: RMSE over the penumbra mask, false-lit and
// false-shadow pixels outside it, and the penumbra-width error along the truth's gradient.
#include <shadowbench/SoftShadowMetrics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace shadowbench;

namespace {

constexpr glm::ivec2 kSize{96, 32};

/// Visibility rising linearly along x from 0 at `dark` to 1 at `bright` (pixel centres), every pixel a
/// receiver.
std::vector<float> ramp(float dark, float bright) {
    std::vector<float> image(static_cast<std::size_t>(kSize.x * kSize.y));
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            const float centre = static_cast<float>(x) + 0.5f;
            image[static_cast<std::size_t>(y * kSize.x + x)] =
                bright > dark ? std::clamp((centre - dark) / (bright - dark), 0.0f, 1.0f)
                              : float(centre >= dark);
        }
    }
    return image;
}

const std::vector<PixelClass> kReceivers(static_cast<std::size_t>(kSize.x* kSize.y), PixelClass::Lit);

TEST(PenumbraWidth, IsTheDistanceBetweenTheTenthAndNinetiethIsoLines) {
    const std::vector<float> image = ramp(20.0f, 40.0f);
    // 0.1 at x = 22, 0.9 at x = 38.
    EXPECT_NEAR(penumbraWidth(kSize, kReceivers, image, {30.0f, 16.0f}, {1.0f, 0.0f}, 64.0f), 16.0f, 0.05f);
    // Along a line 60° off the gradient the iso-lines lie twice as far apart.
    EXPECT_NEAR(penumbraWidth(kSize, kReceivers, image, {30.0f, 16.0f}, {0.5f, 0.8660254f}, 64.0f), 32.0f,
                0.2f);
    // Either way along the line.
    EXPECT_NEAR(penumbraWidth(kSize, kReceivers, image, {30.0f, 16.0f}, {-1.0f, 0.0f}, 64.0f), 16.0f, 0.05f);
    // No edge within reach.
    EXPECT_LT(penumbraWidth(kSize, kReceivers, image, {80.0f, 16.0f}, {1.0f, 0.0f}, 8.0f), 0.0f);
}

TEST(PenumbraWidth, EndsWhereTheReceiversDo) {
    const std::vector<float> image = ramp(20.0f, 40.0f);
    std::vector<PixelClass> classes = kReceivers;
    for (int y = 0; y < kSize.y; ++y) {
        classes[static_cast<std::size_t>(y * kSize.x + 36)] = PixelClass::Ignored; // before the 0.9 line
    }
    EXPECT_LT(penumbraWidth(kSize, classes, image, {30.0f, 16.0f}, {1.0f, 0.0f}, 64.0f), 0.0f);
}

TEST(SoftShadowMetrics, TheTruthItselfHasNoError) {
    const std::vector<float> truth = ramp(20.0f, 40.0f);
    const SoftShadowMetrics metrics = softShadowMetrics(kSize, kReceivers, truth, truth);
    EXPECT_GT(metrics.penumbraPixels, 0u);
    EXPECT_EQ(metrics.penumbraRmse, 0.0);
    EXPECT_EQ(metrics.falseLit, 0u);
    EXPECT_EQ(metrics.falseShadow, 0u);
    EXPECT_GT(metrics.widthSamples, 0u);
    EXPECT_NEAR(metrics.widthErrorMedian, 0.0, 1e-3);
    EXPECT_NEAR(metrics.widthErrorP95, 0.0, 1e-3);
}

TEST(SoftShadowMetrics, ANarrowerPenumbraIsOffByTheWidthsDifference) {
    const std::vector<float> truth = ramp(20.0f, 40.0f);  // 16 px from 0.1 to 0.9
    const std::vector<float> narrow = ramp(25.0f, 35.0f); // 8 px
    const std::vector<float> hard = ramp(30.0f, 30.0f);   // a step: 0.8 px between the pixel centres
    const SoftShadowMetrics soft = softShadowMetrics(kSize, kReceivers, truth, narrow);
    EXPECT_NEAR(soft.widthErrorMedian, 8.0, 0.1);
    EXPECT_NEAR(soft.widthErrorP95, 8.0, 0.1);
    EXPECT_GT(soft.penumbraRmse, 0.05);
    const SoftShadowMetrics step = softShadowMetrics(kSize, kReceivers, truth, hard);
    EXPECT_NEAR(step.widthErrorMedian, 15.2, 0.1);
    EXPECT_GT(step.penumbraRmse, soft.penumbraRmse);
    // Penumbrae narrower than the minimum width are not measured.
    EXPECT_EQ(softShadowMetrics(kSize, kReceivers, truth, narrow, 20.0f).widthSamples, 0u);
}

TEST(SoftShadowMetrics, WidthRatioSaysWhetherPenumbraeAreTooWideOrTooNarrow) {
    const std::vector<float> truth = ramp(20.0f, 40.0f);
    EXPECT_NEAR(softShadowMetrics(kSize, kReceivers, truth, ramp(25.0f, 35.0f)).widthRatioMedian, 0.5, 0.02);
    EXPECT_NEAR(softShadowMetrics(kSize, kReceivers, truth, truth).widthRatioMedian, 1.0, 1e-3);
}

TEST(SoftShadowMetrics, SeamJumpIsTheWidthChangeBetweenMapsBeyondTheTruths) {
    // The upper half reads map 0 and renders the truth; the lower half reads map 1 and a penumbra 3.2 px
    // narrower (ramp 22-38: 12.8 px from 0.1 to 0.9).
    const std::vector<float> truth = ramp(20.0f, 40.0f);
    std::vector<float> rendered = truth;
    const std::vector<float> narrower = ramp(22.0f, 38.0f);
    std::vector<float> slots(truth.size(), 0.0f);
    for (std::size_t i = static_cast<std::size_t>(16 * kSize.x); i < truth.size(); ++i) {
        rendered[i] = narrower[i];
        slots[i] = 1.0f;
    }
    SoftShadowMetrics metrics = softShadowMetrics(kSize, kReceivers, truth, rendered);
    seamWidthJumps(kSize, slots, metrics);
    EXPECT_GT(metrics.seamPairs, 0u);
    EXPECT_NEAR(metrics.seamJumpMedian, 3.2, 0.1);
    EXPECT_NEAR(metrics.seamJumpMax, 3.2, 0.1);
    // The same change within one map is no seam's; pixels that read no map pair with none.
    SoftShadowMetrics oneMap = softShadowMetrics(kSize, kReceivers, truth, rendered);
    seamWidthJumps(kSize, std::vector<float>(truth.size(), 0.0f), oneMap);
    EXPECT_EQ(oneMap.seamPairs, 0u);
    SoftShadowMetrics unmapped = softShadowMetrics(kSize, kReceivers, truth, rendered);
    seamWidthJumps(kSize, std::vector<float>(truth.size(), -1.0f), unmapped);
    EXPECT_EQ(unmapped.seamPairs, 0u);
    // A penumbra as the truth's on both sides has no jump.
    SoftShadowMetrics exact = softShadowMetrics(kSize, kReceivers, truth, truth);
    seamWidthJumps(kSize, slots, exact);
    EXPECT_GT(exact.seamPairs, 0u);
    EXPECT_NEAR(exact.seamJumpMax, 0.0, 1e-3);
}

TEST(SoftShadowMetrics, CountsFalseLitUmbraAndFalseShadowOutsideTheMask) {
    const std::vector<float> truth = ramp(40.0f, 50.0f);
    std::vector<float> rendered = truth;
    rendered[static_cast<std::size_t>(5 * kSize.x + 10)] = 1.0f; // in the umbra
    rendered[static_cast<std::size_t>(5 * kSize.x + 38)] = 1.0f; // within the mask, 2 px from the penumbra
    rendered[static_cast<std::size_t>(9 * kSize.x + 80)] = 0.0f; // on the lit side
    const SoftShadowMetrics metrics = softShadowMetrics(kSize, kReceivers, truth, rendered);
    EXPECT_EQ(metrics.falseLit, 1u);
    EXPECT_EQ(metrics.falseShadow, 1u);
    // The mask: x from 40 to 50 with truth strictly inside (0.02, 0.98), dilated by 2 pixels.
    EXPECT_EQ(metrics.penumbraPixels, static_cast<std::size_t>(14 * kSize.y));
    EXPECT_EQ(metrics.umbraPixels + metrics.litPixels + metrics.penumbraPixels,
              static_cast<std::size_t>(kSize.x * kSize.y));
}

} // namespace
