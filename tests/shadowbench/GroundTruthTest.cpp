// Ray-traced ground truth against closed-form shadows, and the metrics on synthetic images (no GL).
#include "../support/TestScenes.h"

#include <shadowbench/RayTracedVisibility.h>
#include <shadowbench/ShadowBench.h>
#include <shadowbench/ShadowMetrics.h>

#include <engine/Primitives.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadowbench;

namespace {

engine::FrameLight sun(glm::vec3 direction) {
    engine::FrameLight light;
    light.direction = glm::normalize(direction);
    return light;
}

/// Points on a grid over the ground plane y = 0, normals up.
struct GroundSamples {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint8_t> covered;
};

GroundSamples groundGrid(float half, int n) {
    GroundSamples s;
    for (int z = 0; z < n; ++z) {
        for (int x = 0; x < n; ++x) {
            s.positions.emplace_back(
                -half + 2.0f * half * (static_cast<float>(x) + 0.5f) / static_cast<float>(n), 0.0f,
                -half + 2.0f * half * (static_cast<float>(z) + 0.5f) / static_cast<float>(n));
            s.normals.emplace_back(0, 1, 0);
            s.covered.push_back(1);
        }
    }
    return s;
}

} // namespace

TEST(GroundTruthTest, BoxOnPlaneMatchesTheClosedFormShadow) {
    const engine::Scene scene = testsupport::boxOnPlane(20.0f, 2.0f);
    const RayTracedVisibility tracer(scene);
    const engine::FrameLight light = sun({-1.0f, -1.0f, -0.5f});
    const GroundSamples s = groundGrid(5.0f, 120);
    std::vector<float> visibility(s.positions.size());
    tracer.hardVisibility(s.positions, s.normals, s.covered, light, visibility);

    // Closed form: the ground point is shadowed when its ray towards the light passes through
    // [-1,1]x[0,2]x[-1,1].
    const glm::vec3 toLight = -light.direction;
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        const glm::vec3 p = s.positions[i];
        const auto [enter, exit] =
            testsupport::crossBox(p, toLight, {-1.0f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f}, 0.0f);
        const bool expected = enter < exit;
        if (std::abs(enter - exit) < 1e-3f) {
            continue; // grazing the box's silhouette: either answer is exact to float precision
        }
        EXPECT_EQ(visibility[i], expected ? 0.0f : 1.0f) << "at " << p.x << ", " << p.z;
        shadowed += expected;
    }
    EXPECT_GT(shadowed, 500u);
}

namespace {

/// A finely tessellated unit sphere centred at `centre` over a 20 x 20 ground.
engine::Scene ballOverGround(const glm::vec3& centre) {
    engine::Scene scene;
    testsupport::addGround(scene, 20.0f);
    const auto ball = scene.create("ball");
    scene.entity(ball).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::sphere(1.0f, 96, 192))};
    scene.entity(ball).transform.translation = centre;
    return scene;
}

} // namespace

TEST(GroundTruthTest, SphereOverPlaneMatchesTheClosedFormShadow) {
    const glm::vec3 centre(0.5f, 2.0f, -0.5f);
    const RayTracedVisibility tracer(ballOverGround(centre));
    const engine::FrameLight light = sun({0.3f, -1.0f, 0.2f});
    const GroundSamples s = groundGrid(4.0f, 100);
    std::vector<float> visibility(s.positions.size());
    tracer.hardVisibility(s.positions, s.normals, s.covered, light, visibility);
    const glm::vec3 toLight = -light.direction;
    std::size_t compared = 0;
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        // Distance from the sphere's centre to the ray: inside the radius means shadowed.
        const glm::vec3 offset = centre - s.positions[i];
        const float along = glm::dot(offset, toLight);
        const float distance = glm::length(offset - along * toLight);
        // The tessellated sphere is within 1e-3 of the true one: skip the thin shell where they may differ.
        if (std::abs(distance - 1.0f) < 2e-3f) {
            continue;
        }
        EXPECT_EQ(visibility[i], distance < 1.0f ? 0.0f : 1.0f);
        ++compared;
    }
    EXPECT_GT(compared, 9000u);
}

TEST(GroundTruthTest, PointLightAboveASphereCastsTheClosedFormMagnifiedShadow) {
    const glm::vec3 centre(0.5f, 2.0f, -0.5f);
    const RayTracedVisibility tracer(ballOverGround(centre));
    engine::FrameLight bulb;
    bulb.light.type = engine::LightType::Point;
    bulb.position = centre + glm::vec3(0.0f, 3.0f, 0.0f); // 5 above the ground, straight over the ball
    bulb.direction = {1, 0, 0};                           // a point light's axis must not matter
    const GroundSamples s = groundGrid(4.0f, 100);
    std::vector<float> visibility(s.positions.size());
    tracer.hardVisibility(s.positions, s.normals, s.covered, bulb, visibility);
    std::size_t compared = 0;
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        // Shadowed when the segment from the ground point to the light passes within the radius of the
        // sphere's centre.
        const glm::vec3 p = s.positions[i];
        const glm::vec3 segment = bulb.position - p;
        const float t = glm::clamp(glm::dot(centre - p, segment) / glm::dot(segment, segment), 0.0f, 1.0f);
        const float distance = glm::length(p + t * segment - centre);
        if (std::abs(distance - 1.0f) < 2e-3f) {
            continue; // the tessellated sphere's silhouette
        }
        EXPECT_EQ(visibility[i], distance < 1.0f ? 0.0f : 1.0f) << "at " << p.x << ", " << p.z;
        shadowed += visibility[i] == 0.0f;
        ++compared;
    }
    EXPECT_GT(compared, 9000u);
    // The shadow is the disk the light's tangent cone cuts from the ground: radius H tan(asin(r / (H - h)))
    // = 5 tan(asin(1/3)) = 1.77 for light height H = 5, centre height h = 2, radius r = 1; a sun overhead
    // would give radius 1. Each sample stands for (8/100)² of ground.
    const float shadowRadius = 5.0f * std::tan(std::asin(1.0f / 3.0f));
    const float expectedSamples = glm::pi<float>() * shadowRadius * shadowRadius / (0.08f * 0.08f);
    EXPECT_NEAR(static_cast<float>(shadowed), expectedSamples, 0.03f * expectedSamples);
}

