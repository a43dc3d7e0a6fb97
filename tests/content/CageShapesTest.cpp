#include "content/CageShapes.h"

#include "MeshChecks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace content {
namespace {

struct ShapeCase {
    const char* name;
    std::function<Cage()> build;
    long euler; // 2 for sphere-like cages, 0 for tori
    double volume;
};

class CageShapesTest : public ::testing::TestWithParam<ShapeCase> {};

TEST_P(CageShapesTest, IsAClosedOutwardAllQuadCage) {
    const ShapeCase& shape = GetParam();
    const Cage cage = shape.build();
    ASSERT_NO_THROW(cage.validate());
    for (const auto& face : cage.faces) {
        ASSERT_EQ(face.size(), 4u);
    }
    const test::EdgeReport edges = test::analyseEdges(cage.faces);
    EXPECT_TRUE(edges.closed);
    EXPECT_TRUE(edges.consistentlyOriented);
    EXPECT_EQ(test::eulerCharacteristic(cage.positions.size(), edges.edges, cage.faces.size()), shape.euler);
    // Positive volume means the faces wind counter-clockwise seen from outside.
    EXPECT_NEAR(test::signedVolume(cage.positions, cage.faces), shape.volume, 1e-3 * shape.volume);
}

CageShapes::LatheProfile cylinderProfile() {
    CageShapes::LatheProfile profile;
    profile.rings = {{1.0f, 0.0f}, {1.0f, 2.0f}};
    profile.bottomPoleHeight = 0.0f;
    profile.topPoleHeight = 2.0f;
    return profile;
}

// Expected volumes of the cages themselves (polyhedra, not the smooth shapes they approximate).
const ShapeCase kShapes[] = {
    {"Box",
     [] {
         return CageShapes::box({3, 2, 4}, {3.0f, 2.0f, 1.0f});
     },
     2, 6.0},
    {"UnitCube",
     [] {
         return CageShapes::box({1, 1, 1}, {1.0f, 1.0f, 1.0f});
     },
     2, 1.0},
    // A 1x1-per-face quad sphere is the cube inscribed in the sphere: edge 2/sqrt(3).
    {"CoarseQuadSphere", [] { return CageShapes::quadSphere(1, 1.0f); }, 2, 8.0 / (3.0 * std::sqrt(3.0))},
    // Torus of 4 x 4 segments: each quarter is the image of a diamond prism (diamond area 0.5 centred at
    // distance 1) under (x, y, t) -> (x(1-t), y, xt), whose Jacobian is x, so its volume is 0.5 * 1.
    {"SquareTorus", [] { return CageShapes::torus(4, 4, 1.0f, 0.5f); }, 0, 4 * 0.5},
    // 8-sided prism of radius 1 (area 2*sqrt(2)) and height 2, with flat caps.
    {"OctagonalLathe", [] { return CageShapes::lathe(cylinderProfile(), 8); }, 2, 4.0 * std::sqrt(2.0)},
};

INSTANTIATE_TEST_SUITE_P(Shapes, CageShapesTest, ::testing::ValuesIn(kShapes),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(CageShapesArgumentsTest, RejectsInvalidArguments) {
    EXPECT_THROW((void)CageShapes::box({0, 1, 1}, {1.0f, 1.0f, 1.0f}), std::invalid_argument);
    EXPECT_THROW((void)CageShapes::torus(2, 8, 1.0f, 0.2f), std::invalid_argument);
    EXPECT_THROW((void)CageShapes::lathe(cylinderProfile(), 6), std::invalid_argument);
    CageShapes::LatheProfile onAxis = cylinderProfile();
    onAxis.rings[0].x = 0.0f;
    EXPECT_THROW((void)CageShapes::lathe(onAxis, 8), std::invalid_argument);
}

} // namespace
} // namespace content
