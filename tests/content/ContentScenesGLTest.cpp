// Every scene under content/scenes loads, refines its subdivision surfaces and renders headless.
#include "../engine/GLTestContext.h"

#include <content/GltfLoader.h>

#include <engine/Engine.h>
#include <engine/LightAim.h>
#include <engine/RenderTarget.h>

#include <glm/gtc/matrix_inverse.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

const std::filesystem::path kScenes = std::filesystem::path(CONTENT_DIR) / "scenes";

struct SceneCase {
    const char* name;
    std::size_t subdivided; // entities whose mesh is a subdivision surface
    std::size_t triangles;  // drawn at least (the soft-shadow scenes are a few boxes)
};

const SceneCase kScenesExpected[] = {
    {"knob", 1, 500},        {"torus", 1, 500},         {"bowl", 1, 500},        {"thin-shell", 2, 500},
    {"crease-cube", 1, 500}, {"grazing-plane", 2, 500}, {"spheres", 16, 500},    {"room", 1, 500},
    {"outdoor", 0, 500},     {"soft-contact", 0, 12},   {"soft-overlap", 0, 24}, {"soft-fence", 0, 150}};

class ContentScenesGLTest : public testing::TestWithParam<SceneCase> {};

} // namespace

TEST(ContentScenesTest, EverySceneFileIsCovered) {
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
        files += entry.path().extension() == ".gltf";
    }
    EXPECT_EQ(files, std::size(kScenesExpected));
}

TEST_P(ContentScenesGLTest, LoadsWithCameraShadowCastingLightAndSmoothNormals) {
    const content::LoadedScene loaded =
        content::GltfLoader::load(kScenes / (std::string(GetParam().name) + ".gltf"));
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_TRUE(loaded.scene.firstCamera());
    std::size_t castingLights = 0;
    loaded.scene.forEach([&](engine::EntityId, const engine::Entity& e) {
        castingLights += e.light && e.light->castsShadows;
    });
    EXPECT_GE(castingLights, 1u);
    ASSERT_EQ(loaded.subdivided.size(), GetParam().subdivided);
    for (const auto& [entity, tag] : loaded.subdivided) {
        const engine::MeshData& mesh = *loaded.scene.entity(entity).mesh->mesh;
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        // Smooth, not faceted: vertices are shared between triangles (one normal each, unit length), and on
        // average a corner's limit normal stays close to its triangle's own normal.
        EXPECT_LT(mesh.positions.size(), mesh.indices.size() / 2) << mesh.name;
        double dotSum = 0.0;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 a = mesh.positions[mesh.indices[t]];
            const glm::vec3 face = glm::normalize(
                glm::cross(mesh.positions[mesh.indices[t + 1]] - a, mesh.positions[mesh.indices[t + 2]] - a));
            for (int corner = 0; corner < 3; ++corner) {
                const glm::vec3 normal = mesh.normals[mesh.indices[t + corner]];
                EXPECT_NEAR(glm::length(normal), 1.0f, 1e-4f);
                dotSum += glm::dot(face, normal);
            }
        }
        EXPECT_GT(dotSum / static_cast<double>(mesh.indices.size()), std::cos(glm::radians(12.0)))
            << mesh.name;
    }
}

TEST_P(ContentScenesGLTest, RendersTheSceneNotJustTheBackground) {
    glTestContext();
    const content::LoadedScene loaded =
        content::GltfLoader::load(kScenes / (std::string(GetParam().name) + ".gltf"));
    engine::Engine engine;
    engine.renderer().environment.background = glm::vec3(0.0f);
    engine::RenderTarget target({128, 96});
    const engine::FrameStats stats = engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    EXPECT_GE(stats.triangles, GetParam().triangles);
    const engine::Image image = target.readPixels();
    std::size_t covered = 0;
    for (int y = 0; y < image.size.y; ++y) {
        for (int x = 0; x < image.size.x; ++x) {
            const glm::u8vec4 p = image.at(x, y);
            covered += (p.r | p.g | p.b) != 0;
        }
    }
    EXPECT_GT(covered, static_cast<std::size_t>(image.size.x * image.size.y) / 4);
}

