// surfaceParts: which parts of a mesh are closed and which way they wind, on welded positions, and
// hiddenFace: the face a pass may leave out of a closed part, checked against each triangle's facing.
#include <engine/Primitives.h>
#include <engine/SurfaceClosure.h>

#include "../support/TestMeshes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace {

using engine::MeshData;
using engine::SurfaceClosure;
using testsupport::merged;

MeshData reversed(MeshData mesh) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
    return mesh;
}

std::vector<SurfaceClosure> closures(const MeshData& mesh) {
    const engine::SurfaceParts parts = engine::surfaceParts(mesh);
    EXPECT_EQ(parts.triangleParts.size(), mesh.triangleCount());
    std::vector<SurfaceClosure> result;
    for (const auto& part : parts.parts) {
        result.push_back(part.closure);
    }
    return result;
}

TEST(SurfaceParts, ACubeSplitForItsNormalsIsOneOutwardPart) {
    const MeshData cube = engine::primitives::cube(2.0f); // 24 positions, 8 points
    const engine::SurfaceParts parts = engine::surfaceParts(cube);
    ASSERT_EQ(parts.parts.size(), 1u);
    EXPECT_EQ(parts.parts[0].closure, SurfaceClosure::Outward);
    EXPECT_EQ(parts.parts[0].bounds.min, glm::vec3(-1.0f));
    EXPECT_EQ(parts.parts[0].bounds.max, glm::vec3(1.0f));
}

TEST(SurfaceParts, ASphereWhosePolesCollapseTrianglesIsOutward) {
    // The primitive computes its seam and poles once per segment, with rounding: put each at one point.
    constexpr int kRings = 12;
    constexpr int kSegments = 24;
    MeshData sphere = engine::primitives::sphere(1.0f, kRings, kSegments);
    for (const SurfaceClosure closure : closures(sphere)) {
        EXPECT_EQ(closure, SurfaceClosure::Open) << "a seam rounded apart is a crack";
    }
    for (int r = 0; r <= kRings; ++r) {
        for (int s = 0; s <= kSegments; ++s) {
            glm::vec3& p = sphere.positions[static_cast<std::size_t>(r * (kSegments + 1) + s)];
            p = r == 0 ? glm::vec3(0, 1, 0) : r == kRings ? glm::vec3(0, -1, 0) : p;
            if (s == kSegments) {
                p = sphere.positions[static_cast<std::size_t>(r * (kSegments + 1))];
            }
        }
    }
    EXPECT_EQ(closures(sphere), (std::vector<SurfaceClosure>{SurfaceClosure::Open, SurfaceClosure::Outward}))
        << "the poles' degenerate triangles form an open part of their own, covering nothing";
}

TEST(SurfaceParts, ReversedWindingIsInward) {
    EXPECT_EQ(closures(reversed(engine::primitives::cube())),
              std::vector<SurfaceClosure>{SurfaceClosure::Inward});
}

TEST(SurfaceParts, EachPartIsJudgedAlone) {
    MeshData mesh =
        merged(engine::primitives::cube(), reversed(engine::primitives::cube()), glm::vec3(3.0f, 0, 0));
    MeshData holed = engine::primitives::cube();
    holed.indices.resize(holed.indices.size() - 3);
    mesh = merged(mesh, holed, glm::vec3(6.0f, 0, 0));
    mesh = merged(mesh, engine::primitives::plane(1.0f), glm::vec3(9.0f, 0, 0));
    EXPECT_EQ(closures(mesh), (std::vector<SurfaceClosure>{SurfaceClosure::Outward, SurfaceClosure::Inward,
                                                           SurfaceClosure::Open, SurfaceClosure::Open}));
}

TEST(SurfaceParts, OneFlippedTriangleOpensItsPart) {
    MeshData cube = engine::primitives::cube();
    std::swap(cube.indices[1], cube.indices[2]);
    EXPECT_EQ(closures(cube), std::vector<SurfaceClosure>{SurfaceClosure::Open});
}

TEST(SurfaceParts, FacesBackToBackEncloseNoVolume) {
    const MeshData plane = engine::primitives::plane(1.0f);
    EXPECT_EQ(closures(merged(plane, reversed(plane), glm::vec3(0.0f))),
              std::vector<SurfaceClosure>{SurfaceClosure::Open});
}

TEST(SurfaceParts, FarFromTheOriginTheVolumeKeepsItsSign) {
    MeshData cube = engine::primitives::cube(0.5f);
    for (glm::vec3& p : cube.positions) {
        p += glm::vec3(1.0e4f, -2.0e4f, 3.0e4f); // a float's step there: 0.002
    }
    EXPECT_EQ(closures(cube), std::vector<SurfaceClosure>{SurfaceClosure::Outward});
}

TEST(SurfaceParts, MalformedInputIsOpen) {
    MeshData outOfRange = engine::primitives::cube();
    outOfRange.indices[4] = 1000;
    EXPECT_EQ(closures(outOfRange), std::vector<SurfaceClosure>{SurfaceClosure::Open});
    MeshData notFinite = engine::primitives::cube();
    notFinite.positions[0].x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(closures(notFinite), std::vector<SurfaceClosure>{SurfaceClosure::Open});
    EXPECT_TRUE(engine::surfaceParts(MeshData{}).triangleParts.empty());
}

