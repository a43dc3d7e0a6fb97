// splitIntoChunks: every triangle survives exactly once, chunks respect the limit, their bounds hold their
// vertices, small meshes keep their order, closed parts and open ones never share a chunk, flat parts are
// chunked plane by plane and their chunks hold that plane, and broken input neither crashes nor loses
// triangles.
#include <engine/MeshChunks.h>
#include <engine/Primitives.h>

#include "../support/TestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

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
    const engine::MeshData cube = engine::primitives::cube(1.0f);
    engine::MeshData mesh = testsupport::merged(engine::primitives::plane(4.0f, 2), cube, glm::vec3(0, 2, 0));
    mesh = testsupport::merged(mesh, engine::primitives::plane(1.0f), glm::vec3(0, -3, 0));
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

TEST(MeshChunksTest, FlatChunksHoldTheirPlaneAndFlatPartsChunkApart) {
    // A ground tessellated into several chunks, a cube, a bent open strip and a tilted square in one mesh.
    const glm::mat4 tilt =
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(5, 1, 0)), 0.5f, glm::vec3(1, 0, 0));
    engine::MeshData strip = engine::primitives::plane(1.0f, 2);
    for (glm::vec3& p : strip.positions) {
        p.y = p.x > 0.0f ? p.x : 0.0f; // folded along x = 0
    }
    engine::MeshData mesh = engine::primitives::plane(8.0f, 8);
    mesh = testsupport::merged(mesh, engine::primitives::cube(1.0f), glm::vec3(0, 0.5f, 0));
    mesh = testsupport::merged(mesh, strip, glm::vec3(-3, 2, 0)); // above the ground, welded to nothing
    mesh = testsupport::merged(mesh, engine::primitives::plane(1.0f), tilt);

    const engine::ChunkedMesh chunked = engine::splitIntoChunks(mesh, {32});
    EXPECT_EQ(sourceTriangles(chunked), meshTriangles(mesh));
    const glm::vec3 tiltedNormal = glm::normalize(glm::vec3(tilt * glm::vec4(0, 1, 0, 0)));
    std::size_t groundTriangles = 0;
    std::size_t tiltedTriangles = 0;
    for (const engine::MeshChunk& chunk : chunked.chunks) {
        if (!chunk.plane) {
            continue;
        }
        const glm::vec3 normal(*chunk.plane);
        EXPECT_NEAR(glm::length(normal), 1.0f, 1e-6f);
        for (std::uint32_t v = chunk.firstVertex; v < chunk.firstVertex + chunk.vertexCount; ++v) {
            EXPECT_NEAR(glm::dot(normal, mesh.positions[chunked.sourceVertex[v]]) + chunk.plane->w, 0.0f,
                        1e-5f);
        }
        if (std::abs(glm::dot(normal, glm::vec3(0, 1, 0))) > 0.9999f) {
            groundTriangles += chunk.indexCount / 3;
        } else if (std::abs(glm::dot(normal, tiltedNormal)) > 0.9999f) {
            tiltedTriangles += chunk.indexCount / 3;
        }
    }
    // Every triangle of the ground and of the tilted square is in a flat chunk of its own plane; the cube's
    // and the strip's are in none (the strip's two flat halves are one part, which is not flat).
    EXPECT_EQ(groundTriangles, 128u);
    EXPECT_EQ(tiltedTriangles, 2u);
    std::size_t unplanarOpenTriangles = 0;
    for (const engine::MeshChunk& chunk : chunked.chunks) {
        if (!chunk.plane && chunk.closure == engine::SurfaceClosure::Open) {
            unplanarOpenTriangles += chunk.indexCount / 3;
        }
    }
    EXPECT_EQ(unplanarOpenTriangles, strip.triangleCount());
}

TEST(MeshChunksTest, FlatPartsOnOnePlaneShareChunksAndOthersDoNot) {
    // Two squares on y = 0 apart (two parts), and one on a plane 0.1 rad off it, between them.
    engine::MeshData mesh = testsupport::merged(engine::primitives::plane(1.0f),
                                                engine::primitives::plane(1.0f), glm::vec3(6, 0, 0));
    mesh = testsupport::merged(
        mesh, engine::primitives::plane(1.0f),
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(3, 0, 0)), 0.1f, glm::vec3(0, 0, 1)));
    const engine::ChunkedMesh chunked = engine::splitIntoChunks(mesh);
    ASSERT_EQ(chunked.chunks.size(), 2u);
    EXPECT_EQ(chunked.chunks[0].indexCount, 12u); // the two on y = 0, in their order
    EXPECT_EQ(chunked.chunks[1].indexCount, 6u);
    for (const engine::MeshChunk& chunk : chunked.chunks) {
        ASSERT_TRUE(chunk.plane.has_value());
    }
    EXPECT_NEAR(std::abs(chunked.chunks[0].plane->y), 1.0f, 1e-6f);
    EXPECT_NEAR(std::abs(chunked.chunks[1].plane->y), std::cos(0.1f), 1e-6f);
}

TEST(MeshChunksTest, ZeroLimitMeansOneTrianglePerChunk) {
    const engine::MeshData cube = engine::primitives::cube(1.0f);
    EXPECT_EQ(engine::splitIntoChunks(cube, {0}).chunks.size(), cube.triangleCount());
}

} // namespace
