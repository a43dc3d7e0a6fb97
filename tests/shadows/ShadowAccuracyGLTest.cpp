// Accuracy of every technique against analytic ground truth (a box on a plane), and the concave-neck ordering
// of the GSM multisampling reference (Fig. 4.2.5) on the knob. Thresholds come from measured values on Mesa
// llvmpipe (deterministic) with margin; see the table below.
#include "ShadowMeasurement.h"

#include <content/GltfLoader.h>
#include <engine/Primitives.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace shadows;

namespace {

// The analytic scene: a 2-unit box standing on a large plane, sun at 40° elevation.
const glm::vec3 kBoxMin(-1.0f, 0.0f, -1.0f);
const glm::vec3 kBoxMax(1.0f, 2.0f, 1.0f);

glm::vec3 sunDirection() {
    const float elevation = glm::radians(40.0f);
    const float azimuth = glm::radians(30.0f);
    const glm::vec3 from(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::cos(azimuth));
    return -from;
}

engine::Scene boxOnPlane(engine::EntityId& camera) {
    engine::Scene scene;
    const auto ground = scene.create("ground");
    scene.entity(ground).mesh = engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::plane(24.0f, 1))};
    const auto box = scene.create("box");
    scene.entity(box).mesh = engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::cube(2.0f))};
    scene.entity(box).transform.translation = {0.0f, 1.0f, 0.0f};
    const auto sun = scene.create("sun");
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).transform = engine::Transform::lookAt(-10.0f * sunDirection(), {0, 0, 0});
    camera = scene.create("camera");
    scene.entity(camera).camera = engine::CameraComponent{};
    scene.entity(camera).transform = engine::Transform::lookAt({-2.0f, 6.0f, -7.0f}, {0.5f, 0.5f, 1.5f});
    return scene;
}

/// Slab test: does the ray from `origin` towards the light hit the box?
bool boxOccludes(const glm::vec3& origin, const glm::vec3& toLight) {
    float enter = 1e-4f;
    float exit = 1e30f;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(toLight[axis]) < 1e-12f) {
            if (origin[axis] < kBoxMin[axis] || origin[axis] > kBoxMax[axis]) {
                return false;
            }
            continue;
        }
        float t0 = (kBoxMin[axis] - origin[axis]) / toLight[axis];
        float t1 = (kBoxMax[axis] - origin[axis]) / toLight[axis];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return enter < exit;
}

/// Classifies lit/shadowed receivers facing the light, away from shadow edges by `band` world units.
ShadowErrors measureBoxScene(const ShadowMeasurement& m, float band) {
    const glm::vec3 toLight = -sunDirection();
    // Two directions across the light, to probe the neighbourhood of each receiver for a nearby shadow edge.
    const glm::vec3 across1 = glm::normalize(glm::cross(toLight, glm::vec3(0, 1, 0.3f)));
    const glm::vec3 across2 = glm::cross(toLight, across1);
    ShadowErrors errors;
    for (std::size_t i = 0; i < m.visibility.size(); ++i) {
        if (m.position[i].w < 0.5f || glm::dot(m.normal[i], toLight) < 0.1f) {
            continue; // background, or a surface not facing the light (unlit by shading anyway)
        }
        const glm::vec3 p(m.position[i]);
        const bool shadowed = boxOccludes(p, toLight);
        bool interior = true;
        for (const glm::vec3 offset : {across1, -across1, across2, -across2}) {
            interior = interior && boxOccludes(p + band * offset, toLight) == shadowed;
        }
        if (!interior) {
            continue;
        }
        if (shadowed) {
            ++errors.shadowedPixels;
            errors.leak += m.visibility[i] > 0.5f;
        } else {
            ++errors.litPixels;
            errors.acne += m.visibility[i] < 0.5f;
            errors.darkeningSum += 1.0 - static_cast<double>(m.visibility[i]);
        }
    }
    return errors;
}

struct AccuracyCase {
    const char* name;
    ShadowTechnique technique;
    DepthFormat format;
    float constantBias;
    double maxAcne;
    double maxLeak;
    double maxDarkening;
};