TEST(GroundTruthTest, SpotLightBlockedOnlyBetweenLightAndSurface) {
    engine::Scene scene;
    const auto box = scene.create("box");
    scene.entity(box).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::cube(1))};
    scene.entity(box).transform.translation = {0, 5, 0};
    const RayTracedVisibility tracer(scene);
    engine::FrameLight spot;
    spot.light.type = engine::LightType::Spot;
    spot.position = {0, 3, 0}; // below the box: the box is behind the light
    spot.direction = {0, -1, 0};
    const std::vector<glm::vec3> positions{{0, 0, 0}};
    const std::vector<glm::vec3> normals{{0, 1, 0}};
    const std::vector<std::uint8_t> covered{1};
    std::vector<float> visibility(1);
    tracer.hardVisibility(positions, normals, covered, spot, visibility);
    EXPECT_EQ(visibility[0], 1.0f);
    spot.position = {0, 8, 0}; // above the box: blocked
    tracer.hardVisibility(positions, normals, covered, spot, visibility);
    EXPECT_EQ(visibility[0], 0.0f);
}

TEST(GroundTruthTest, ASmoothedNormalThroughItsFacetDoesNotShadowItsOwnPoint) {
    // Real models' smoothed normals can point through their own facets (the at-at's lean up to 45° past
    // them). Here the ground's normals face the viewer but dip below the ground, and the sun is overhead:
    // nothing blocks it, so every point is lit. Offsetting the ray along such a normal would start it under
    // the ground, which would then shadow its own point.
    engine::Scene scene;
    testsupport::addGround(scene, 20.0f);
    RayTracedVisibility tracer(scene);
    const glm::vec3 viewer(0.0f, 3.0f, -20.0f);
    tracer.setViewer(viewer);
    GroundSamples s = groundGrid(4.0f, 20);
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        s.normals[i] = glm::normalize(glm::vec3(0.0f, -0.5f, -1.0f));
        // It faces the viewer, like the G-buffer's.
        ASSERT_GT(glm::dot(s.normals[i], viewer - s.positions[i]), 0.0f);
    }
    std::vector<float> visibility(s.positions.size());
    tracer.hardVisibility(s.positions, s.normals, s.covered, sun({0.1f, -1.0f, 0.2f}), visibility);
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        EXPECT_EQ(visibility[i], 1.0f) << "at " << s.positions[i].x << ", " << s.positions[i].z;
    }
}

TEST(GroundTruthTest, FacetNormalIsTheTrianglesOnTheViewersSide) {
    engine::Scene scene;
    testsupport::addGround(scene, 20.0f);
    RayTracedVisibility tracer(scene);
    const glm::vec3 leaning = glm::normalize(glm::vec3(0.3f, 1.0f, 0.0f));
    EXPECT_EQ(tracer.facetNormal({1, 0, 1}, leaning), leaning); // no viewer yet: the normal given
    tracer.setViewer({0.0f, 3.0f, -20.0f});
    const glm::vec3 above = tracer.facetNormal({1, 0, 1}, leaning);
    EXPECT_NEAR(above.y, 1.0f, 1e-6f);
    tracer.setViewer({0.0f, -3.0f, -20.0f});
    const glm::vec3 below = tracer.facetNormal({1, 0, 1}, leaning);
    EXPECT_NEAR(below.y, -1.0f, 1e-6f);
    EXPECT_EQ(tracer.facetNormal({30, 0, 1}, leaning), leaning); // off the ground: no triangle there
}

TEST(GroundTruthTest, SoftVisibilityIsTheUnblockedFractionOfTheDisk) {
    engine::Scene scene;
    const auto wall = scene.create("half-plane");
    // A blocker covering x < 0 just above the receiver: from the origin, half the sun's disk is hidden.
    auto mesh = std::make_shared<engine::MeshData>(engine::primitives::plane(2.0f, 1));
    scene.entity(wall).mesh = engine::MeshComponent{mesh};
    scene.entity(wall).transform.translation = {-1.0f, 1.0f, 0.0f};
    const RayTracedVisibility tracer(scene);
    const std::vector<glm::vec3> positions{{0, 0, 0}, {3, 0, 0}, {-3, 0, 0.5f}};
    const std::vector<glm::vec3> normals(3, glm::vec3(0, 1, 0));
    const std::vector<std::uint8_t> covered(3, 1);
    std::vector<float> visibility(3);
    tracer.softVisibility(positions, normals, covered, sun({0, -1, 0}), 0.05f, 16, visibility);
    EXPECT_NEAR(visibility[0], 0.5f, 0.04f);
    EXPECT_EQ(visibility[1], 1.0f);
    EXPECT_EQ(visibility[2], 1.0f); // beyond the blocker's edge at x = -2
}

/// The fraction of a uniform disk of unit radius beyond a chord at signed distance `a` from its centre: the
/// part of a small light a half-plane edge leaves visible (the circular segment's area over the disk's).
double diskBeyondChord(double a) {
    a = std::clamp(a, -1.0, 1.0);
    return 1.0 - (std::acos(-a) - (-a) * std::sqrt(1.0 - a * a)) / glm::pi<double>();
}

/// A blocker over x < 0 at height 1 (a plane from x = -2 to 0).
engine::Scene halfPlaneBlocker() {
    engine::Scene scene;
    const auto wall = scene.create("half-plane");
    auto mesh = std::make_shared<engine::MeshData>(engine::primitives::plane(2.0f, 1));
    scene.entity(wall).mesh = engine::MeshComponent{mesh};
    scene.entity(wall).transform.translation = {-1.0f, 1.0f, 0.0f};
    return scene;
}

// A sun is a cone of its angular radius seen from each point: under a half-plane's edge the visible part is
// the disk's segment beyond the edge's chord, as the closed form has it.
TEST(GroundTruthTest, SoftVisibilityOfASunIsTheVisiblePartOfItsCone) {
    const RayTracedVisibility tracer(halfPlaneBlocker());
    const float radius = 0.05f; // angular radius: the disk spans tan(0.05) at height 1
    std::vector<glm::vec3> positions;
    for (const float x : {-0.04f, -0.02f, 0.0f, 0.02f, 0.04f}) {
        positions.push_back({x, 0.0f, 0.0f});
    }
    const std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 1, 0));
    const std::vector<std::uint8_t> covered(positions.size(), 1);
    std::vector<float> visibility(positions.size());
    tracer.softVisibility(positions, normals, covered, sun({0, -1, 0}), radius, 16, visibility);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const double expected = diskBeyondChord(-positions[i].x / std::tan(static_cast<double>(radius)));
        EXPECT_NEAR(visibility[i], expected, 0.02) << "at x = " << positions[i].x;
    }
}

// A point or spot light of radius r at distance d fills the cone of half-angle asin(r / d).
TEST(GroundTruthTest, SoftVisibilityOfASphereLightIsTheVisiblePartOfItsCone) {
    const RayTracedVisibility tracer(halfPlaneBlocker());
    engine::FrameLight bulb;
    bulb.light.type = engine::LightType::Point;
    bulb.light.radius = 0.3f;
    bulb.position = {0.0f, 3.0f, 0.0f};
    const double tangent = std::tan(std::asin(0.3 / 3.0)); // the cone's radius at the blocker, height 1
    std::vector<glm::vec3> positions;
    for (const float x : {-0.08f, 0.0f, 0.05f}) {
        positions.push_back({x, 0.0f, 0.0f});
    }
    const std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 1, 0));
    const std::vector<std::uint8_t> covered(positions.size(), 1);
    std::vector<float> visibility(positions.size());
    tracer.softVisibility(positions, normals, covered, bulb, RayTracedVisibility::ownRadius(bulb), 16,
                          visibility);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        // The cone's axis leans with the point's offset; its chord sits where the line to the centre crosses
        // the blocker's height, x (2/3) of the way.
        const double chord = -positions[i].x * (2.0 / 3.0);
        EXPECT_NEAR(visibility[i], diskBeyondChord(chord / tangent), 0.03) << "at x = " << positions[i].x;
    }
    // A radius of 0, and a point inside the light's sphere.
    EXPECT_EQ(RayTracedVisibility::ownRadius(sun({0, -1, 0})),
              0.5f * engine::LightComponent::kSunAngularDiameter);
    bulb.light.radius = 3.5f;
    tracer.softVisibility(positions, normals, covered, bulb, 3.5f, 4, visibility);
    EXPECT_EQ(visibility[0], 1.0f);
}

// Stratified rays converge: twice as many per axis change the visibility of a penumbra little.
TEST(GroundTruthTest, SoftVisibilityConvergesWithMoreRays) {
    const RayTracedVisibility tracer(halfPlaneBlocker());
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 41; ++i) {
        positions.push_back({-0.06f + 0.003f * static_cast<float>(i), 0.0f, 0.3f});
    }
    const std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 1, 0));
    const std::vector<std::uint8_t> covered(positions.size(), 1);
    const auto rms = [&](int coarse) {
        std::vector<float> a(positions.size());
        std::vector<float> b(positions.size());
        tracer.softVisibility(positions, normals, covered, sun({0, -1, 0}), 0.05f, coarse, a);
        tracer.softVisibility(positions, normals, covered, sun({0, -1, 0}), 0.05f, 2 * coarse, b);
        double sum = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            sum += (a[i] - b[i]) * static_cast<double>(a[i] - b[i]);
        }
        return std::sqrt(sum / static_cast<double>(a.size()));
    };
    const double coarse = rms(4);
    const double fine = rms(16);
    EXPECT_LT(fine, 0.005); // every point in the penumbra: no shadowless points dilute it
    EXPECT_LT(fine, coarse);
}

TEST(GroundTruthTest, EdgeWithinFindsTheOtherSideOfTheShadowsEdgeAcrossTheRays) {
    // Under an overhead sun a unit ball 2 above the ground shadows a unit disk: its edge lies 1 from the
    // point under the centre and 0.2 from a point 0.8 out, measured across the rays; the same from a lit
    // point 1.2 out.
    const glm::vec3 centre(0.5f, 2.0f, -0.5f);
    const RayTracedVisibility tracer(ballOverGround(centre));
    const std::vector<glm::vec3> positions{{0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {1.3f, 0, -0.5f},
                                           {1.3f, 0, -0.5f}, {0.5f, 0, -0.5f}, {1.7f, 0, -0.5f},
                                           {1.7f, 0, -0.5f}};
    const std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 1, 0));
    const std::vector<float> reach{0.9f, 1.1f, 0.1f, 0.3f, 0.0f, 0.1f, 0.3f};
    const std::vector<std::uint8_t> lit{0, 0, 0, 0, 0, 1, 1};
    std::vector<std::uint8_t> marked(positions.size(), 7);
    tracer.edgeWithin(positions, normals, reach, lit, sun({0, -1, 0}), marked);
    EXPECT_EQ(marked, (std::vector<std::uint8_t>{0, 1, 0, 1, 0, 0, 1}));
}

TEST(GroundTruthTest, EdgeWithinALitReceiverCountsOnlyThePointsItReaches) {
    // A thin wall x = 0 (y in [0, 4], z in [-2, 2]) on the ground, the sun at +x, +y, +z: the ground just
    // past the wall (x < 0) lies in its shadow. Across the rays a point 0.1 before the wall reaches the
    // shadowed ground past it only through the wall, and any lit point reaches the ground's underside only
    // through the ground: neither is an edge of its shadow. The shadowed foot of the wall is in the band, as
    // under any caster narrower than the band.
    engine::Scene scene;
    testsupport::addGround(scene, 20.0f);
    const auto wall = scene.create("wall");
    scene.entity(wall).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::plane(4.0f, 1))};
    scene.entity(wall).transform.translation = {0.0f, 2.0f, 0.0f};
    scene.entity(wall).transform.rotation = glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1));
    const RayTracedVisibility tracer(scene);
    const engine::FrameLight light = sun({-1.0f, -1.0f, -1.0f});
    const std::vector<glm::vec3> positions{{0.1f, 0, 0}, {6.0f, 0, 0}, {-0.1f, 0, 0}};
    const std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 1, 0));
    std::vector<float> visibility(positions.size());
    tracer.hardVisibility(positions, normals, std::vector<std::uint8_t>(positions.size(), 1), light,
                          visibility);
    ASSERT_EQ(visibility, (std::vector<float>{1.0f, 1.0f, 0.0f}));
    const std::vector<float> reach(positions.size(), 1.0f);
    const std::vector<std::uint8_t> lit{1, 1, 0};
    std::vector<std::uint8_t> marked(positions.size(), 7);
    tracer.edgeWithin(positions, normals, reach, lit, light, marked);
    EXPECT_EQ(marked, (std::vector<std::uint8_t>{0, 0, 1}));
}

/// Pixel positions of a `size` image laid on the ground y = 0, one world unit apart, rows along z.
std::vector<glm::vec3> groundPixels(glm::ivec2 size) {
    std::vector<glm::vec3> positions;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            positions.emplace_back(static_cast<float>(x), 0.0f, static_cast<float>(y));
        }
    }
    return positions;
}

/// Classes of the pixels of a `width`x1 strip on the ground, lit left of `edge` and shadowed from it on,
/// under a sun travelling along `direction` with shadow texels of `texel` world units.
std::vector<PixelClass> stripClasses(int width, int edge, glm::vec3 direction, float texel,
                                     float bandTexels) {
    const glm::ivec2 size(width, 1);
    std::vector<float> truth(static_cast<std::size_t>(width), 1.0f);
    std::fill(truth.begin() + edge, truth.end(), 0.0f);
    const std::vector<Surface> surfaces(truth.size(), Surface::Receiver);
    const std::vector<glm::vec3> positions = groundPixels(size);
    const std::vector<float> texels(truth.size(), texel);
    LightPlane plane{positions, texels};
    plane.direction = glm::normalize(direction);
    return classify(size, truth, surfaces, plane, bandTexels);
}

TEST(ShadowMetricsTest, ClassesAndRatesOnASyntheticImage) {
    // 8x1 strip: truth lit on the left half, shadowed on the right; pixel 0 is background.
    const glm::ivec2 size(8, 1);
    const std::vector<float> truth{1, 1, 1, 1, 0, 0, 0, 0};
    const std::vector<Surface> surfaces{Surface::None,     Surface::Receiver, Surface::Receiver,
                                        Surface::Receiver, Surface::Receiver, Surface::Receiver,
                                        Surface::Receiver, Surface::Receiver};
    const std::vector<float> visibility{0.0f, 0.2f, 1.0f, 1.0f, 0.0f, 0.0f, 0.9f, 0.0f};
    const std::vector<std::uint8_t> concave{0, 1, 1, 0, 0, 0, 0, 0};
    const std::vector<glm::vec3> positions = groundPixels(size);
    const std::vector<float> texels(8, 1.0f);
    const auto classes = classify(size, truth, surfaces, LightPlane{positions, texels}, 1.0f);
    EXPECT_EQ(classes, (std::vector<PixelClass>{PixelClass::Ignored, PixelClass::Lit, PixelClass::Lit,
                                                PixelClass::Band, PixelClass::Band, PixelClass::Shadowed,
                                                PixelClass::Shadowed, PixelClass::Shadowed}));
    const ShadowMetrics m = computeMetrics(classes, truth, visibility, concave);
    EXPECT_EQ(m.receivers, 7u);
    EXPECT_EQ(m.lit, 2u);
    EXPECT_EQ(m.shadowed, 3u);
    EXPECT_EQ(m.band, 2u);
    EXPECT_EQ(m.acne, 1u);
    EXPECT_EQ(m.leak, 1u);
    EXPECT_DOUBLE_EQ(m.acneRate, 0.5);
    EXPECT_DOUBLE_EQ(m.leakRate, 1.0 / 3.0);
    EXPECT_NEAR(m.darkening, (0.8 + 0.0) / 2.0, 1e-6);
    EXPECT_NEAR(m.concaveDarkening, 0.4, 1e-6);
    // MAE over every receiver: |0.2-1| + 0 + 0 + 0 + 0 + 0.9 + 0 = 1.7 over 7.
    EXPECT_NEAR(m.meanAbsoluteError, 1.7 / 7.0, 1e-6);
    EXPECT_NEAR(m.rootMeanSquareError, std::sqrt((0.64 + 0.81) / 7.0), 1e-6);
}

TEST(ShadowMetricsTest, BandIsADiskOfTexelsAroundAnEdgeUnderAnOverheadSun) {
    const glm::ivec2 size(7, 7);
    std::vector<float> truth(49, 1.0f);
    truth[3 * 7 + 3] = 0.0f; // one shadowed pixel in the middle
    const std::vector<Surface> surfaces(49, Surface::Receiver);
    const std::vector<glm::vec3> positions = groundPixels(size);
    const std::vector<float> texels(49, 1.0f);
    const auto classes = classify(size, truth, surfaces, LightPlane{positions, texels}, 2.0f);
    std::size_t band = 0;
    for (int y = 0; y < 7; ++y) {
        for (int x = 0; x < 7; ++x) {
            const bool near = (x - 3) * (x - 3) + (y - 3) * (y - 3) <= 4;
            EXPECT_EQ(classes[static_cast<std::size_t>(y * 7 + x)] == PixelClass::Band, near)
                << x << "," << y;
            band += near;
        }
    }
    EXPECT_EQ(band, 13u);
}

TEST(ShadowMetricsTest, BandSpreadsAcrossAReceiverTheLightGrazes) {
    // A sun 10° above the ground, shining along the strip: one texel across its rays covers 1/sin 10° = 5.8
    // pixels of ground, so two texels reach 11 pixels either side of the edge at 20.
    const float elevation = glm::radians(10.0f);
    const auto grazing = stripClasses(40, 20, {std::cos(elevation), -std::sin(elevation), 0.0f}, 1.0f, 2.0f);
    for (int x = 0; x < 40; ++x) {
        EXPECT_EQ(grazing[static_cast<std::size_t>(x)] == PixelClass::Band, x >= 9 && x <= 30) << x;
    }
    // The same sun shining across the strip sees the ground's pixels a texel apart.
    const auto across = stripClasses(40, 20, {0.0f, -std::sin(elevation), std::cos(elevation)}, 1.0f, 2.0f);
    for (int x = 0; x < 40; ++x) {
        EXPECT_EQ(across[static_cast<std::size_t>(x)] == PixelClass::Band, x >= 18 && x <= 21) << x;
    }
}

TEST(ShadowMetricsTest, AnEdgesNeighboursAreInTheBandHoweverFineTheMap) {
    const auto fine = stripClasses(10, 5, {0.0f, -1.0f, 0.0f}, 0.01f, 2.0f);
    for (int x = 0; x < 10; ++x) {
        EXPECT_EQ(fine[static_cast<std::size_t>(x)] == PixelClass::Band, x == 4 || x == 5) << x;
    }
}

TEST(ShadowMetricsTest, ALitReceiverMeetingASurfaceFacingAwayIsAtAnEdgeOfTheLight) {
    // 11x1 strip: lit receivers, a surface facing away from the light (a convex corner's far face), then
    // truly shadowed receivers. Only the lit side of the corner is at an edge: both sides of the other are
    // dark.
    const glm::ivec2 size(11, 1);
    const std::vector<float> truth{1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0};
    std::vector<Surface> surfaces(11, Surface::Receiver);
    surfaces[4] = surfaces[5] = surfaces[6] = Surface::FacingAway;
    const std::vector<glm::vec3> positions = groundPixels(size);
    const std::vector<float> texels(11, 1.0f);
    const auto classes = classify(size, truth, surfaces, LightPlane{positions, texels}, 2.0f);
    EXPECT_EQ(classes,
              (std::vector<PixelClass>{PixelClass::Lit, PixelClass::Lit, PixelClass::Band, PixelClass::Band,
                                       PixelClass::Ignored, PixelClass::Ignored, PixelClass::Ignored,
                                       PixelClass::Shadowed, PixelClass::Shadowed, PixelClass::Shadowed,
                                       PixelClass::Shadowed}));
}

