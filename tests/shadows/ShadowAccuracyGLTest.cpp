// Accuracy of every technique against analytic ground truth (a box on a plane), and the concave-neck ordering
// of the GSM multisampling reference (Fig. 4.2.5) on the knob. Thresholds come from measured values on Mesa
// llvmpipe (deterministic) with margin; see the table below.
#include "ShadowMeasurement.h"

#include "../support/TestScenes.h"

#include <content/GltfLoader.h>
#include <shadows/ShadowTechniqueTraits.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
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
    engine::Scene scene = testsupport::boxOnPlane(24.0f, 2.0f);
    const auto sun = scene.create("sun");
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).transform = engine::Transform::lookAt(-10.0f * sunDirection(), {0, 0, 0});
    camera = scene.create("camera");
    scene.entity(camera).camera = engine::CameraComponent{};
    scene.entity(camera).transform = engine::Transform::lookAt({-2.0f, 6.0f, -7.0f}, {0.5f, 0.5f, 1.5f});
    return scene;
}

/// Does the ray from `origin` towards the light hit the box?
bool boxOccludes(const glm::vec3& origin, const glm::vec3& toLight) {
    const testsupport::BoxCrossing crossing = testsupport::crossBox(origin, toLight, kBoxMin, kBoxMax, 1e-4f);
    return crossing.enter < crossing.exit;
}

constexpr int kResolution = 1024;

/// Receivers in view whose visibility the map decides: the map covers where shadows can fall, and receivers
/// beyond it or in its lit border are lit without reading it, whatever the technique (counting them would
/// dilute every rate).
bool mapped(const ShadowMeasurement& m, const glm::vec3& p) {
    const LightProjection& map = m.projections.front();
    const glm::vec4 s = map.worldToShadow * glm::vec4(p, 1.0f);
    const float inner = 0.5f - map.litBorderTexels / static_cast<float>(kResolution);
    return std::abs(s.x / s.w - 0.5f) <= inner && std::abs(s.y / s.w - 0.5f) <= inner;
}

/// Classifies lit/shadowed receivers facing the light, inside the map, away from shadow edges by `band` world
/// units.
ShadowErrors measureBoxScene(const ShadowMeasurement& m, float band) {
    const glm::vec3 toLight = -sunDirection();
    const auto occluded = [&](const glm::vec3& p) { return boxOccludes(p, toLight); };
    ShadowErrors errors;
    for (std::size_t i = 0; i < m.visibility.size(); ++i) {
        if (m.position[i].w < 0.5f || glm::dot(m.normal[i], toLight) < 0.1f) {
            continue; // background, or a surface not facing the light (unlit by shading anyway)
        }
        const glm::vec3 p(m.position[i]);
        if (!mapped(m, p)) {
            continue;
        }
        if (awayFromShadowEdges(p, toLight, band, occluded)) {
            errors.add(occluded(p), m.visibility[i]);
        }
    }
    return errors;
}

struct AccuracyCase {
    const char* name;
    ShadowTechnique technique;
    DepthFormat format;
    float constantBiasTexels;
    float depthBiasSteps;
    bool floorReceiverDepth;
    double maxAcne;
    double maxLeak;
    double maxDarkening;
};

constexpr float kDefaultSteps = ShadowSettings{}.depthBiasSteps;

// Thresholds: the values measured on llvmpipe (printed by the test as "[ measured ]") with margin, and no
// looser than the floor of the defaults (acne and leak 0.05 %, darkening 0.5 %) where the measurement is
// below it. Every technique at its defaults first; then the naive reproductions, whose thresholds pin down
// the acne and darkening the others fix.
const AccuracyCase kAccuracy[] = {
    // name, technique, format, constant bias (texels), depth bias (steps), floor reference, max acne, max
    // leak,
    // max darkening
    {"hardLargeBias", ShadowTechnique::HardCompare, DepthFormat::D24, 8.0f, 0.0f, false, 0.0005, 0.0005,
     0.005},
    {"slopeScaled", ShadowTechnique::SlopeScaledBias, DepthFormat::D24, 0.0f, kDefaultSteps, false, 0.0005,
     0.0005, 0.005},
    {"hardwarePcf", ShadowTechnique::HardwarePcf, DepthFormat::D24, 0.0f, kDefaultSteps, false, 0.0005,
     0.0005, 0.005},
    {"hardwarePcfD16", ShadowTechnique::HardwarePcf, DepthFormat::D16, 0.0f, kDefaultSteps, false, 0.0005,
     0.0005, 0.005},
    {"pcf", ShadowTechnique::Pcf, DepthFormat::D24, 0.0f, kDefaultSteps, false, 0.0005, 0.0005, 0.005},
    {"gsm", ShadowTechnique::Gsm, DepthFormat::D24, 0.0f, kDefaultSteps, false, 0.0005, 0.0005, 0.005},
    {"pcfGsmPoint", ShadowTechnique::PcfGsmPointGradient, DepthFormat::D24, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.0005},
    {"pcfGsmAverage", ShadowTechnique::PcfGsmAverageGradient, DepthFormat::D24, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.0005},
    {"pcfGsmAverageD16", ShadowTechnique::PcfGsmAverageGradient, DepthFormat::D16, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.0005},
    {"pcfGsmAverageD32F", ShadowTechnique::PcfGsmAverageGradient, DepthFormat::D32F, 0.0f, kDefaultSteps,
     false, 0.0005, 0.0005, 0.0005},
    {"pcfGsmQuadratic", ShadowTechnique::PcfGsmQuadratic, DepthFormat::D24, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.0005},
    {"pcfGsmConnected", ShadowTechnique::PcfGsmConnected, DepthFormat::D24, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.0005},
    {"receiverPlane", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D24, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.005},
    {"receiverPlaneD16", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D16, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.005},
    {"normalOffset", ShadowTechnique::NormalOffset, DepthFormat::D24, 0.0f, kDefaultSteps, false, 0.0005,
     0.0005, 0.005},
    {"adaptiveBias", ShadowTechnique::AdaptiveBias, DepthFormat::D24, 0.0f, kDefaultSteps, false, 0.0005,
     0.0005, 0.005},
    {"pcfAdaptiveBias", ShadowTechnique::PcfAdaptiveBias, DepthFormat::D24, 0.0f, kDefaultSteps, false,
     0.0005, 0.0005, 0.005},
    // The naive reproductions. Without any bias a plain comparison self-shadows about half of every lit
    // surface, and PCF over GSM compared at the fragment's depth darkens about as much...
    {"hardNoBias", ShadowTechnique::HardCompare, DepthFormat::D24, 0.0f, 0.0f, false, 0.55, 0.005, 0.55},
    {"hardD16NoBias", ShadowTechnique::HardCompare, DepthFormat::D16, 0.0f, 0.0f, false, 0.55, 0.005, 0.55},
    {"pcfGsmNaive", ShadowTechnique::PcfGsmNaive, DepthFormat::D24, 0.0f, 0.0f, false, 0.005, 0.005, 0.45},
    // ...the receiver plane without depth bias removes most of it, but the comparison rounds the reference to
    // the format (bias reference: "SampleCmp must indeed be converting the supplied comparison value to the
    // texture format")...
    {"receiverPlaneD16NoDepthBias", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D16, 0.0f, 0.0f, false,
     0.30, 0.005, 0.30},
    {"receiverPlaneD24NoDepthBias", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D24, 0.0f, 0.0f, false,
     0.06, 0.005, 0.08},
    // ...and flooring the reference to the format's step removes that rounding acne entirely for D16. A D24
    // step (6e-8) is one float32 ulp at depth 0.5, so the floor computed in float barely helps there (5.1 %
    // acne without it, 4.6 % with it).
    {"receiverPlaneD16Floor", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D16, 0.0f, 0.0f, true, 0.002,
     0.005, 0.002},
    {"receiverPlaneD24Floor", ShadowTechnique::ReceiverPlaneBias, DepthFormat::D24, 0.0f, 0.0f, true, 0.06,
     0.005, 0.06},
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
    settings.constantBiasTexels = c.constantBiasTexels;
    settings.depthBiasSteps = c.depthBiasSteps;
    settings.floorReceiverDepth = c.floorReceiverDepth;
    settings.resolution = kResolution;
    const ShadowMeasurement m = ShadowMeasurement::render(scene, camera, settings, {320, 240});
    ASSERT_GT(m.texelWorldSize, 0.0f);
    const ShadowErrors errors = measureBoxScene(m, 3.0f * m.texelWorldSize + 0.02f);
    std::cout << "[ measured ] " << c.name << ": acne " << errors.acneRate() << " of " << errors.litPixels
              << " lit, leak " << errors.leakRate() << " of " << errors.shadowedPixels
              << " shadowed, darkening " << errors.darkening() << "\n";
    EXPECT_GT(errors.litPixels, 2000u); // the box's top and sides and the ground under its footprint: 2594
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
    settings.resolution = kResolution;
    const ShadowMeasurement m = ShadowMeasurement::render(scene, camera, settings, {320, 240});
    const ShadowErrors errors = measureBoxScene(m, 4.0f * m.texelWorldSize + 0.02f);
    std::cout << "[ measured ] naive 6x6 darkening " << errors.darkening() << "\n";
    EXPECT_GT(errors.darkening(), 0.3);
    EXPECT_LT(errors.darkening(), 0.6);
}

namespace {

/// Renders `scene` under every non-naive technique at its defaults and hands each measurement to `check`.
template <typename Check>
void forEachTechniqueAtItsDefaults(const engine::Scene& scene, engine::EntityId camera, Check check) {
    for (const ShadowTechniqueTraits& traits : techniqueTable()) {
        if (traits.naive) {
            continue;
        }
        ShadowSettings settings;
        settings.technique = traits.technique;
        settings.resolution = kResolution;
        check(traits, ShadowMeasurement::render(scene, camera, settings, {320, 240}));
    }
}

} // namespace

TEST(ShadowFacetGLTest, BiasesFollowTheFacetNotItsSmoothedNormals) {
    // Real models' smoothed vertex normals can lean far off their facets (up to 45° and more on the at-at
    // corpus model). Lean the box scene's normals 60° towards the light, past the camera's side of the
    // ground, and every non-naive technique must still keep the ground's lit and shadowed pixels right at its
    // defaults: the depths in the map come from facets, so biases must follow the facet.
    engine::EntityId camera = engine::kNoEntity;
    engine::Scene scene = boxOnPlane(camera);
    const glm::vec3 toLight = -sunDirection();
    const glm::vec3 lean =
        glm::normalize(glm::cross(glm::cross(glm::vec3(0, 1, 0), toLight), glm::vec3(0, 1, 0)));
    const glm::vec3 leaned = glm::normalize(std::cos(glm::radians(60.0f)) * glm::vec3(0, 1, 0) +
                                            std::sin(glm::radians(60.0f)) * lean);
    engine::EntityId ground = engine::kNoEntity;
    scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        ground = entity.name == "ground" ? id : ground;
    });
    ASSERT_NE(ground, engine::kNoEntity);
    auto mesh = std::make_shared<engine::MeshData>(*scene.entity(ground).mesh->mesh);
    std::fill(mesh->normals.begin(), mesh->normals.end(), leaned);
    scene.entity(ground).mesh->mesh = mesh;
    forEachTechniqueAtItsDefaults(
        scene, camera, [&](const ShadowTechniqueTraits& traits, const ShadowMeasurement& m) {
            const float band = 3.0f * m.texelWorldSize + 0.02f;
            ShadowErrors errors;
            for (std::size_t i = 0; i < m.visibility.size(); ++i) {
                const glm::vec3 p(m.position[i]);
                if (m.position[i].w < 0.5f || std::abs(p.y) > 1e-3f || !mapped(m, p)) {
                    continue; // only the ground, whose facet faces straight up
                }
                const auto occluded = [&](const glm::vec3& q) { return boxOccludes(q, toLight); };
                if (awayFromShadowEdges(p, toLight, band, occluded)) {
                    errors.add(occluded(p), m.visibility[i]);
                }
            }
            std::cout << "[ measured ] " << traits.name << ": acne " << errors.acneRate() << " of "
                      << errors.litPixels << " lit, leak " << errors.leakRate() << " of "
                      << errors.shadowedPixels << " shadowed\n";
            EXPECT_GT(errors.litPixels, 1000u) << traits.name;
            EXPECT_GT(errors.shadowedPixels, 1000u) << traits.name;
            EXPECT_LE(errors.acneRate(), 0.0005) << traits.name;
            EXPECT_LE(errors.leakRate(), 0.0005) << traits.name;
        });
}

