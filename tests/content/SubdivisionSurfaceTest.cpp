#include "content/SubdivisionSurface.h"
#include "content/CageShapes.h"
#include "content/ContentError.h"

#include "MeshChecks.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace content {
namespace {

using Level = SubdivisionSurface::LevelCounts;

Cage pentagonalPrism() {
    Cage cage;
    for (const float y : {0.0f, 1.0f}) {
        for (int i = 0; i < 5; ++i) {
            const float angle = glm::two_pi<float>() * static_cast<float>(i) / 5.0f;
            cage.positions.emplace_back(std::cos(angle), y, std::sin(angle));
        }
    }
    cage.faces = {{0, 1, 2, 3, 4}, {5, 9, 8, 7, 6}};
    for (std::uint32_t i = 0; i < 5; ++i) {
        const std::uint32_t next = (i + 1) % 5;
        cage.faces.push_back({i, i + 5, next + 5, next});
    }
    return cage;
}

Cage octahedron() {
    Cage cage;
    cage.scheme = Scheme::Loop;
    cage.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    cage.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return cage;
}

Cage triangulatedTorus() {
    Cage cage = CageShapes::torus(8, 5, 1.0f, 0.4f);
    cage.scheme = Scheme::Loop;
    std::vector<std::vector<std::uint32_t>> triangles;
    for (const auto& q : cage.faces) {
        triangles.push_back({q[0], q[1], q[2]});
        triangles.push_back({q[0], q[2], q[3]});
    }
    cage.faces = std::move(triangles);
    return cage;
}

/// Open 3x3-quad patch with a bump: has boundary edges and valence-2 corners.
Cage openGrid() {
    Cage cage;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            const bool inner = i > 0 && i < 3 && j > 0 && j < 3;
            cage.positions.emplace_back(static_cast<float>(i), inner ? 0.5f : 0.0f, static_cast<float>(j));
        }
    }
    for (std::uint32_t j = 0; j < 3; ++j) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t v = j * 4 + i;
            cage.faces.push_back({v, v + 4, v + 5, v + 1});
        }
    }
    return cage;
}

Cage knobLathe() {
    CageShapes::LatheProfile profile;
    profile.rings = {{1.0f, 0.0f}, {1.0f, 0.2f}, {0.3f, 0.5f}, {0.3f, 0.9f}, {1.2f, 1.4f}, {0.8f, 2.0f}};
    profile.bottomPoleHeight = 0.0f;
    profile.topPoleHeight = 2.1f;
    return CageShapes::lathe(profile, 8);
}

struct SurfaceCase {
    const char* name;
    std::function<Cage()> build;
    long euler;
    bool closed;
};

const SurfaceCase kSurfaces[] = {
    {"Cube",
     [] {
         return CageShapes::box({1, 1, 1}, {2.0f, 2.0f, 2.0f});
     },
     2, true},
    {"QuadSphere", [] { return CageShapes::quadSphere(2, 1.0f); }, 2, true},
    {"Torus", [] { return CageShapes::torus(8, 4, 1.0f, 0.3f); }, 0, true},
    {"Knob", knobLathe, 2, true},
    {"PentagonalPrism", pentagonalPrism, 2, true},
    {"OpenGrid", openGrid, 1, false},
    {"LoopOctahedron", octahedron, 2, true},
    {"LoopTorus", triangulatedTorus, 0, true},
};

constexpr int kGrowthLevels = 4;

class SubdivisionGrowthTest : public ::testing::TestWithParam<SurfaceCase> {};