TEST(ShadowMetricsTest, AReceiverWhoseEdgeLiesWithinTheBandOffTheImageIsInTheBand) {
    // Where the other side of a receiver's shadow edge lies near it off the image (hidden from the camera, or
    // a caster narrower than the band), the receiver is in the band, lit or shadowed.
    const glm::ivec2 size(7, 1);
    const std::vector<float> truth{0, 0, 0, 1, 1, 1, 1};
    const std::vector<Surface> surfaces(7, Surface::Receiver);
    const std::vector<glm::vec3> positions = groundPixels(size);
    const std::vector<float> texels(7, 0.01f);
    const std::vector<std::uint8_t> edgeWithinBand{1, 0, 0, 0, 0, 1, 0};
    LightPlane plane{positions, texels};
    plane.edgeWithinBand = edgeWithinBand;
    EXPECT_EQ(
        classify(size, truth, surfaces, plane, 2.0f),
        (std::vector<PixelClass>{PixelClass::Band, PixelClass::Shadowed, PixelClass::Band, PixelClass::Band,
                                 PixelClass::Lit, PixelClass::Band, PixelClass::Lit}));
}

TEST(ShadowMetricsTest, ScreenBandIsADiscOfPixelsAroundAnEdge) {
    // 7x7 lit receivers around one shadowed pixel: within 2 pixels of it (between centres) is the band, the
    // knight's move (sqrt 5 away) is not.
    const glm::ivec2 size(7, 7);
    std::vector<float> truth(49, 1.0f);
    truth[3 * 7 + 3] = 0.0f;
    const std::vector<Surface> surfaces(49, Surface::Receiver);
    const std::vector<PixelClass> classes = classifyByScreenBand(size, truth, surfaces, 2.0f);
    const auto at = [&](int x, int y) { return classes[static_cast<std::size_t>(y * 7 + x)]; };
    EXPECT_EQ(at(3, 3), PixelClass::Band);
    for (const glm::ivec2 p : {glm::ivec2(4, 4), glm::ivec2(2, 3), glm::ivec2(5, 3), glm::ivec2(3, 1)}) {
        EXPECT_EQ(at(p.x, p.y), PixelClass::Band) << p.x << "," << p.y;
    }
    for (const glm::ivec2 p : {glm::ivec2(5, 4), glm::ivec2(5, 5), glm::ivec2(0, 3), glm::ivec2(6, 6)}) {
        EXPECT_EQ(at(p.x, p.y), PixelClass::Lit) << p.x << "," << p.y;
    }
    // A band under 1.5 pixels still holds the 8 neighbours; a wider one reaches further.
    EXPECT_EQ(classifyByScreenBand(size, truth, surfaces, 0.5f)[4 * 7 + 4], PixelClass::Band);
    EXPECT_EQ(classifyByScreenBand(size, truth, surfaces, 0.5f)[3 * 7 + 5], PixelClass::Lit);
    EXPECT_EQ(classifyByScreenBand(size, truth, surfaces, 3.0f)[3 * 7 + 6], PixelClass::Band);
}

TEST(ShadowMetricsTest, ScreenBandIgnoresTheMapsTexelsAndKeepsTheEdgeOffTheImage) {
    // The same strip whatever the light: a texel band under a grazing sun spreads over the strip, a pixel
    // band does not; a receiver whose edge lies off the image (edgeWithinBand) is in the band.
    const glm::ivec2 size(9, 1);
    const std::vector<float> truth{1, 1, 1, 1, 0, 0, 0, 0, 0};
    const std::vector<Surface> surfaces(9, Surface::Receiver);
    const std::vector<std::uint8_t> edgeWithinBand{0, 0, 0, 0, 0, 0, 0, 0, 1};
    EXPECT_EQ(classifyByScreenBand(size, truth, surfaces, 2.0f, edgeWithinBand),
              (std::vector<PixelClass>{PixelClass::Lit, PixelClass::Lit, PixelClass::Band, PixelClass::Band,
                                       PixelClass::Band, PixelClass::Band, PixelClass::Shadowed,
                                       PixelClass::Shadowed, PixelClass::Band}));
    const std::vector<PixelClass> texelBand = stripClasses(9, 4, {1.0f, -0.02f, 0.0f}, 0.1f, 2.0f);
    EXPECT_EQ(std::count(texelBand.begin(), texelBand.end(), PixelClass::Band), 9);
}

TEST(ShadowMetricsTest, TexelDensityCountsTrulyLitReceiversWithAFootprint) {
    const std::vector<PixelClass> classes{PixelClass::Lit,  PixelClass::Lit,      PixelClass::Band,
                                          PixelClass::Band, PixelClass::Shadowed, PixelClass::Ignored,
                                          PixelClass::Lit,  PixelClass::Lit};
    const std::vector<float> truth{1, 1, 1, 0, 0, 1, 1, 1};
    const std::vector<float> footprints{0.5f, 1.0f, 3.0f, 0.1f, 0.1f, 0.1f, -1.0f, 2.0f};
    const TexelDensity density = texelDensity(classes, truth, footprints);
    // Pixels 0, 1, 2 and 7: the band's lit side counts, its shadowed side, shadows, the ignored and the
    // unknown do not.
    EXPECT_EQ(density.pixels, 4u);
    EXPECT_DOUBLE_EQ(density.atMostOnePixel, 0.5);
    EXPECT_DOUBLE_EQ(density.median, 1.0);
    EXPECT_DOUBLE_EQ(density.percentile99, 3.0);
    EXPECT_EQ(texelDensity(classes, truth, std::vector<float>(8, -1.0f)).pixels, 0u);
}