TEST(ShadowMapEdgeGLTest, TheGroundAroundTheMapsEdgeIsLit) {
    // The map covers where the box's shadow can fall, plus a margin, and the camera sees ground far beyond
    // it. Lookups near the map's edge must not read across it: a kernel, fit or central difference over the
    // border's far depth would predict taps far behind the receiver, which then look shadowed (dotted lines
    // along the map's outline). Every non-naive technique at its defaults keeps all of that ground lit.
    engine::EntityId camera = engine::kNoEntity;
    const engine::Scene scene = boxOnPlane(camera);
    const glm::vec3 toLight = -sunDirection();
    forEachTechniqueAtItsDefaults(
        scene, camera, [&](const ShadowTechniqueTraits& traits, const ShadowMeasurement& m) {
            const float band = 3.0f * m.texelWorldSize + 0.02f;
            std::size_t nearTheEdge = 0;
            std::size_t darkened = 0;
            for (std::size_t i = 0; i < m.visibility.size(); ++i) {
                const glm::vec3 p(m.position[i]);
                if (m.position[i].w < 0.5f || std::abs(p.y) > 1e-3f || boxOccludes(p, toLight) ||
                    !awayFromShadowEdges(p, toLight, band,
                                         [&](const glm::vec3& q) { return boxOccludes(q, toLight); })) {
                    continue;
                }
                const glm::vec4 s = m.projections.front().worldToShadow * glm::vec4(p, 1.0f);
                const float fromCentre = std::max(std::abs(s.x / s.w - 0.5f), std::abs(s.y / s.w - 0.5f));
                if (std::abs(fromCentre - 0.5f) * 1024.0f <= 10.0f) {
                    ++nearTheEdge; // within 10 texels of the map's edge, inside or out
                    darkened += m.visibility[i] < 0.99f;
                }
            }
            std::cout << "[ measured ] " << traits.name << ": " << darkened << " of " << nearTheEdge
                      << " lit ground pixels near the map's edge darkened\n";
            EXPECT_GT(nearTheEdge, 500u) << traits.name;
            EXPECT_EQ(darkened, 0u) << traits.name;
        });
}

INSTANTIATE_TEST_SUITE_P(Techniques, ShadowAccuracyGLTest, testing::ValuesIn(kAccuracy),
                         [](const auto& test) { return std::string(test.param.name); });

namespace {

/// Möller–Trumbore: does the segment from `origin` along `direction` hit the triangle (t > 0)?
bool hitsTriangle(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& a, const glm::vec3& b,
                  const glm::vec3& c) {
    const glm::vec3 e1 = b - a;
    const glm::vec3 e2 = c - a;
    const glm::vec3 p = glm::cross(direction, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) {
        return false;
    }
    const float inverse = 1.0f / det;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) {
        return false;
    }
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) {
        return false;
    }
    return glm::dot(e2, q) * inverse > 0.0f;
}

/// The knob scene and the pixels of its concave neck that are truly lit, away from true shadow edges.
class KnobNeck {
public:
    KnobNeck()
        : loaded_(content::GltfLoader::load(std::filesystem::path(CONTENT_DIR) / "scenes" / "knob.gltf")) {
        const engine::EntityId knob = *loaded_.scene.find("knob");
        const engine::MeshData& mesh = *loaded_.scene.entity(knob).mesh->mesh;
        const glm::mat4 toWorld = loaded_.scene.worldMatrix(knob);
        for (const std::uint32_t index : mesh.indices) {
            triangles_.emplace_back(toWorld * glm::vec4(mesh.positions[index], 1.0f));
        }
        loaded_.scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
            if (e.light) {
                toLight_ = glm::normalize(glm::vec3(loaded_.scene.worldMatrix(id)[2]));
            }
        });
    }

    /// Mean 1 - V of `technique` over the mask (built from the first measurement: geometry only).
    /// `footprintNormalOffset`: false measures the corrections as the reference has them. The point gradient
    /// is the map's own (central differences, as in docs/RESULTS.md's reproduction), not the module's
    /// default.
    double darkening(ShadowTechnique technique, bool footprintNormalOffset = false) {
        ShadowSettings settings;
        settings.technique = technique;
        settings.gradientSource = GradientSource::CentralDifferences;
        settings.resolution = kResolution;
        settings.pcfTaps = 5;
        settings.pcfRadius = 2.0f;
        settings.footprintNormalOffset = footprintNormalOffset;
        const ShadowMeasurement m =
            ShadowMeasurement::render(loaded_.scene, *loaded_.scene.firstCamera(), settings, {320, 240});
        if (mask_.empty()) {
            buildMask(m);
        }
        double sum = 0.0;
        for (const std::size_t i : mask_) {
            sum += 1.0 - static_cast<double>(m.visibility[i]);
        }
        return sum / static_cast<double>(std::max<std::size_t>(mask_.size(), 1));
    }

    [[nodiscard]] std::size_t pixels() const { return mask_.size(); }

private:
    bool occluded(const glm::vec3& origin) const {
        for (std::size_t t = 0; t + 2 < triangles_.size(); t += 3) {
            if (hitsTriangle(origin, toLight_, triangles_[t], triangles_[t + 1], triangles_[t + 2])) {
                return true;
            }
        }
        return false;
    }

    void buildMask(const ShadowMeasurement& m) {
        // Neck: between the base disc and the handle, close to the axis, facing the light. A pixel counts
        // when it is truly lit and no truly shadowed light-facing pixel lies within kBand pixels (away from
        // shadow edges).
        constexpr int kBand = 3;
        auto facing = [&](std::size_t i) {
            return m.position[i].w > 0.5f && glm::dot(m.normal[i], toLight_) >= 0.15f;
        };
        auto onNeck = [&](std::size_t i) {
            const glm::vec3 p(m.position[i]);
            return facing(i) && p.y >= 0.3f && p.y <= 1.0f && glm::length(glm::vec2(p.x, p.z)) <= 0.5f;
        };
        std::vector<int> shadowed(m.visibility.size(), -1); // -1 unknown, 0 lit, 1 shadowed
        auto isShadowed = [&](std::size_t i) {
            if (shadowed[i] < 0) {
                shadowed[i] = occluded(glm::vec3(m.position[i]) + 2e-3f * m.normal[i]) ? 1 : 0;
            }
            return shadowed[i] == 1;
        };
        for (int y = kBand; y < m.size.y - kBand; ++y) {
            for (int x = kBand; x < m.size.x - kBand; ++x) {
                const auto i = static_cast<std::size_t>(y * m.size.x + x);
                if (!onNeck(i) || isShadowed(i)) {
                    continue;
                }
                bool interior = true;
                for (int dy = -kBand; dy <= kBand && interior; ++dy) {
                    for (int dx = -kBand; dx <= kBand && interior; ++dx) {
                        const auto j = static_cast<std::size_t>((y + dy) * m.size.x + x + dx);
                        interior = !facing(j) || !isShadowed(j);
                    }
                }
                if (interior) {
                    mask_.push_back(i);
                }
            }
        }
    }

    content::LoadedScene loaded_;
    std::vector<glm::vec3> triangles_;
    glm::vec3 toLight_{0.0f};
    std::vector<std::size_t> mask_;
};

} // namespace