namespace {

content::LoadedScene loadScene(const char* name) {
    return content::GltfLoader::load(kScenes / (std::string(name) + ".gltf"));
}

std::size_t triangles(const engine::Scene& scene) {
    std::size_t count = 0;
    scene.forEach([&](engine::EntityId, const engine::Entity& e) {
        count += e.mesh && e.mesh->mesh ? e.mesh->mesh->triangleCount() : 0;
    });
    return count;
}

} // namespace

TEST(ContentScenesTest, RoomIsAClosedRoomLitByTwoPointLightsWithARange) {
    const content::LoadedScene loaded = loadScene("room");
    const engine::Scene& scene = loaded.scene;
    std::size_t pointLights = 0;
    std::size_t otherLights = 0;
    scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
        if (!e.light) {
            return;
        }
        if (e.light->type != engine::LightType::Point) {
            ++otherLights;
            return;
        }
        ++pointLights;
        EXPECT_GT(e.light->range, 5.0f) << e.name;
        EXPECT_TRUE(std::isfinite(e.light->range)) << e.name;
        EXPECT_GT(e.light->intensity, 0.0f) << e.name;
        // Under the ceiling, inside the room.
        const glm::vec3 at(scene.worldMatrix(id)[3]);
        EXPECT_GT(at.y, 2.0f) << e.name;
        EXPECT_LT(at.y, 3.0f) << e.name;
    });
    EXPECT_EQ(pointLights, 2u);
    EXPECT_EQ(otherLights, 0u);
    // About 8 x 3 x 6 m, closed: the camera stands inside the walls' box.
    const engine::Aabb bounds = engine::meshBounds(scene);
    EXPECT_NEAR(bounds.max.x - bounds.min.x, 8.0f, 0.01f);
    EXPECT_NEAR(bounds.max.y - bounds.min.y, 3.0f, 0.01f);
    EXPECT_NEAR(bounds.max.z - bounds.min.z, 6.0f, 0.01f);
    const glm::vec3 eye(scene.worldMatrix(*scene.firstCamera())[3]);
    EXPECT_TRUE(glm::all(glm::greaterThan(eye, bounds.min)) && glm::all(glm::lessThan(eye, bounds.max)));
    EXPECT_LT(triangles(scene), 30000u);
}

TEST(ContentScenesTest, OutdoorSpansKilometresAndTheCameraSeesAllOfIt) {
    const content::LoadedScene loaded = loadScene("outdoor");
    const engine::Scene& scene = loaded.scene;
    const engine::Aabb bounds = engine::meshBounds(scene);
    EXPECT_GT(bounds.max.x - bounds.min.x, 3000.0f);
    EXPECT_GT(bounds.max.z - bounds.min.z, 3000.0f);
    const engine::EntityId camera = *scene.firstCamera();
    const engine::CameraComponent& lens = *scene.entity(camera).camera;
    const glm::vec3 eye(scene.worldMatrix(camera)[3]);
    // The far plane reaches every corner of the scene's box; the near plane suits things at arm's length.
    for (const glm::vec3& corner : bounds.corners()) {
        EXPECT_LT(glm::length(corner - eye), lens.farPlane);
    }
    EXPECT_LE(lens.nearPlane, 0.5f);
    std::size_t suns = 0;
    scene.forEach([&](engine::EntityId id, const engine::Entity& e) {
        if (e.light) {
            ASSERT_EQ(e.light->type, engine::LightType::Directional) << e.name;
            ++suns;
            const glm::vec3 toSun = glm::normalize(glm::vec3(scene.worldMatrix(id)[2]));
            const float elevation = glm::degrees(std::asin(toSun.y));
            EXPECT_GE(elevation, 25.0f);
            EXPECT_LE(elevation, 35.0f);
        }
    });
    EXPECT_EQ(suns, 1u);
    // Many meshes (ground tiles and objects), so passes can cull; small enough for llvmpipe.
    std::size_t meshes = 0;
    scene.forEach([&](engine::EntityId, const engine::Entity& e) { meshes += e.mesh.has_value(); });
    EXPECT_GT(meshes, 500u);
    EXPECT_LT(triangles(scene), 150000u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ContentScenesGLTest, testing::ValuesIn(kScenesExpected),
                         [](const auto& test) {
                             std::string name = test.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });
