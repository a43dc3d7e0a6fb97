// splitIntoChunks: every triangle survives exactly once, chunks respect the limit, their bounds hold their
// vertices, small meshes keep their order, closed parts and open ones never share a chunk, and broken input
// neither crashes nor loses triangles.
#include <engine/MeshChunks.h>
#include <engine/Primitives.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <set>

namespace {

using Triangle = std::array<std::uint32_t, 3>;

/// The mesh's triangles as source-vertex triples, each rotated to start at its smallest index.
std::multiset<Triangle> sourceTriangles(const engine::ChunkedMesh& chunked) {
    std::multiset<Triangle> triangles;
    for (std::size_t i = 0; i < chunked.indices.size(); i += 3) {
        Triangle t{chunked.sourceVertex[chunked.indices[i]], chunked.sourceVertex[chunked.indices[i + 1]],
                   chunked.sourceVertex[chunked.indices[i + 2]]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); // keeps the winding
        triangles.insert(t);
    }
    return triangles;
}

std::multiset<Triangle> meshTriangles(const engine::MeshData& mesh) {
    std::multiset<Triangle> triangles;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        Triangle t{mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        triangles.insert(t);
    }
    return triangles;
}

TEST(MeshChunksTest, EveryTriangleOnceWithWindingAndChunksWithinTheLimit) {
    const engine::MeshData sphere = engine::primitives::sphere(1.0f, 40, 80);
    const engine::ChunkedMesh chunked = engine::splitIntoChunks(sphere, {500});
    EXPECT_EQ(sourceTriangles(chunked), meshTriangles(sphere));
    ASSERT_GT(chunked.chunks.size(), 1u);
    std::uint32_t nextIndex = 0;
    std::uint32_t nextVertex = 0;
    for (const engine::MeshChunk& chunk : chunked.chunks) {
        EXPECT_LE(chunk.indexCount, 3u * 500u);
        EXPECT_EQ(chunk.firstIndex, nextIndex);
        EXPECT_EQ(chunk.firstVertex, nextVertex);
        nextIndex += chunk.indexCount;
        nextVertex += chunk.vertexCount;
        for (std::uint32_t i = chunk.firstIndex; i < chunk.firstIndex + chunk.indexCount; ++i) {
            const std::uint32_t vertex = chunked.indices[i];
            EXPECT_GE(vertex, chunk.firstVertex);
            EXPECT_LT(vertex, chunk.firstVertex + chunk.vertexCount); // a draw reads only its own range
            const glm::vec3 p = sphere.positions[chunked.sourceVertex[vertex]];
            EXPECT_TRUE(glm::all(glm::lessThanEqual(chunk.bounds.min, p)) &&
                        glm::all(glm::lessThanEqual(p, chunk.bounds.max)));
        }
    }
    EXPECT_EQ(nextIndex, chunked.indices.size());
    EXPECT_EQ(nextVertex, chunked.sourceVertex.size());
}

TEST(MeshChunksTest, ChunksAreSpatiallyCompact) {
    // A 128x128-cell plane in 32 chunks: median splits give square-ish tiles of 1/32 of the area each.
    const engine::MeshData plane = engine::primitives::plane(1.0f, 128);
    const engine::ChunkedMesh chunked = engine::splitIntoChunks(plane, {1024});
    ASSERT_EQ(chunked.chunks.size(), 32u);
    for (const engine::MeshChunk& chunk : chunked.chunks) {
        const glm::vec3 extent = chunk.bounds.max - chunk.bounds.min;
        EXPECT_LT(extent.x * extent.z, 1.5f / 32.0f);
    }
}

TEST(MeshChunksTest, AMeshThatFitsOneChunkKeepsItsTriangleOrder) {
    const engine::MeshData cube = engine::primitives::cube(2.0f);
    const engine::ChunkedMesh chunked = engine::splitIntoChunks(cube);
    ASSERT_EQ(chunked.chunks.size(), 1u);
    ASSERT_EQ(chunked.indices.size(), cube.indices.size());
    for (std::size_t i = 0; i < cube.indices.size(); ++i) {
        EXPECT_EQ(chunked.sourceVertex[chunked.indices[i]], cube.indices[i]);
    }
    EXPECT_EQ(chunked.bounds.min, glm::vec3(-1.0f));
    EXPECT_EQ(chunked.bounds.max, glm::vec3(1.0f));
}

TEST(MeshChunksTest, EmptyMeshHasNoChunks) {
    const engine::ChunkedMesh chunked = engine::splitIntoChunks(engine::MeshData{});
    EXPECT_TRUE(chunked.chunks.empty());
    EXPECT_TRUE(chunked.indices.empty());
    EXPECT_TRUE(chunked.bounds.empty());
}

TEST(MeshChunksTest, NonFinitePositionsKeepEveryTriangle) {
    engine::MeshData mesh = engine::primitives::plane(1.0f, 16);
    mesh.positions[3] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    mesh.positions[7] = glm::vec3(std::numeric_limits<float>::infinity(), 0.0f, 0.0f);
    const engine::ChunkedMesh chunked = engine::splitIntoChunks(mesh, {7});
    EXPECT_EQ(sourceTriangles(chunked), meshTriangles(mesh));
}

TEST(MeshChunksTest, EachChunkHoldsOneClosureWithTheBoundsOfItsWholeParts) {
    // An open plane, then a closed cube, then another plane: one mesh, as real assets merge them.
    engine::MeshData mesh = engine::primitives::plane(4.0f, 2);
    const engine::MeshData cube = engine::primitives::cube(1.0f);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec3& p : cube.positions) {
        mesh.positions.push_back(p + glm::vec3(0.0f, 2.0f, 0.0f));
    }
    for (const std::uint32_t index : cube.indices) {
        mesh.indices.push_back(base + index);
    }
    const engine::MeshData plane = engine::primitives::plane(1.0f);
    const auto planeBase = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec3& p : plane.positions) {
        mesh.positions.push_back(p + glm::vec3(0.0f, -3.0f, 0.0f));
    }
    for (const std::uint32_t index : plane.indices) {
        mesh.indices.push_back(planeBase + index);
    }
    mesh.normals.clear();

    const engine::ChunkedMesh chunked = engine::splitIntoChunks(mesh, {5}); // the cube's 12 in three chunks
    EXPECT_EQ(sourceTriangles(chunked), meshTriangles(mesh));
    std::size_t closedTriangles = 0;
    for (const engine::MeshChunk& chunk : chunked.chunks) {
        if (chunk.closure == engine::SurfaceClosure::Outward) {
            closedTriangles += chunk.indexCount / 3;
            EXPECT_EQ(chunk.closedBounds.min, glm::vec3(-0.5f, 1.5f, -0.5f));
            EXPECT_EQ(chunk.closedBounds.max, glm::vec3(0.5f, 2.5f, 0.5f));
        } else {
            EXPECT_EQ(chunk.closure, engine::SurfaceClosure::Open);
            EXPECT_TRUE(chunk.closedBounds.empty());
        }
    }
    EXPECT_EQ(closedTriangles, cube.triangleCount());
}

TEST(MeshChunksTest, ZeroLimitMeansOneTrianglePerChunk) {
    const engine::MeshData cube = engine::primitives::cube(1.0f);
    EXPECT_EQ(engine::splitIntoChunks(cube, {0}).chunks.size(), cube.triangleCount());
}

} // namespace