TEST(ShadowReproductionGLTest, ConcaveNeckDarkensLeastUnderTheQuadraticFit) {
    // GSM multisampling reference, Fig. 4.2.5: a PCF area that follows a plane dips into concave surfaces.
    // The reference suggests the taps' average gradient, and names higher-order derivatives as the obvious
    // fix. Measured on our smooth (subdivided) knob, the anchored least-squares gradient does not darken
    // consistently less than the fragment's own gradient (for a locally quadratic surface and a symmetric
    // pattern the two coincide: the least-squares slope of a parabola is its tangent slope), so the test pins
    // the ordering that does hold: the quadric darkens far less than either plane. The values are printed for
    // docs/RESULTS.md.
    KnobNeck neck;
    const double point = neck.darkening(ShadowTechnique::PcfGsmPointGradient);
    const double average = neck.darkening(ShadowTechnique::PcfGsmAverageGradient);
    const double quadratic = neck.darkening(ShadowTechnique::PcfGsmQuadratic);
    std::cout << "[ measured ] neck darkening over " << neck.pixels() << " lit interior pixels: point "
              << point << ", average " << average << ", quadratic " << quadratic << "\n";
    ASSERT_GT(neck.pixels(), 300u);
    EXPECT_GT(point, 0.0);
    EXPECT_LT(quadratic, 0.6 * std::min(point, average));
}

TEST(ShadowReproductionGLTest, ConnectedTapsDarkenTheConcaveNeckLessThanAnyPlane) {
    // The neck of Fig. 4.2.5 again: it runs on without a jump in the map, so pcf-gsm-connected keeps the taps
    // lit where every plane through the fragment fails. The quadric follows this smooth neck about as well
    // (it cannot follow a sharp crease); both stay above single-tap gsm, whose one tap never leaves the
    // fragment.
    KnobNeck neck;
    const double point = neck.darkening(ShadowTechnique::PcfGsmPointGradient);
    const double average = neck.darkening(ShadowTechnique::PcfGsmAverageGradient);
    const double nearer = neck.darkening(ShadowTechnique::PcfGsmNearer);
    const double connected = neck.darkening(ShadowTechnique::PcfGsmConnected);
    const double gsm = neck.darkening(ShadowTechnique::Gsm);
    std::cout << "[ measured ] neck darkening: nearer " << nearer << ", connected " << connected << ", gsm "
              << gsm << "\n";
    EXPECT_LT(connected, 0.5 * std::min({point, average, nearer}));
}

TEST(ShadowReproductionGLTest, TheFootprintNormalOffsetLiftsTheConcaveNeckOverItsOwnTaps) {
    // The module's default (docs/SHADOWS.md, "Automatic bias"): the receiver pushed half a texel diagonal
    // along its normal clears the neck's curvature under the taps, which every plane through the fragment
    // fails.
    KnobNeck neck;
    for (const ShadowTechnique technique :
         {ShadowTechnique::PcfGsmPointGradient, ShadowTechnique::PcfGsmAverageGradient,
          ShadowTechnique::PcfGsmNearer}) {
        const double reference = neck.darkening(technique);
        const double offset = neck.darkening(technique, true);
        std::cout << "[ measured ] neck darkening of " << traitsOf(technique).name << ": " << reference
                  << " as the reference has it, " << offset << " with the footprint's normal offset\n";
        EXPECT_LT(offset, 0.4 * reference); // measured 0.26-0.29 (pcfTaps 5 over 2 texels)
    }
}
