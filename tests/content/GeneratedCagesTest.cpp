#include "content/CageLoader.h"
#include "content/SubdivisionSurface.h"

#include "MeshChecks.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <filesystem>
#include <set>
#include <string>

namespace content {
namespace {

const std::filesystem::path kCagesDir = CONTENT_CAGES_DIR;

struct GeneratedCage {
    const char* name;
    long euler;
    std::size_t creases;
};

const GeneratedCage kGeneratedCages[] = {
    {"knob", 2, 0}, {"torus", 0, 0}, {"bowl", 2, 0}, {"crease-cube", 2, 5}, {"sphere", 2, 0}, {"roof", 2, 0},
};

class GeneratedCagesTest : public ::testing::TestWithParam<GeneratedCage> {};

TEST_P(GeneratedCagesTest, LoadsAsAClosedOutwardCageAndSubdivides) {
    const GeneratedCage& expected = GetParam();
    const Cage cage = CageLoader::load(kCagesDir / (std::string(expected.name) + ".obj"));
    EXPECT_EQ(cage.scheme, Scheme::CatmullClark);
    EXPECT_EQ(cage.creases.size(), expected.creases);

    const test::EdgeReport edges = test::analyseEdges(cage.faces);
    EXPECT_TRUE(edges.closed);
    EXPECT_EQ(test::eulerCharacteristic(cage.positions.size(), edges.edges, cage.faces.size()),
              expected.euler);
    EXPECT_GT(test::signedVolume(cage.positions, cage.faces), 0.0) << "faces wind inwards";

    const auto result = SubdivisionSurface(cage).evaluate(2);
    EXPECT_EQ(result.mesh.name, expected.name);
    EXPECT_GT(test::signedVolume(result.mesh.positions, test::triangles(result.mesh)), 0.0);
    for (const glm::vec3& n : result.mesh.normals) {
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
}

INSTANTIATE_TEST_SUITE_P(Cages, GeneratedCagesTest, ::testing::ValuesIn(kGeneratedCages),
                         [](const auto& test) {
                             std::string name = test.param.name;
                             std::erase(name, '-');
                             return name;
                         });

TEST(GeneratedCagesDirectoryTest, HoldsExactlyTheGeneratedCages) {
    std::set<std::string> expected;
    for (const GeneratedCage& cage : kGeneratedCages) {
        expected.insert(std::string(cage.name) + ".obj");
    }
    std::set<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(kCagesDir)) {
        found.insert(entry.path().filename().string());
    }
    EXPECT_EQ(found, expected);
}

// A crease of sharpness 3 (top loop) keeps the surface nearer its cage edge than the smooth bottom loop.
TEST(GeneratedCagesCreaseTest, CreasedEdgesOfTheCreaseCubeStayCloserToTheCage) {
    const auto mesh = SubdivisionSurface(CageLoader::load(kCagesDir / "crease-cube.obj")).evaluate(4).mesh;
    const float creased = test::nearestVertexDistance(mesh, {0.0f, 1.0f, -1.0f});
    const float smooth = test::nearestVertexDistance(mesh, {0.0f, -1.0f, -1.0f});
    EXPECT_LT(creased, 0.5f * smooth);
}

} // namespace
} // namespace content