// Catmull-Clark: every face yields one vertex and one quad per corner, every edge a vertex and two edges:
// V' = V + E + F, E' = 2E + sum(valence), F' = sum(valence). Loop: V' = V + E, E' = 2E + 3F, F' = 4F.
TEST_P(SubdivisionGrowthTest, CountsFollowTheSchemeRecurrence) {
    const Cage cage = GetParam().build();
    const SubdivisionSurface::Result result = SubdivisionSurface(cage).evaluate(kGrowthLevels);
    ASSERT_EQ(result.levels.size(), static_cast<std::size_t>(kGrowthLevels + 1));

    long valenceSum = 0;
    for (const auto& face : cage.faces) {
        valenceSum += static_cast<long>(face.size());
    }
    Level expected{static_cast<int>(cage.positions.size()),
                   static_cast<int>(test::analyseEdges(cage.faces).edges),
                   static_cast<int>(cage.faces.size())};
    for (int k = 0; k <= kGrowthLevels; ++k) {
        const Level& actual = result.levels[static_cast<std::size_t>(k)];
        EXPECT_EQ(actual.vertices, expected.vertices) << "level " << k;
        EXPECT_EQ(actual.edges, expected.edges) << "level " << k;
        EXPECT_EQ(actual.faces, expected.faces) << "level " << k;
        if (cage.scheme == Scheme::CatmullClark) {
            expected = {expected.vertices + expected.edges + expected.faces,
                        2 * expected.edges + static_cast<int>(valenceSum), static_cast<int>(valenceSum)};
            valenceSum = 4L * expected.faces; // every refined face is a quad
        } else {
            expected = {expected.vertices + expected.edges, 2 * expected.edges + 3 * expected.faces,
                        4 * expected.faces};
        }
    }
    const Level& last = result.levels.back();
    EXPECT_EQ(result.mesh.positions.size(), static_cast<std::size_t>(last.vertices));
    EXPECT_EQ(result.mesh.normals.size(), static_cast<std::size_t>(last.vertices));
    EXPECT_EQ(result.mesh.triangleCount(),
              static_cast<std::size_t>(cage.scheme == Scheme::Loop ? last.faces : 2 * last.faces));
}

TEST_P(SubdivisionGrowthTest, EulerCharacteristicIsPreservedAtEveryLevel) {
    const SurfaceCase& surface = GetParam();
    const SubdivisionSurface subdivision(surface.build());
    for (int level = 0; level <= kGrowthLevels; ++level) {
        const SubdivisionSurface::Result result = subdivision.evaluate(level);
        for (const Level& counts : result.levels) {
            EXPECT_EQ(test::eulerCharacteristic(static_cast<std::size_t>(counts.vertices),
                                                static_cast<std::size_t>(counts.edges),
                                                static_cast<std::size_t>(counts.faces)),
                      surface.euler);
        }
        // The triangulated output is the same surface: same characteristic, closed iff the cage is.
        const auto triangles = test::triangles(result.mesh);
        const test::EdgeReport edges = test::analyseEdges(triangles);
        EXPECT_EQ(test::eulerCharacteristic(result.mesh.positions.size(), edges.edges, triangles.size()),
                  surface.euler)
            << "level " << level;
        EXPECT_EQ(edges.closed, surface.closed) << "level " << level;
        EXPECT_TRUE(edges.consistentlyOriented) << "level " << level;
    }
}

TEST_P(SubdivisionGrowthTest, LimitNormalsAreUnitOutwardAndMatchNeighbouringLimitPoints) {
    const SurfaceCase& surface = GetParam();
    const SubdivisionSurface::Result result = SubdivisionSurface(surface.build()).evaluate(4);
    const engine::MeshData& mesh = result.mesh;
    const std::vector<glm::vec3> estimates = test::neighbourNormals(mesh);
    float worstAngle = 0.0f;
    for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
        ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-5f) << "vertex " << v;
        const float cosine = std::clamp(glm::dot(mesh.normals[v], estimates[v]), -1.0f, 1.0f);
        worstAngle = std::max(worstAngle, glm::degrees(std::acos(cosine)));
    }
    // The estimate is a first-order finite difference over a one-ring 1/16 of a cage edge wide; boundary
    // vertices only see one side of their ring.
    EXPECT_LT(worstAngle, surface.closed ? 3.0f : 6.0f);
    if (surface.closed) {
        EXPECT_GT(test::signedVolume(mesh.positions, test::triangles(mesh)), 0.0) << "triangles wind inwards";
    }
}

INSTANTIATE_TEST_SUITE_P(Surfaces, SubdivisionGrowthTest, ::testing::ValuesIn(kSurfaces),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(SubdivisionSurfaceTest, ClosedQuadCageFaceCountGrowsByFourPerLevel) {
    const Cage cage = CageShapes::torus(6, 4, 1.0f, 0.25f);
    const auto result = SubdivisionSurface(cage).evaluate(SubdivisionSurface::kMaxLevel);
    for (int k = 0; k <= SubdivisionSurface::kMaxLevel; ++k) {
        EXPECT_EQ(result.levels[static_cast<std::size_t>(k)].faces, 24 << (2 * k));
    }
}

TEST(SubdivisionSurfaceTest, SphereNormalsPointAwayFromTheCentre) {
    const auto mesh = SubdivisionSurface(CageShapes::quadSphere(3, 2.0f)).evaluate(3).mesh;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        EXPECT_GT(glm::dot(mesh.normals[v], glm::normalize(mesh.positions[v])), 0.99f) << "vertex " << v;
    }
}

// A Loop fan whose ring winds twice around the centre vertex (ring vertex i at angle 2 * 60i degrees): the
// limit tangents at the centre are the first Fourier components of the ring, which vanish for a ring of
// frequency 2, so the centre is a branch point and its normal must come from the surrounding faces.
TEST(SubdivisionSurfaceTest, DegenerateLimitTangentsFallBackToTheFaceNormals) {
    Cage cage;
    cage.scheme = Scheme::Loop;
    cage.positions.emplace_back(0.0f, 0.5f, 0.0f);
    for (int i = 0; i < 6; ++i) {
        const float angle = 2.0f * glm::two_pi<float>() * static_cast<float>(i) / 6.0f;
        cage.positions.emplace_back(std::cos(angle), 0.0f, std::sin(angle));
    }
    for (std::uint32_t i = 0; i < 6; ++i) {
        cage.faces.push_back({0, 1 + i, 1 + (i + 1) % 6});
    }
    for (int level = 0; level <= 2; ++level) {
        const auto mesh = SubdivisionSurface(cage).evaluate(level).mesh;
        // Angles increasing from +X towards +Z wind the fan clockwise seen from +Y: the faces face -Y.
        EXPECT_NEAR(mesh.normals[0].y, -1.0f, 1e-5f) << "level " << level;
    }
}

// ---- creases -------------------------------------------------------------------------------------------

Cage cube() {
    return CageShapes::box({1, 1, 1}, {2.0f, 2.0f, 2.0f});
}

std::uint32_t cubeVertex(const Cage& cage, glm::vec3 position) {
    const auto it = std::find(cage.positions.begin(), cage.positions.end(), position);
    EXPECT_NE(it, cage.positions.end());
    return static_cast<std::uint32_t>(it - cage.positions.begin());
}

// The edge of the 2x2x2 cube from (1,1,-1) to (1,1,1).
const glm::vec3 kEdgeStart{1.0f, 1.0f, -1.0f};
const glm::vec3 kEdgeEnd{1.0f, 1.0f, 1.0f};

float edgeMidpointDistance(float sharpness) {
    Cage cage = cube();
    if (sharpness > 0.0f) {
        cage.creases.push_back({cubeVertex(cage, kEdgeStart), cubeVertex(cage, kEdgeEnd), sharpness});
    }
    const auto mesh = SubdivisionSurface(cage).evaluate(4).mesh;
    return test::nearestVertexDistance(mesh, 0.5f * (kEdgeStart + kEdgeEnd));
}

TEST(SubdivisionCreaseTest, SharperCreasesStayCloserToTheCageEdge) {
    const float sharpness[] = {0.0f, 0.5f, 1.0f, 2.0f, 3.0f, 10.0f};
    float previous = std::numeric_limits<float>::max();
    for (const float s : sharpness) {
        const float distance = edgeMidpointDistance(s);
        EXPECT_LT(distance, previous) << "sharpness " << s;
        previous = distance;
    }
}