/// For each triangle of `mesh` drawn through `clipFromModel` seen from `eye` (model space): whether GL would
/// keep it with `culled` culled (counter-clockwise front faces), against whether it faces the eye.
void expectKeepsExactlyTheFacesTurnedToTheEye(const MeshData& mesh, const glm::mat4& clipFromModel,
                                              const glm::vec3& eye, GLenum culled, bool outward) {
    ASSERT_NE(culled, static_cast<GLenum>(GL_NONE));
    int kept = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::vec2 window[3];
        glm::vec3 corner[3];
        for (int k = 0; k < 3; ++k) {
            corner[k] = mesh.positions[mesh.indices[t + static_cast<std::size_t>(k)]];
            const glm::vec4 clip = clipFromModel * glm::vec4(corner[k], 1.0f);
            window[k] = glm::vec2(clip) / clip.w;
        }
        const glm::vec2 u = window[1] - window[0];
        const glm::vec2 v = window[2] - window[0];
        const float area = u.x * v.y - u.y * v.x;
        const glm::vec3 normal = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
        const float facing = glm::dot(normal, eye - corner[0]) * (outward ? 1.0f : -1.0f);
        if (std::abs(area) < 1e-6f || std::abs(facing) < 1e-6f) {
            continue; // edge-on
        }
        const bool front = area > 0.0f;
        const bool keeps = culled == GL_BACK ? front : !front;
        EXPECT_EQ(keeps, facing > 0.0f) << "triangle " << t / 3;
        kept += keeps;
    }
    EXPECT_GT(kept, 0);
}

TEST(HiddenFace, LeavesOutExactlyTheFacesTurnedAwayFromTheViewpoint) {
    const MeshData sphere = engine::primitives::sphere(1.0f, 8, 16);
    const engine::Aabb bounds{glm::vec3(-1.0f), glm::vec3(1.0f)};
    const glm::vec3 eye(3.0f, 2.0f, 4.0f);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const glm::mat4 perspective = glm::perspective(0.8f, 1.3f, 0.1f, 100.0f);
    const glm::mat4 orthographic = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.5f, 20.0f);
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
    for (const glm::mat4& projection : {perspective, orthographic}) {
        for (const bool mirrored : {false, true}) {
            const glm::mat4 model = mirrored ? mirror : glm::mat4(1.0f);
            const glm::mat4 clipFromModel = projection * view * model;
            const glm::vec3 eyeInModel = glm::vec3(glm::inverse(model) * glm::vec4(eye, 1.0f));
            for (const SurfaceClosure closure : {SurfaceClosure::Outward, SurfaceClosure::Inward}) {
                const bool outward = closure == SurfaceClosure::Outward;
                const MeshData mesh = outward ? sphere : reversed(sphere);
                const GLenum face = engine::hiddenFace(closure, bounds, clipFromModel);
                EXPECT_EQ(face, static_cast<GLenum>(outward != mirrored ? GL_BACK : GL_FRONT));
                // An orthographic view sees along its axis: its eye is far back along it.
                const glm::vec3 viewpoint = projection == perspective ? eyeInModel : eyeInModel * 1.0e4f;
                expectKeepsExactlyTheFacesTurnedToTheEye(mesh, clipFromModel, viewpoint, face, outward);
            }
        }
    }
}

TEST(HiddenFace, NothingWhereTheViewpointMaySeeInsideOrThePartIsOpen) {
    const engine::Aabb bounds{glm::vec3(-1.0f), glm::vec3(1.0f)};
    const glm::mat4 perspective = glm::perspective(0.8f, 1.3f, 0.1f, 100.0f);
    const auto from = [](const glm::vec3& eye) {
        return glm::lookAt(eye, glm::vec3(0.0f, 0.0f, -10.0f), glm::vec3(0, 1, 0));
    };
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Outward, bounds, perspective * from(glm::vec3(0, 0, 5))),
              static_cast<GLenum>(GL_BACK));
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Open, bounds, perspective * from(glm::vec3(0, 0, 5))),
              static_cast<GLenum>(GL_NONE));
    EXPECT_EQ(
        engine::hiddenFace(SurfaceClosure::Outward, engine::Aabb{}, perspective * from(glm::vec3(0, 0, 5))),
        static_cast<GLenum>(GL_NONE));
    // Inside, and just outside but within the near plane's reach, which would cut the part open.
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Outward, bounds, perspective * from(glm::vec3(0.0f))),
              static_cast<GLenum>(GL_NONE));
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Inward, bounds, perspective * from(glm::vec3(0, 0, 1.05f))),
              static_cast<GLenum>(GL_NONE));
    // Behind the viewpoint.
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Outward, bounds, perspective * from(glm::vec3(0, 0, -5))),
              static_cast<GLenum>(GL_NONE));
    // An orthographic view whose near plane cuts the part.
    const glm::mat4 orthographic = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 4.5f, 20.0f);
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Outward, bounds, orthographic * from(glm::vec3(0, 0, 5))),
              static_cast<GLenum>(GL_NONE));
    const glm::mat4 degenerate(0.0f);
    EXPECT_EQ(engine::hiddenFace(SurfaceClosure::Outward, bounds, degenerate), static_cast<GLenum>(GL_NONE));
}

} // namespace