TEST(TexelFootprintsTest, OverheadMapOfTheGroundIsItsTexelInPixels) {
    // Pixels one world unit apart on the ground, an orthographic map looking down over 64 units at 16 texels:
    // a texel spans 4 world units, 4 pixels.
    const glm::ivec2 size(6, 5);
    const std::vector<glm::vec3> positions = groundPixels(size);
    std::vector<Surface> surfaces(positions.size(), Surface::Receiver);
    surfaces[0] = Surface::None;
    shadows::LightProjection map;
    map.worldToShadow = glm::mat4(glm::vec4(1.0f / 64.0f, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                                  glm::vec4(0, 1.0f / 64.0f, 0, 0), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    map.texelScale = 4.0f;
    const std::vector<float> footprints = texelFootprints(size, positions, surfaces, {&map, 1}, 16);
    EXPECT_EQ(footprints[0], -1.0f); // background
    for (std::size_t i = 1; i < footprints.size(); ++i) {
        EXPECT_NEAR(footprints[i], 4.0f, 1e-3f) << i;
    }
    // Outside every map: unknown.
    const std::vector<glm::vec3> far(positions.size(), glm::vec3(1000.0f, 0.0f, 0.0f));
    const std::vector<float> outside = texelFootprints(size, far, surfaces, {&map, 1}, 16);
    EXPECT_TRUE(std::all_of(outside.begin(), outside.end(), [](float m) { return m == -1.0f; }));
}

TEST(TexelFootprintsTest, ADerivativeDoesNotCrossASilhouette) {
    // A strip whose right half lies far away (another surface): the pixel beside the jump takes its near
    // neighbour's difference.
    const glm::ivec2 size(6, 2);
    std::vector<glm::vec3> positions = groundPixels(size);
    for (glm::vec3& p : positions) {
        if (p.x >= 3.0f) {
            p.x += 40.0f;
        }
    }
    const std::vector<Surface> surfaces(positions.size(), Surface::Receiver);
    shadows::LightProjection map;
    map.worldToShadow = glm::mat4(glm::vec4(1.0f / 64.0f, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                                  glm::vec4(0, 1.0f / 64.0f, 0, 0), glm::vec4(0.25f, 0.5f, 0.5f, 1.0f));
    const std::vector<float> footprints = texelFootprints(size, positions, surfaces, {&map, 1}, 16);
    EXPECT_NEAR(footprints[2], 4.0f, 1e-3f);
    EXPECT_NEAR(footprints[3], 4.0f, 1e-3f);
}

TEST(ShadowMetricsTest, APointLightMeasuresAcrossItsRaysAtTheReceiversDistance) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 5, 0}, {0, 20, 0}};
    const std::vector<float> texels{0.5f, 0.5f, 0.5f, 0.0f};
    LightPlane lamp{positions, texels};
    lamp.directional = false;
    lamp.position = {0, 10, 0};
    EXPECT_FLOAT_EQ(lamp.texelsBetween(0, 1), 2.0f);   // one unit off the ray at the same distance
    EXPECT_FLOAT_EQ(lamp.texelsBetween(0, 2), 4.0f);   // one unit off it halfway: two at the receiver
    EXPECT_TRUE(std::isinf(lamp.texelsBetween(0, 3))); // behind the lamp
    EXPECT_TRUE(std::isinf(lamp.texelsBetween(3, 0))); // no map holds the pixel
}

TEST(ShadowMetricsTest, ConcaveMaskFindsTheInsideOfACylinder) {
    // A half-pipe seen from above: positions on a cylinder y = -sqrt(1 - x²), normals pointing at the axis
    // (inward: the concave side faces the camera).
    const glm::ivec2 size(21, 3);
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const float u = -0.9f + 1.8f * static_cast<float>(x) / static_cast<float>(size.x - 1);
            const glm::vec3 p(u, -std::sqrt(1.0f - u * u), 0.1f * static_cast<float>(y));
            positions.push_back(p);
            normals.push_back(-glm::normalize(glm::vec3(p.x, p.y, 0.0f)));
        }
    }
    const std::vector<std::uint8_t> covered(positions.size(), 1);
    const auto concave = concaveMask(size, positions, normals, covered, 0.5f);
    EXPECT_EQ(concave[static_cast<std::size_t>(size.x + 10)], 1);
    // Flip the normals outward: a convex surface is not concave.
    for (glm::vec3& n : normals) {
        n = -n;
    }
    const auto convex = concaveMask(size, positions, normals, covered, 0.5f);
    EXPECT_EQ(convex[static_cast<std::size_t>(size.x + 10)], 0);
}

