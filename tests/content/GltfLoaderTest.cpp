#include <content/ContentError.h>
#include <content/GltfLoader.h>

#include <engine/Primitives.h>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace content;

namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t chunk = (bytes[i] << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                                    (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += alphabet[(chunk >> 18) & 63];
        out += alphabet[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[chunk & 63] : '=';
    }
    return out;
}

template <typename T>
void appendBytes(std::vector<unsigned char>& buffer, const T& value) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    buffer.insert(buffer.end(), bytes, bytes + sizeof(T));
}

/// A one-triangle glTF whose fields can be overridden to make it broken in one precise way.
struct TriangleGltf {
    std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::vector<std::uint16_t> indices{0, 1, 2};
    std::string positionCount = "3";
    std::string indexCount = "3";
    std::string positionViewLength = "36";
    std::string extraNodeFields;
    std::string extraTopLevel;

    std::string json() const {
        std::vector<unsigned char> buffer;
        for (const auto& p : positions) {
            appendBytes(buffer, p);
        }
        for (auto i : indices) {
            appendBytes(buffer, i);
        }
        return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
               R"("nodes":[{"name":"tri","mesh":0)" +
               extraNodeFields +
               R"(}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)" +
               R"("buffers":[{"byteLength":)" + std::to_string(buffer.size()) +
               R"(,"uri":"data:application/octet-stream;base64,)" + base64(buffer) + R"("}],)" +
               R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" + positionViewLength +
               R"(},{"buffer":0,"byteOffset":36,"byteLength":6}],)" +
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" + positionCount +
               R"(,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":)" +
               indexCount + R"(,"type":"SCALAR"}])" + extraTopLevel + "}";
    }
};

class GltfTest : public testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() /
                  ("gs_gltf_" + std::to_string(::getpid()) + "_" +
                   testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(folder_);
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const auto path = folder_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    std::filesystem::path folder_;
};

std::string loadError(const std::filesystem::path& path) {
    try {
        (void)GltfLoader::load(path);
    } catch (const ContentError& error) {
        return error.what();
    }
    return "(loaded)";
}

} // namespace

TEST_F(GltfTest, LoadsEmbeddedTriangle) {
    const LoadedScene loaded = GltfLoader::load(write("tri.gltf", TriangleGltf{}.json()));
    ASSERT_EQ(loaded.scene.size(), 1u);
    const auto& mesh = *loaded.scene.entity(0).mesh->mesh;
    EXPECT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_TRUE(mesh.normals.empty()); // none in the file: the renderer shades faceted
    EXPECT_EQ(loaded.scene.entity(0).name, "tri");
}

struct BadGltfCase {
    const char* name;
    std::function<std::string()> text;
    const char* expected;
};

class GltfBadInputTest : public GltfTest, public testing::WithParamInterface<BadGltfCase> {};

TEST_P(GltfBadInputTest, FailsWithMessageNamingFileAndField) {
    const auto path = write("bad.gltf", GetParam().text());
    const std::string message = loadError(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GltfBadInputTest,
    testing::Values(BadGltfCase{"garbled", [] { return std::string("{\"asset\": [[[ nonsense"); },
                                "not a valid glTF 2.0 file"},
                    BadGltfCase{"truncated",
                                [] {
                                    const std::string text = TriangleGltf{}.json();
                                    return text.substr(0, text.size() / 2);
                                },
                                "not a valid glTF 2.0 file"},
                    BadGltfCase{"empty", [] { return std::string(); }, "not a valid glTF 2.0 file"},
                    BadGltfCase{"accessorOutOfBounds",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.positionCount = "4";
                                    return gltf.json();
                                },
                                "accessor out of bounds"},
                    BadGltfCase{"absurdCount",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.indexCount = "4000000000";
                                    return gltf.json();
                                },
                                "accessors[1]"},
                    BadGltfCase{"viewBeyondBuffer",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.positionViewLength = "4096";
                                    return gltf.json();
                                },
                                "beyond its buffer"},
                    BadGltfCase{"indexOutOfRange",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.indices = {0, 1, 7};
                                    return gltf.json();
                                },
                                "indices[2] = 7 is out of range"},
                    BadGltfCase{"nanPosition",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.positions[1].y = std::nanf("");
                                    return gltf.json();
                                },
                                "POSITION vertex 1 is not finite"},
                    BadGltfCase{"badSubdivisionLevel",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.extraNodeFields = R"(,"extras":{"subdivision":{"level":9}})";
                                    return gltf.json();
                                },
                                "nodes[0].extras.subdivision.level must be an integer in [0, 6]"},
                    BadGltfCase{"badSubdivisionScheme",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.extraNodeFields =
                                        R"(,"extras":{"subdivision":{"scheme":"doo-sabin"}})";
                                    return gltf.json();
                                },
                                "scheme must be \"catmull-clark\" or \"loop\""},
                    BadGltfCase{"missingCageFile",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.extraNodeFields =
                                        R"(,"extras":{"subdivision":{"cage":"nowhere.obj"}})";
                                    return gltf.json();
                                },
                                "nowhere.obj"},
                    BadGltfCase{"badNodeScale",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.extraNodeFields = R"(,"scale":[1,2])";
                                    return gltf.json();
                                },
                                "nodes[0].scale must hold 3 finite numbers"},
                    BadGltfCase{"missingLight",
                                [] {
                                    TriangleGltf gltf;
                                    gltf.extraNodeFields =
                                        R"(,"extensions":{"KHR_lights_punctual":{"light":3}})";
                                    return gltf.json();
                                },
                                "light 3 does not exist"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST_F(GltfTest, MissingFileIsNamed) {
    const auto path = folder_ / "absent.gltf";
    EXPECT_EQ(loadError(path), path.string() + ": file not found");
}

TEST_F(GltfTest, TruncatedGlbIsRejected) {
    engine::Scene scene;
    const auto id = scene.create("cube");
    scene.entity(id).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::cube())};
    const auto path = folder_ / "cube.glb";
    GltfWriter::save(scene, path);
    const auto size = std::filesystem::file_size(path);
    std::filesystem::resize_file(path, size / 2);
    EXPECT_NE(loadError(path).find("not a valid glTF 2.0 file"), std::string::npos) << loadError(path);
}