// Thresholds: the values measured on llvmpipe (printed by the test as "[ measured ]") with margin. Hard
// comparisons with a tiny bias are expected to show acne and naive PCF over GSM to darken (that is what the
// other techniques fix); their thresholds pin that behaviour down too.
const AccuracyCase kAccuracy[] = {
    // name, technique, format, constant bias (world), max acne, max leak, max darkening
    {"hardTinyBias", ShadowTechnique::HardCompare, DepthFormat::D24, 0.002f, 0.55, 0.005, 0.55},
    {"hardLargeBias", ShadowTechnique::HardCompare, DepthFormat::D24, 0.05f, 0.005, 0.005, 0.005},
    {"slopeScaled", ShadowTechnique::SlopeScaledBias, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.005},
    {"hardwarePcf", ShadowTechnique::HardwarePcf, DepthFormat::D24, 0.05f, 0.005, 0.005, 0.005},
    {"pcf", ShadowTechnique::Pcf, DepthFormat::D24, 0.05f, 0.005, 0.005, 0.25},
    {"gsm", ShadowTechnique::Gsm, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.005},
    {"pcfGsmNaive", ShadowTechnique::PcfGsmNaive, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.45},
    {"pcfGsmPoint", ShadowTechnique::PcfGsmPointGradient, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.002},
    {"pcfGsmAverage", ShadowTechnique::PcfGsmAverageGradient, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.002},
    {"pcfGsmQuadratic", ShadowTechnique::PcfGsmQuadratic, DepthFormat::D24, 0.002f, 0.003, 0.005, 0.003},
    {"receiverPlane", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.005},
    {"normalOffset", ShadowTechnique::NormalOffset, DepthFormat::D24, 0.002f, 0.005, 0.005, 0.005},
    {"pcfGsmAverageD16", ShadowTechnique::PcfGsmAverageGradient, DepthFormat::D16, 0.002f, 0.005, 0.005, 0.002},
    {"pcfGsmAverageD32F", ShadowTechnique::PcfGsmAverageGradient, DepthFormat::D32F, 0.002f, 0.005, 0.005, 0.002},
};

class ShadowAccuracyGLTest : public testing::TestWithParam<AccuracyCase> {};

} // namespace

TEST_P(ShadowAccuracyGLTest, AcneAndLeakStayUnderMeasuredThresholds) {
    const AccuracyCase& c = GetParam();
    engine::EntityId camera = engine::kNoEntity;
    const engine::Scene scene = boxOnPlane(camera);
    ShadowSettings settings;
    settings.technique = c.technique;
    settings.depthFormat = c.format;
    settings.constantBias = c.constantBias;
    settings.resolution = 1024;
    const ShadowMeasurement m = ShadowMeasurement::render(scene, camera, settings, {320, 240});
    ASSERT_GT(m.texelWorldSize, 0.0f);
    const ShadowErrors errors = measureBoxScene(m, 3.0f * m.texelWorldSize + 0.02f);
    std::cout << "[ measured ] " << c.name << ": acne " << errors.acneRate() << " of " << errors.litPixels
              << " lit, leak " << errors.leakRate() << " of " << errors.shadowedPixels << " shadowed, darkening "
              << errors.darkening() << "\n";
    EXPECT_GT(errors.litPixels, 10000u);
    EXPECT_GT(errors.shadowedPixels, 2000u);
    EXPECT_LE(errors.acneRate(), c.maxAcne);
    EXPECT_LE(errors.leakRate(), c.maxLeak);
    EXPECT_LE(errors.darkening(), c.maxDarkening);
}

TEST(ShadowReproductionGLTest, NaivePcfOverGsmDarkensLitSurfacesByAboutAHalf) {
    // GSM multisampling reference, Fig. 4.2.3: uncorrected taps lose roughly half the light on lit surfaces.
    engine::EntityId camera = engine::kNoEntity;
    const engine::Scene scene = boxOnPlane(camera);
    ShadowSettings settings;
    settings.technique = ShadowTechnique::PcfGsmNaive;
    settings.pcfTaps = 6;
    settings.pcfRadius = 2.5f;
    settings.resolution = 1024;
    const ShadowMeasurement m = ShadowMeasurement::render(scene, camera, settings, {320, 240});
    const ShadowErrors errors = measureBoxScene(m, 4.0f * m.texelWorldSize + 0.02f);
    std::cout << "[ measured ] naive 6x6 darkening " << errors.darkening() << "\n";
    EXPECT_GT(errors.darkening(), 0.3);
    EXPECT_LT(errors.darkening(), 0.6);
}

INSTANTIATE_TEST_SUITE_P(Techniques, ShadowAccuracyGLTest, testing::ValuesIn(kAccuracy),
                         [](const auto& test) { return std::string(test.param.name); });