namespace {
/// A disc of shadow (visibility 0) of `radius` pixels centred at `centre` on a lit 64x48 receiver.
std::vector<float> discShadow(glm::vec2 centre, float radius) {
    std::vector<float> image(64 * 48, 1.0f);
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (glm::length(glm::vec2(x, y) - centre) <= radius) {
                image[static_cast<std::size_t>(y * 64 + x)] = 0.0f;
            }
        }
    }
    return image;
}
} // namespace

TEST(EdgePlacementTest, EdgePixelsAreTheShadowedSideOfEachBoundary) {
    const glm::ivec2 size(6, 1);
    const std::vector<PixelClass> classes(6, PixelClass::Lit);
    const std::vector<float> visibility{1, 1, 0, 0, 0, 1};
    EXPECT_EQ(edgePixels(size, classes, visibility), (std::vector<std::uint8_t>{0, 0, 1, 0, 1, 0}));
    // A neighbour that is not a receiver (background, back faces) makes no edge.
    std::vector<PixelClass> withBackground = classes;
    withBackground[1] = PixelClass::Ignored;
    EXPECT_EQ(edgePixels(size, withBackground, visibility), (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 0}));
}

class EdgeShiftTest : public testing::TestWithParam<int> {};

TEST_P(EdgeShiftTest, AShadowShiftedByKPixelsIsKPixelsAway) {
    const int k = GetParam();
    const glm::ivec2 size(64, 48);
    const std::vector<PixelClass> classes(64 * 48, PixelClass::Lit);
    // A half-plane shadow x >= 20, rendered from x >= 20 + k: both edges are straight columns.
    std::vector<float> truth(64 * 48, 1.0f);
    std::vector<float> rendered(64 * 48, 1.0f);
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            truth[static_cast<std::size_t>(y * 64 + x)] = x >= 20 ? 0.0f : 1.0f;
            rendered[static_cast<std::size_t>(y * 64 + x)] = x >= 20 + k ? 0.0f : 1.0f;
        }
    }
    const EdgePlacement edges = edgePlacement(size, classes, truth, rendered);
    EXPECT_EQ(edges.trueToRendered.count, 48u);
    EXPECT_EQ(edges.renderedToTrue.count, 48u);
    EXPECT_DOUBLE_EQ(edges.trueToRendered.mean, k);
    EXPECT_DOUBLE_EQ(edges.trueToRendered.percentile95, k);
    EXPECT_DOUBLE_EQ(edges.renderedToTrue.mean, k);
    EXPECT_DOUBLE_EQ(edges.renderedToTrue.percentile95, k);
}

INSTANTIATE_TEST_SUITE_P(Shifts, EdgeShiftTest, testing::Values(0, 1, 3, 10));

TEST(EdgePlacementTest, AShrunkenShadowIsFarFromTheTrueEdgeOnlyOneWay) {
    // Peter-panning-like shrink: the rendered disc (radius 6) lies inside the true one (radius 12). Every
    // rendered edge is ~6 pixels from the true circle, and so is every true edge from the rendered one.
    const glm::ivec2 size(64, 48);
    const std::vector<PixelClass> classes(64 * 48, PixelClass::Lit);
    const EdgePlacement edges =
        edgePlacement(size, classes, discShadow({32, 24}, 12.0f), discShadow({32, 24}, 6.0f));
    EXPECT_NEAR(edges.trueToRendered.mean, 6.0, 0.8);
    EXPECT_NEAR(edges.renderedToTrue.mean, 6.0, 0.8);
}

TEST(EdgePlacementTest, SpeckleFarFromAnyTrueEdgeShowsOnlyFromTheRenderedSide) {
    const glm::ivec2 size(64, 48);
    const std::vector<PixelClass> classes(64 * 48, PixelClass::Lit);
    const std::vector<float> truth = discShadow({16, 24}, 5.0f);
    std::vector<float> rendered = truth;
    rendered[static_cast<std::size_t>(10 * 64 + 56)] = 0.0f; // one acne pixel at (56, 10)
    const EdgePlacement edges = edgePlacement(size, classes, truth, rendered);
    EXPECT_DOUBLE_EQ(edges.trueToRendered.mean, 0.0);
    // One stray pixel among ~30 edge pixels moves the mean, not the 95th percentile.
    EXPECT_DOUBLE_EQ(edges.renderedToTrue.percentile95, 0.0);
    EXPECT_EQ(edges.renderedToTrue.count, edges.trueToRendered.count + 1);
    // The acne pixel is ~35 pixels from the disc: it alone lifts the mean.
    EXPECT_GT(edges.renderedToTrue.mean * static_cast<double>(edges.renderedToTrue.count), 30.0);
}

TEST(EdgePlacementTest, NoRenderedEdgeCountsAsTheImageDiagonal) {
    const glm::ivec2 size(64, 48);
    const std::vector<PixelClass> classes(64 * 48, PixelClass::Lit);
    const std::vector<float> lit(64 * 48, 1.0f);
    const EdgePlacement edges = edgePlacement(size, classes, discShadow({32, 24}, 8.0f), lit);
    EXPECT_GT(edges.trueToRendered.count, 0u);
    EXPECT_DOUBLE_EQ(edges.trueToRendered.mean, 80.0); // hypot(64, 48)
    EXPECT_EQ(edges.renderedToTrue.count, 0u);
    EXPECT_DOUBLE_EQ(edges.renderedToTrue.mean, 0.0);
}
