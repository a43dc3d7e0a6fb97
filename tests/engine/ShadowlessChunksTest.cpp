// castsNoShadow and chunksCastingNoShadow: a flat chunk is left out of a shadow pass only where no mesh lies
// behind it as the light sees it, for suns and point lights, under any model transform.
#include <engine/MeshChunks.h>
#include <engine/Primitives.h>
#include <engine/ShadowlessChunks.h>

#include "../support/TestMeshes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace {

using engine::ChunkedMesh;
using engine::MeshChunk;
using engine::PlacedChunks;

const glm::vec4 kGround(0, 1, 0, 0); // y = 0, normal up
const glm::vec4 kHighSun = glm::vec4(glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)), 0.0f);

TEST(ShadowlessChunksTest, CastsNoShadowOnPointsOnTheLightsSide) {
    const std::array<glm::vec3, 2> above{glm::vec3(0, 1, 0), glm::vec3(5, 0, -3)}; // one on the plane
    const std::array<glm::vec3, 2> oneBelow{glm::vec3(0, 1, 0), glm::vec3(5, -0.01f, -3)};
    EXPECT_TRUE(engine::castsNoShadow(kGround, kHighSun, above, 1e-4f));
    EXPECT_FALSE(engine::castsNoShadow(kGround, kHighSun, oneBelow, 1e-4f));
    EXPECT_TRUE(engine::castsNoShadow(kGround, kHighSun, oneBelow, 0.02f)); // within the tolerance
    // A sun below the plane: the points above are behind it.
    EXPECT_FALSE(engine::castsNoShadow(kGround, -kHighSun, above, 1e-4f));
    // A point light above, below; one on the plane and a sun along it shadow nothing.
    EXPECT_TRUE(engine::castsNoShadow(kGround, glm::vec4(0, 3, 0, 1), above, 1e-4f));
    EXPECT_FALSE(engine::castsNoShadow(kGround, glm::vec4(0, -3, 0, 1), above, 1e-4f));
    EXPECT_TRUE(engine::castsNoShadow(kGround, glm::vec4(2, 0, 0, 1), oneBelow, 1e-4f));
    EXPECT_TRUE(engine::castsNoShadow(kGround, glm::vec4(1, 0, 0, 0), oneBelow, 1e-4f));
    // Homogeneous points scaled by a negative w are the same light.
    EXPECT_FALSE(engine::castsNoShadow(kGround, glm::vec4(0, 3, 0, -1), above, 1e-4f));
    EXPECT_TRUE(engine::castsNoShadow(kGround, glm::vec4(0, -3, 0, -1), above, 1e-4f));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(engine::castsNoShadow(kGround, glm::vec4(nan, 1, 0, 0), above, 1e-4f));
    EXPECT_FALSE(engine::castsNoShadow(kGround, kHighSun, std::array{glm::vec3(0, nan, 0)}, 1e-4f));
}

/// Meshes placed in a scene, with the chunks chunksCastingNoShadow sees.
class Placed {
public:
    Placed& add(const engine::MeshData& mesh, const glm::mat4& model) {
        chunked_.push_back(engine::splitIntoChunks(mesh));
        models_.push_back(model);
        return *this;
    }
    [[nodiscard]] std::vector<PlacedChunks> meshes() const {
        std::vector<PlacedChunks> meshes;
        for (std::size_t i = 0; i < chunked_.size(); ++i) {
            meshes.push_back({models_[i], chunked_[i].bounds, chunked_[i].chunks});
        }
        return meshes;
    }
    /// Per mesh, how many of its chunks cast no shadow from `light`.
    [[nodiscard]] std::vector<std::size_t> shadowless(const glm::vec4& light) const {
        const std::vector<const MeshChunk*> left = engine::chunksCastingNoShadow(meshes(), light);
        std::vector<std::size_t> counts;
        for (const ChunkedMesh& mesh : chunked_) {
            counts.push_back(
                static_cast<std::size_t>(std::count_if(left.begin(), left.end(), [&](const MeshChunk* c) {
                    return c >= mesh.chunks.data() && c < mesh.chunks.data() + mesh.chunks.size();
                })));
        }
        return counts;
    }

private:
    std::vector<ChunkedMesh> chunked_;
    std::vector<glm::mat4> models_;
};

glm::mat4 translation(const glm::vec3& offset) {
    return glm::translate(glm::mat4(1.0f), offset);
}

TEST(ShadowlessChunksTest, GroundUnderAModelCastsNothingFromAboveOnly) {
    Placed scene;
    scene.add(engine::primitives::plane(20.0f), glm::mat4(1.0f))
        .add(engine::primitives::cube(1.0f), translation({0, 0.5f, 0}));
    EXPECT_EQ(scene.shadowless(kHighSun), (std::vector<std::size_t>{1, 0}));
    EXPECT_EQ(scene.shadowless(glm::vec4(1, 4, 0, 1)), (std::vector<std::size_t>{1, 0}));
    EXPECT_EQ(scene.shadowless(-kHighSun), (std::vector<std::size_t>{0, 0}));
    EXPECT_EQ(scene.shadowless(glm::vec4(1, -4, 0, 1)), (std::vector<std::size_t>{0, 0}));
}