TEST_F(GltfTest, PointLightsAreLeftOutWithAWarning) {
    TriangleGltf gltf;
    gltf.extraNodeFields = R"(,"extensions":{"KHR_lights_punctual":{"light":0}})";
    gltf.extraTopLevel =
        R"(,"extensionsUsed":["KHR_lights_punctual"],)"
        R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","name":"bulb"}]}})";
    const LoadedScene loaded = GltfLoader::load(write("point.gltf", gltf.json()));
    EXPECT_FALSE(loaded.scene.entity(0).light);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("'bulb') is a point light"), std::string::npos) << loaded.warnings[0];
}

class GltfRoundTripTest : public GltfTest, public testing::WithParamInterface<const char*> {};

TEST_P(GltfRoundTripTest, PreservesGeometryHierarchyCamerasAndLights) {
    engine::Scene scene;
    const auto root = scene.create("root");
    scene.entity(root).transform.translation = {1, 2, 3};
    scene.entity(root).transform.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 1, 0)));
    auto sphere = std::make_shared<engine::MeshData>(engine::primitives::sphere(0.5f, 6, 8));
    sphere->material.baseColor = {0.1f, 0.5f, 0.9f};
    sphere->material.shininess = 64.0f;
    const auto ball = scene.create("ball", root);
    scene.entity(ball).mesh = engine::MeshComponent{sphere};
    scene.entity(ball).transform.scale = {2, 2, 2};
    const auto sun = scene.create("sun");
    scene.entity(sun).light = engine::LightComponent{};
    scene.entity(sun).light->intensity = 3.0f;
    scene.entity(sun).light->castsShadows = false;
    const auto spot = scene.create("spot");
    scene.entity(spot).light =
        engine::LightComponent{engine::LightType::Spot, {1, 0.5f, 0.25f}, 7.0f, true, 20.0f, 0.2f, 0.4f};
    const auto camera = scene.create("camera");
    scene.entity(camera).camera = engine::CameraComponent{};
    scene.entity(camera).camera->verticalFov = 0.9f;

    const auto path = folder_ / (std::string("scene") + GetParam());
    GltfWriter::save(scene, path);
    const LoadedScene loaded = GltfLoader::load(path);
    ASSERT_EQ(loaded.scene.size(), scene.size());
    EXPECT_TRUE(loaded.warnings.empty());

    const auto& mesh = *loaded.scene.entity(ball).mesh->mesh;
    EXPECT_EQ(mesh.positions, sphere->positions);
    EXPECT_EQ(mesh.indices, sphere->indices);
    ASSERT_EQ(mesh.normals.size(), sphere->normals.size());
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        EXPECT_LT(glm::length(mesh.normals[i] - sphere->normals[i]), 1e-6f);
    }
    EXPECT_LT(glm::length(mesh.material.baseColor - sphere->material.baseColor), 1e-6f);
    EXPECT_NEAR(mesh.material.shininess, 64.0f, 0.01f);
    EXPECT_EQ(loaded.scene.entity(ball).parent, root);
    const glm::mat4 before = scene.worldMatrix(ball);
    const glm::mat4 after = loaded.scene.worldMatrix(ball);
    for (int c = 0; c < 4; ++c) {
        EXPECT_LT(glm::length(before[c] - after[c]), 1e-5f);
    }
    ASSERT_TRUE(loaded.scene.entity(sun).light);
    EXPECT_EQ(loaded.scene.entity(sun).light->type, engine::LightType::Directional);
    EXPECT_FALSE(loaded.scene.entity(sun).light->castsShadows);
    const auto& spotLight = *loaded.scene.entity(spot).light;
    EXPECT_EQ(spotLight.type, engine::LightType::Spot);
    EXPECT_FLOAT_EQ(spotLight.intensity, 7.0f);
    EXPECT_FLOAT_EQ(spotLight.range, 20.0f);
    EXPECT_FLOAT_EQ(spotLight.outerConeAngle, 0.4f);
    EXPECT_EQ(spotLight.color, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(loaded.scene.entity(camera).camera->verticalFov, 0.9f);
}

INSTANTIATE_TEST_SUITE_P(Formats, GltfRoundTripTest, testing::Values(".gltf", ".glb"),
                         [](const auto& test) { return std::string(test.param + 1); });