TEST(SubdivisionCreaseTest, InfinitelySharpEdgeBetweenCornersReproducesTheCageEdge) {
    Cage cage = cube();
    const std::uint32_t a = cubeVertex(cage, kEdgeStart);
    const std::uint32_t b = cubeVertex(cage, kEdgeEnd);
    cage.creases.push_back({a, b, 10.0f});
    cage.corners = {{a, 10.0f}, {b, 10.0f}};
    const auto mesh = SubdivisionSurface(cage).evaluate(4).mesh;
    for (int i = 0; i <= 16; ++i) {
        const glm::vec3 onEdge = glm::mix(kEdgeStart, kEdgeEnd, static_cast<float>(i) / 16.0f);
        EXPECT_LT(test::nearestVertexDistance(mesh, onEdge), 1e-5f) << "sample " << i;
    }
}

TEST(SubdivisionCreaseTest, AllEdgesSharpGivesBackTheCube) {
    Cage cage = cube();
    for (const auto& face : cage.faces) {
        for (std::size_t i = 0; i < face.size(); ++i) {
            cage.creases.push_back({face[i], face[(i + 1) % face.size()], 10.0f});
        }
    }
    const auto mesh = SubdivisionSurface(cage).evaluate(3).mesh;
    for (const glm::vec3& p : mesh.positions) {
        EXPECT_NEAR(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0f, 1e-5f);
    }
}

// ---- level selection and errors ------------------------------------------------------------------------

class SubdivisionEdgeLengthTest : public ::testing::TestWithParam<float> {};

TEST_P(SubdivisionEdgeLengthTest, PicksTheSmallestLevelMeetingTheTarget) {
    const float target = GetParam();
    const SubdivisionSurface surface(CageShapes::torus(8, 4, 2.0f, 0.5f));
    const auto result = surface.evaluateForEdgeLength(target);
    if (result.level < SubdivisionSurface::kMaxLevel) {
        EXPECT_LE(result.maxEdgeLength, target);
    }
    if (result.level > 0) {
        EXPECT_GT(surface.evaluate(result.level - 1).maxEdgeLength, target);
    }
}

INSTANTIATE_TEST_SUITE_P(Targets, SubdivisionEdgeLengthTest,
                         ::testing::Values(10.0f, 1.0f, 0.3f, 0.1f, 0.02f, 1e-4f));

TEST(SubdivisionSurfaceTest, EdgeLengthSelectionIsCappedAtTheMaximumLevel) {
    const SubdivisionSurface surface(cube());
    EXPECT_EQ(surface.evaluateForEdgeLength(1e-6f).level, SubdivisionSurface::kMaxLevel);
    EXPECT_EQ(surface.evaluateForEdgeLength(100.0f).level, 0);
}

TEST(SubdivisionSurfaceTest, RejectsInvalidArguments) {
    const SubdivisionSurface surface(cube());
    EXPECT_THROW((void)surface.evaluate(-1), std::out_of_range);
    EXPECT_THROW((void)surface.evaluate(SubdivisionSurface::kMaxLevel + 1), std::out_of_range);
    EXPECT_THROW((void)surface.evaluateForEdgeLength(0.0f), std::invalid_argument);
    EXPECT_THROW((void)surface.evaluateForEdgeLength(std::numeric_limits<float>::quiet_NaN()),
                 std::invalid_argument);
}

TEST(SubdivisionSurfaceTest, LoopOnQuadsNamesTheFace) {
    Cage cage = cube();
    cage.scheme = Scheme::Loop;
    try {
        (void)SubdivisionSurface(cage);
        FAIL() << "expected ContentError";
    } catch (const ContentError& error) {
        EXPECT_STREQ(error.what(),
                     "CageShapes::box: face 0 has 4 vertices, but Loop subdivision needs triangles");
    }
}

TEST(SubdivisionSurfaceTest, InvalidCageIsRejectedOnConstruction) {
    Cage cage = cube();
    cage.faces[2][1] = 42;
    EXPECT_THROW(SubdivisionSurface{cage}, ContentError);
}

} // namespace
} // namespace content