TEST(ShadowlessChunksTest, AModelReachingBelowTheGroundKeepsIt) {
    Placed sunk;
    sunk.add(engine::primitives::plane(20.0f), glm::mat4(1.0f))
        .add(engine::primitives::cube(1.0f), translation({0, 0.49f, 0}));
    EXPECT_EQ(sunk.shadowless(kHighSun), (std::vector<std::size_t>{0, 0}));
    // Rounding of where a model stands (a millionth of the ground's size) is not below it.
    Placed standing;
    standing.add(engine::primitives::plane(20.0f), glm::mat4(1.0f))
        .add(engine::primitives::cube(1.0f), translation({0, 0.5f - 2e-6f, 0}));
    EXPECT_EQ(standing.shadowless(kHighSun), (std::vector<std::size_t>{1, 0}));
}

TEST(ShadowlessChunksTest, FollowsTheModelTransformOfEveryMesh) {
    // The whole scene turned, scaled and mirrored: the same answer as upright.
    const glm::mat4 turn =
        glm::scale(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(1, 0, 1)), glm::vec3(2.0f, 0.5f, -1.0f));
    for (const glm::vec4& light : {kHighSun, glm::vec4(1, 4, 0, 1), -kHighSun}) {
        Placed upright;
        upright.add(engine::primitives::plane(20.0f), glm::mat4(1.0f))
            .add(engine::primitives::cube(1.0f), translation({0, 0.5f, 0}));
        Placed turned;
        turned.add(engine::primitives::plane(20.0f), turn)
            .add(engine::primitives::cube(1.0f), turn * translation({0, 0.5f, 0}));
        const glm::vec4 turnedLight = turn * light;
        EXPECT_EQ(turned.shadowless(turnedLight), upright.shadowless(light)) << light.x << " " << light.w;
    }
    // A ground that cannot be inverted is kept.
    Placed flattened;
    flattened.add(engine::primitives::plane(20.0f), glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, 0)));
    EXPECT_EQ(flattened.shadowless(kHighSun), (std::vector<std::size_t>{0}));
}

TEST(ShadowlessChunksTest, RoomWallsCastNothingOnTheirInsideFromALightWithin) {
    // Six squares facing into a 4 m room, and a box on its floor.
    const std::array<glm::mat4, 6> walls{
        translation({0, 0, 0}),
        translation({0, 4, 0}) * glm::rotate(glm::mat4(1.0f), glm::pi<float>(), glm::vec3(1, 0, 0)),
        translation({2, 2, 0}) * glm::rotate(glm::mat4(1.0f), glm::half_pi<float>(), glm::vec3(0, 0, 1)),
        translation({-2, 2, 0}) * glm::rotate(glm::mat4(1.0f), -glm::half_pi<float>(), glm::vec3(0, 0, 1)),
        translation({0, 2, 2}) * glm::rotate(glm::mat4(1.0f), -glm::half_pi<float>(), glm::vec3(1, 0, 0)),
        translation({0, 2, -2}) * glm::rotate(glm::mat4(1.0f), glm::half_pi<float>(), glm::vec3(1, 0, 0)),
    };
    Placed room;
    for (const glm::mat4& wall : walls) {
        room.add(engine::primitives::plane(4.0f), wall);
    }
    room.add(engine::primitives::cube(1.0f), translation({0, 0.5f, 0}));
    EXPECT_EQ(room.shadowless(glm::vec4(0.5f, 3, 0.5f, 1)), (std::vector<std::size_t>{1, 1, 1, 1, 1, 1, 0}));
    // From outside, beyond the +x wall: that wall is the one with everything behind it.
    EXPECT_EQ(room.shadowless(glm::vec4(5, 2, 0, 1)), (std::vector<std::size_t>{1, 1, 0, 1, 1, 1, 0}));
}

TEST(ShadowlessChunksTest, CoplanarTilesAndATiltedGroundInOneMesh) {
    // Two ground tiles side by side as separate meshes, each the other's receiver on its own plane.
    Placed tiles;
    tiles.add(engine::primitives::plane(10.0f), translation({-5, 0, 0}))
        .add(engine::primitives::plane(10.0f), translation({5, 0, 0}))
        .add(engine::primitives::cube(1.0f), translation({0, 0.5f, 0}));
    EXPECT_EQ(tiles.shadowless(kHighSun), (std::vector<std::size_t>{1, 1, 0}));
    // A slope merged into one mesh with a cube on it (its box straddles the slope's plane), lit from above
    // the slope: the slope is left out, judged chunk by chunk.
    const glm::mat4 slope = glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(0, 0, 1));
    const engine::MeshData merged = testsupport::merged(
        engine::primitives::plane(20.0f, 4), engine::primitives::cube(1.0f), glm::vec3(0, 0.5f, 0));
    Placed sloped;
    sloped.add(merged, slope);
    const glm::vec4 sun = slope * glm::vec4(0, 1, 0, 0);
    EXPECT_EQ(sloped.shadowless(sun), (std::vector<std::size_t>{1}));
    EXPECT_EQ(sloped.shadowless(-sun), (std::vector<std::size_t>{0}));
}

} // namespace
