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

/// One member of the triangle given the wrong JSON type: `from` replaced by `to` in the document.
struct WrongTypeCase {
    const char* name;
    const char* from;
    const char* to;
    const char* expected;
};

class GltfWrongTypeTest : public GltfTest, public testing::WithParamInterface<WrongTypeCase> {};

TEST_P(GltfWrongTypeTest, RefusedNamingTheMemberPath) {
    TriangleGltf gltf;
    gltf.extraNodeFields = R"(,"translation":[0,0,0])";
    gltf.extraTopLevel =
        R"(,"materials":[{"doubleSided":true}],)"
        R"("cameras":[{"type":"perspective","perspective":{"yfov":0.8,"znear":0.1}}],)"
        R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"directional","intensity":1}]}})";
    std::string text = gltf.json();
    const auto at = text.find(GetParam().from);
    ASSERT_NE(at, std::string::npos) << GetParam().from;
    text.replace(at, std::strlen(GetParam().from), GetParam().to);
    EXPECT_EQ(loadError(write("good.gltf", gltf.json())), "(loaded)");
    const auto path = write("wrong.gltf", text);
    EXPECT_EQ(loadError(path), path.string() + ": " + GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Members, GltfWrongTypeTest,
    testing::Values(WrongTypeCase{"objectForArray",
                                  R"("primitives":[{"attributes":{"POSITION":0},"indices":1}])",
                                  R"("primitives":{"attributes":{"POSITION":0},"indices":1})",
                                  "meshes[0].primitives: expected an array"},
                    WrongTypeCase{"arrayForObject", R"("attributes":{"POSITION":0})", R"("attributes":[0])",
                                  "meshes[0].primitives[0].attributes: expected an object"},
                    WrongTypeCase{"stringForIndex", R"("mesh":0)", R"("mesh":"0")",
                                  "nodes[0].mesh: expected a non-negative integer"},
                    WrongTypeCase{"negativeIndex", R"("scene":0)", R"("scene":-1)",
                                  "scene: expected a non-negative integer"},
                    WrongTypeCase{"stringForNumber", R"("translation":[0,0,0])", R"("translation":[0,"1",0])",
                                  "nodes[0].translation[1]: expected a number"},
                    WrongTypeCase{"numberForString", R"("type":"VEC3")", R"("type":3)",
                                  "accessors[0].type: expected a string"},
                    WrongTypeCase{"stringForBoolean", R"("doubleSided":true)", R"("doubleSided":"yes")",
                                  "materials[0].doubleSided: expected a boolean"},
                    WrongTypeCase{"numberForObject", R"("perspective":{"yfov":0.8,"znear":0.1})",
                                  R"("perspective":4)", "cameras[0].perspective: expected an object"},
                    WrongTypeCase{"objectForNumber", R"("intensity":1)", R"("intensity":{})",
                                  "extensions.KHR_lights_punctual.lights[0].intensity: expected a number"},
                    WrongTypeCase{"missingRequired", R"("componentType":5126,)", "",
                                  "accessors[0].componentType: required member is missing"}),
    [](const testing::TestParamInfo<WrongTypeCase>& wrong) { return std::string(wrong.param.name); });

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

TEST_F(GltfTest, UnknownLightTypesAreLeftOutWithAWarning) {
    TriangleGltf gltf;
    gltf.extraNodeFields = R"(,"extensions":{"KHR_lights_punctual":{"light":0}})";
    gltf.extraTopLevel =
        R"(,"extensionsUsed":["KHR_lights_punctual"],)"
        R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"area","name":"panel"}]}})";
    const LoadedScene loaded = GltfLoader::load(write("area.gltf", gltf.json()));
    EXPECT_FALSE(loaded.scene.entity(0).light);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("light 0 ('panel') has the unknown type 'area'"), std::string::npos)
        << loaded.warnings[0];
}

/// A KHR_lights_punctual light as written in a file, and what the loader makes of it.
struct LightCase {
    const char* name;
    const char* light; // the light's JSON object
    engine::LightType type;
    float range;
};

class GltfLightTest : public GltfTest, public testing::WithParamInterface<LightCase> {};

TEST_P(GltfLightTest, LoadsTypeAndRange) {
    TriangleGltf gltf;
    gltf.extraNodeFields = R"(,"translation":[1,2,3],"extensions":{"KHR_lights_punctual":{"light":0}})";
    gltf.extraTopLevel = std::string(R"(,"extensionsUsed":["KHR_lights_punctual"],)") +
                         R"("extensions":{"KHR_lights_punctual":{"lights":[)" + GetParam().light + "]}}";
    const LoadedScene loaded = GltfLoader::load(write("light.gltf", gltf.json()));
    EXPECT_TRUE(loaded.warnings.empty());
    const engine::Entity& entity = loaded.scene.entity(0);
    ASSERT_TRUE(entity.light);
    EXPECT_EQ(entity.light->type, GetParam().type);
    EXPECT_FLOAT_EQ(entity.light->range, GetParam().range);
    EXPECT_EQ(entity.transform.translation, glm::vec3(1, 2, 3));
}

INSTANTIATE_TEST_SUITE_P(
    Lights, GltfLightTest,
    testing::Values(
        LightCase{"point", R"({"type":"point","intensity":5,"range":10})", engine::LightType::Point, 10.0f},
        // Without range a point light reaches everywhere (range 0 = unlimited).
        LightCase{"pointUnlimited", R"({"type":"point"})", engine::LightType::Point, 0.0f},
        LightCase{"spot", R"({"type":"spot","range":0.5,"spot":{}})", engine::LightType::Spot, 0.5f},
        // A sun has no distance: KHR_lights_punctual gives range to point and spot lights only.
        LightCase{"directionalIgnoresRange", R"({"type":"directional","range":-3})",
                  engine::LightType::Directional, 0.0f}),
    [](const auto& test) { return std::string(test.param.name); });

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
    scene.entity(sun).light->angularDiameter = 0.02f;
    const auto spot = scene.create("spot");
    scene.entity(spot).light = engine::LightComponent{engine::LightType::Spot,
                                                      {1, 0.5f, 0.25f},
                                                      7.0f,
                                                      true,
                                                      20.0f,
                                                      0.2f,
                                                      0.4f,
                                                      engine::LightComponent::kSunAngularDiameter,
                                                      0.3f};
    const auto bulb = scene.create("bulb");
    engine::LightComponent point;
    point.type = engine::LightType::Point;
    point.color = {0.9f, 0.8f, 0.7f};
    point.intensity = 12.0f;
    point.range = 9.5f;
    scene.entity(bulb).light = point;
    scene.entity(bulb).transform.translation = {-1, 2.5f, 0.5f};
    const auto unlimited = scene.create("unlimited bulb");
    point.range = 0.0f;
    scene.entity(unlimited).light = point;
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
    EXPECT_FLOAT_EQ(loaded.scene.entity(sun).light->angularDiameter, 0.02f);
    const auto& spotLight = *loaded.scene.entity(spot).light;
    EXPECT_EQ(spotLight.type, engine::LightType::Spot);
    EXPECT_FLOAT_EQ(spotLight.intensity, 7.0f);
    EXPECT_FLOAT_EQ(spotLight.range, 20.0f);
    EXPECT_FLOAT_EQ(spotLight.outerConeAngle, 0.4f);
    EXPECT_EQ(spotLight.color, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(spotLight.radius, 0.3f);
    const auto& bulbLight = *loaded.scene.entity(bulb).light;
    EXPECT_EQ(bulbLight.type, engine::LightType::Point);
    EXPECT_FLOAT_EQ(bulbLight.intensity, 12.0f);
    EXPECT_FLOAT_EQ(bulbLight.range, 9.5f);
    EXPECT_EQ(bulbLight.color, glm::vec3(0.9f, 0.8f, 0.7f));
    EXPECT_EQ(loaded.scene.entity(bulb).transform.translation, glm::vec3(-1, 2.5f, 0.5f));
    ASSERT_TRUE(loaded.scene.entity(unlimited).light);
    EXPECT_EQ(loaded.scene.entity(unlimited).light->type, engine::LightType::Point);
    EXPECT_FLOAT_EQ(loaded.scene.entity(unlimited).light->range, 0.0f);
    EXPECT_FLOAT_EQ(loaded.scene.entity(camera).camera->verticalFov, 0.9f);
}

INSTANTIATE_TEST_SUITE_P(Formats, GltfRoundTripTest, testing::Values(".gltf", ".glb"),
                         [](const auto& test) { return std::string(test.param + 1); });

namespace {

/// Four vertices of a unit quad in XY, interleaved position+normal (24-byte stride).
std::vector<unsigned char> interleavedQuad() {
    std::vector<unsigned char> bytes;
    const glm::vec3 normal(0, 0, 1);
    for (const glm::vec3 p :
         {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)}) {
        appendBytes(bytes, p);
        appendBytes(bytes, normal);
    }
    return bytes;
}

/// A glTF with one quad mesh drawn as `mode` from `indices` stored as `componentType`, with its buffer in an
/// external .bin file.
std::string quadGltf(int mode, int componentType, std::size_t indexCount, std::size_t indexBytes,
                     const std::string& nodeFields) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
           R"("nodes":[{"name":"quad","mesh":0)" +
           nodeFields +
           R"(}],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2,"mode":)" +
           std::to_string(mode) + R"(}]}],"buffers":[{"byteLength":)" + std::to_string(96 + indexBytes) +
           R"(,"uri":"quad.bin"}],)"
           R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96,"byteStride":24},)"
           R"({"buffer":0,"byteOffset":96,"byteLength":)" +
           std::to_string(indexBytes) +
           R"(}],)"
           R"("accessors":[{"bufferView":0,"byteOffset":0,"componentType":5126,"count":4,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]},)"
           R"({"bufferView":0,"byteOffset":12,"componentType":5126,"count":4,"type":"VEC3"},)"
           R"({"bufferView":1,"componentType":)" +
           std::to_string(componentType) + R"(,"count":)" + std::to_string(indexCount) +
           R"(,"type":"SCALAR"}]})";
}

template <typename Index>
std::vector<unsigned char> withIndices(std::vector<unsigned char> bytes, const std::vector<Index>& indices) {
    for (Index i : indices) {
        appendBytes(bytes, i);
    }
    while (bytes.size() % 4 != 0) {
        bytes.push_back(0);
    }
    return bytes;
}

} // namespace

struct LayoutCase {
    const char* name;
    int mode;
    int componentType;
    std::vector<std::uint32_t> indices;
};

class GltfLayoutTest : public GltfTest, public testing::WithParamInterface<LayoutCase> {};

TEST_P(GltfLayoutTest, ExternalInterleavedBufferGivesTheSameQuad) {
    const LayoutCase& c = GetParam();
    std::vector<unsigned char> bytes;
    std::size_t indexBytes = 0;
    if (c.componentType == 5121) {
        bytes = withIndices(interleavedQuad(), std::vector<std::uint8_t>(c.indices.begin(), c.indices.end()));
        indexBytes = c.indices.size();
    } else if (c.componentType == 5123) {
        bytes =
            withIndices(interleavedQuad(), std::vector<std::uint16_t>(c.indices.begin(), c.indices.end()));
        indexBytes = 2 * c.indices.size();
    } else {
        bytes = withIndices(interleavedQuad(), c.indices);
        indexBytes = 4 * c.indices.size();
    }
    indexBytes = (indexBytes + 3) / 4 * 4;
    write("quad.bin", std::string(bytes.begin(), bytes.end()));
    const auto path = write("quad.gltf", quadGltf(c.mode, c.componentType, c.indices.size(), indexBytes, ""));
    const LoadedScene loaded = GltfLoader::load(path);
    const auto& mesh = *loaded.scene.entity(0).mesh->mesh;
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[2], glm::vec3(1, 1, 0));
    EXPECT_EQ(mesh.normals[3], glm::vec3(0, 0, 1));
    ASSERT_EQ(mesh.indices.size(), 6u);
    // Both triangles are counter-clockwise seen from +Z, whatever the primitive mode.
    for (std::size_t t = 0; t < 6; t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]];
        const glm::vec3 n =
            glm::cross(mesh.positions[mesh.indices[t + 1]] - a, mesh.positions[mesh.indices[t + 2]] - a);
        EXPECT_GT(n.z, 0.0f) << "triangle " << t / 3;
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, GltfLayoutTest,
                         testing::Values(LayoutCase{"trianglesU8", 4, 5121, {0, 1, 2, 0, 2, 3}},
                                         LayoutCase{"trianglesU16", 4, 5123, {0, 1, 2, 0, 2, 3}},
                                         LayoutCase{"trianglesU32", 4, 5125, {0, 1, 2, 0, 2, 3}},
                                         LayoutCase{"strip", 5, 5123, {1, 2, 0, 3}},
                                         LayoutCase{"fan", 6, 5125, {0, 1, 2, 3}}),
                         [](const auto& test) { return std::string(test.param.name); });

TEST_F(GltfTest, NodeMatrixAndOrthographicCameraAreRead) {
    std::vector<unsigned char> bytes =
        withIndices(interleavedQuad(), std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    write("quad.bin", std::string(bytes.begin(), bytes.end()));
    // Column-major: scale 2, then translate (5, 6, 7).
    const std::string matrix = R"(,"matrix":[2,0,0,0, 0,2,0,0, 0,0,2,0, 5,6,7,1],"camera":0)";
    std::string text = quadGltf(4, 5123, 6, 12, matrix);
    text.insert(
        text.size() - 1,
        R"(,"cameras":[{"type":"orthographic","orthographic":{"xmag":3,"ymag":2,"znear":0.5,"zfar":50}}])");
    const LoadedScene loaded = GltfLoader::load(write("quad.gltf", text));
    const glm::mat4 world = loaded.scene.worldMatrix(0);
    EXPECT_EQ(glm::vec3(world * glm::vec4(1, 1, 0, 1)), glm::vec3(7, 8, 7));
    const auto& camera = *loaded.scene.entity(0).camera;
    EXPECT_EQ(camera.projection, engine::ProjectionType::Orthographic);
    EXPECT_FLOAT_EQ(camera.orthographicHeight, 4.0f);
    EXPECT_FLOAT_EQ(camera.farPlane, 50.0f);
}

TEST_F(GltfTest, MissingExternalBufferIsAnError) {
    const auto path = write("quad.gltf", quadGltf(4, 5123, 6, 12, ""));
    const std::string message = loadError(path);
    EXPECT_NE(message.find(path.string() + ": not a valid glTF 2.0 file"), std::string::npos) << message;
    EXPECT_NE(message.find("quad.bin"), std::string::npos) << message;
}

TEST_F(GltfTest, SubdivisionFlagOnOwnTrianglesUsesTheWeldedMesh) {
    // An octahedron as six separate triangle primitives' worth of split vertices: welding must reconnect it.
    const glm::vec3 v[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    engine::Scene scene;
    auto mesh = std::make_shared<engine::MeshData>();
    for (const auto& face : faces) {
        for (int corner : face) {
            mesh->indices.push_back(static_cast<std::uint32_t>(mesh->positions.size()));
            mesh->positions.push_back(v[corner]); // split: no vertex shared between faces
        }
    }
    const auto id = scene.create("octahedron");
    scene.entity(id).mesh = engine::MeshComponent{mesh};
    const auto path = folder_ / "octa.gltf";
    GltfWriter::save(scene, path, {{id, SubdivisionTag{"loop", 2, ""}}});
    const LoadedScene loaded = GltfLoader::load(path);
    ASSERT_EQ(loaded.subdivided.size(), 1u);
    EXPECT_EQ(loaded.subdivided[0].second.scheme, "loop");
    const auto& surface = *loaded.scene.entity(id).mesh->mesh;
    // Loop growth on a closed welded octahedron: F = 8 * 4^2 = 128 triangles, V = F/2 + 2 = 66.
    EXPECT_EQ(surface.triangleCount(), 128u);
    EXPECT_EQ(surface.positions.size(), 66u);
}

// Robustness: inputs found by fuzzing (tests/fuzz, docs/ROBUSTNESS.md) or written against the loader's
// limits. Each must fail with a ContentError naming the source and the field, quickly and without a huge
// allocation.

namespace {

std::span<const std::uint8_t> bytesOf(const std::string& text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

std::string memoryLoadError(const std::string& text, const std::filesystem::path& baseFolder = {},
                            const SceneLoadOptions& options = {}) {
    try {
        (void)GltfLoader::loadFromMemory(bytesOf(text), baseFolder, "mem.gltf", options);
    } catch (const ContentError& error) {
        return error.what();
    }
    return "(loaded)";
}

void appendU32(std::string& out, std::uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) {
        out += static_cast<char>((value >> shift) & 0xffu);
    }
}

/// A GLB container around `json` and `bin`; `binLengthField` overrides the BIN chunk's length field.
std::string glb(std::string json, const std::string& bin, std::optional<std::uint32_t> binLengthField = {},
                std::uint32_t version = 2) {
    while (json.size() % 4 != 0) {
        json += ' ';
    }
    std::string out = "glTF";
    appendU32(out, version);
    appendU32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    appendU32(out, static_cast<std::uint32_t>(json.size()));
    out += "JSON" + json;
    if (!bin.empty()) {
        appendU32(out, binLengthField.value_or(static_cast<std::uint32_t>(bin.size())));
        out += std::string("BIN\0", 4) + bin;
    }
    return out;
}

/// glTF JSON with `nodes` as given and one triangle mesh (the TriangleGltf buffer) that nodes may use.
std::string withNodes(const std::string& nodes,
                      const std::string& scenes = R"("scene":0,"scenes":[{"nodes":[0]}],)") {
    std::string text = TriangleGltf{}.json();
    const auto begin = text.find(R"("scene":0)");
    const auto end = text.find(R"("meshes")");
    return text.substr(0, begin) + scenes + R"("nodes":)" + nodes + "," + text.substr(end);
}

} // namespace

TEST_F(GltfTest, LoadFromMemoryReadsTextAndBinaryLikeFiles) {
    const std::string text = TriangleGltf{}.json();
    const LoadedScene fromText = GltfLoader::loadFromMemory(bytesOf(text), {}, "mem.gltf");
    ASSERT_EQ(fromText.scene.size(), 1u);
    EXPECT_EQ(fromText.scene.entity(0).mesh->mesh->indices, (std::vector<std::uint32_t>{0, 1, 2}));

    engine::Scene scene;
    const auto id = scene.create("cube");
    scene.entity(id).mesh =
        engine::MeshComponent{std::make_shared<engine::MeshData>(engine::primitives::cube())};
    const auto path = folder_ / "cube.glb";
    GltfWriter::save(scene, path);
    std::ifstream file(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    const LoadedScene fromGlb = GltfLoader::loadFromMemory(bytesOf(bytes), {}, "mem.glb");
    EXPECT_EQ(fromGlb.scene.entity(0).mesh->mesh->positions, engine::primitives::cube().positions);
}

TEST_F(GltfTest, AccessorCountOf2To32MinusOneIsRejectedBeforeAllocating) {
    // Found by the fuzzer: the loader sized its vector from the count before checking the bounds, asking for
    // 16 GiB (and spending tens of seconds in page faults where the allocation succeeded).
    TriangleGltf gltf;
    gltf.indexCount = "4294967295";
    const std::string message = memoryLoadError(gltf.json());
    EXPECT_NE(message.find("mem.gltf: accessors[1] (meshes[0].primitives[0].indices): 4294967295 elements"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("(accessor out of bounds)"), std::string::npos) << message;
}

TEST_F(GltfTest, BufferViewOffsetThatWrapsAroundIsRejected) {
    // byteOffset + byteLength wrapped around 2^64 to a small end, so the old check passed and the copy read 8
    // bytes before the buffer (UBSan: pointer overflow).
    std::string text = TriangleGltf{}.json();
    const std::string view = R"("byteOffset":0,"byteLength":36)";
    text.replace(text.find(view), view.size(), R"("byteOffset":18446744073709551608,"byteLength":40)");
    const std::string message = memoryLoadError(text);
    EXPECT_NE(message.find("mem.gltf: accessors[0] (meshes[0].primitives[0].POSITION): bufferView 0 "
                           "(byteOffset 18446744073709551608, byteLength 40) reaches beyond its buffer"),
              std::string::npos)
        << message;
}

TEST_F(GltfTest, AccessorOffsetsAndStridesOutsideTheViewAreRejected) {
    std::string text = TriangleGltf{}.json();
    const std::string accessor = R"({"bufferView":0,"componentType":5126,)";
    text.replace(text.find(accessor), accessor.size(),
                 R"({"bufferView":0,"byteOffset":18446744073709551615,"componentType":5126,)");
    EXPECT_NE(
        memoryLoadError(text).find("3 elements from byteOffset 18446744073709551615 overrun bufferView 0"),
        std::string::npos)
        << memoryLoadError(text);

    // tinygltf itself refuses strides over 252 (glTF's limit); an explicit 0 means tightly packed.
    for (const char* stride : {"256", "0"}) {
        text = TriangleGltf{}.json();
        const std::string view = R"("byteLength":36)";
        text.replace(text.find(view), view.size(), std::string(R"("byteLength":36,"byteStride":)") + stride);
        const std::string message = memoryLoadError(text);
        if (std::string(stride) == "0") {
            EXPECT_EQ(message, "(loaded)");
        } else {
            EXPECT_NE(message.find("mem.gltf: not a valid glTF 2.0 file"), std::string::npos) << message;
            EXPECT_NE(message.find("byteStride"), std::string::npos) << message;
        }
    }
}

TEST_F(GltfTest, GlbWhoseBinChunkOverrunsTheDataIsRejected) {
    // tinygltf 2.7.0 checks the BIN chunk's length without its 8-byte header, so it copied the 12 bytes the
    // chunk claims from the 8 there are (ASan: heap-buffer-overflow).
    const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":12}]})";
    const std::string message = memoryLoadError(glb(json, std::string(8, '\0'), 12));
    EXPECT_NE(message.find("mem.gltf: not a valid glTF 2.0 file: GLB BIN chunk of 12 bytes overruns"),
              std::string::npos)
        << message;
}

TEST_F(GltfTest, GlbHeaderProblemsAreNamed) {
    const std::string json = R"({"asset":{"version":"2.0"}})";
    EXPECT_NE(memoryLoadError(glb(json, "", {}, 1)).find("GLB header has version 1 (expected 2)"),
              std::string::npos);
    std::string longer = glb(json, "");
    longer[8] = static_cast<char>(longer[8] + 4); // the header claims 4 bytes more than there are
    EXPECT_NE(memoryLoadError(longer).find("GLB header says"), std::string::npos) << memoryLoadError(longer);
    EXPECT_NE(memoryLoadError("glTF").find("GLB is 4 bytes, shorter than its headers"), std::string::npos);
}

TEST_F(GltfTest, GlbBufferOfZeroBytesIsAContentError) {
    // tinygltf throws std::out_of_range for it (vector::at(0) on an empty vector) instead of reporting it.
    const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":0}]})";
    const std::string message = memoryLoadError(glb(json, std::string(4, '\0')));
    EXPECT_NE(message.find("mem.gltf: not a valid glTF 2.0 file"), std::string::npos) << message;
}

TEST_F(GltfTest, DeeplyNestedJsonIsRejectedBeforeParsing) {
    // A million nested arrays in `extras` overflowed the stack in tinygltf's recursive value conversion.
    const std::size_t depth = 1'000'000;
    const std::string text = R"({"asset":{"version":"2.0"},"nodes":[{"extras":)" + std::string(depth, '[') +
                             std::string(depth, ']') + "}]}";
    const std::string message = memoryLoadError(text);
    EXPECT_NE(
        message.find("mem.gltf: not a valid glTF 2.0 file: JSON nested more than 128 levels deep at byte"),
        std::string::npos)
        << message;
    // Brackets inside strings, escaped quotes included, are not nesting.
    TriangleGltf gltf;
    gltf.extraNodeFields = R"(,"extras":{"note":"\"[[[[)" + std::string(200, '[') + R"("})";
    EXPECT_EQ(memoryLoadError(gltf.json()), "(loaded)");
}

TEST_F(GltfTest, NodesReachedTwiceAreRejected) {
    // Twenty nodes, each listing the next one twice as a child: 2^20 paths, which the loader used to
    // instantiate one by one.
    std::string nodes = "[";
    for (int i = 0; i < 20; ++i) {
        nodes += i == 0 ? "" : ",";
        nodes += R"({"children":[)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]}";
    }
    nodes += R"(,{"mesh":0}])";
    EXPECT_NE(
        memoryLoadError(withNodes(nodes)).find("mem.gltf: nodes[20] is reached twice in the node hierarchy"),
        std::string::npos)
        << memoryLoadError(withNodes(nodes));
    // A cycle, and a scene listing its root twice.
    EXPECT_NE(memoryLoadError(withNodes(R"([{"children":[1]},{"children":[0]}])"))
                  .find("nodes[0] is reached twice"),
              std::string::npos);
    EXPECT_NE(memoryLoadError(withNodes(R"([{"mesh":0}])", R"("scene":0,"scenes":[{"nodes":[0,0]}],)"))
                  .find("nodes[0] is reached twice"),
              std::string::npos);
}

TEST_F(GltfTest, ChainsDeeperThan256NodesAreRejected) {
    std::string nodes = "[";
    for (int i = 0; i < 300; ++i) {
        nodes += (i == 0 ? "" : ",") + std::string(R"({"children":[)") + std::to_string(i + 1) + "]}";
    }
    nodes += R"(,{"mesh":0}])";
    EXPECT_NE(memoryLoadError(withNodes(nodes)).find("mem.gltf: node 257 is nested more than 256 deep"),
              std::string::npos)
        << memoryLoadError(withNodes(nodes));
}

namespace {

std::string emptyNodes(int count) {
    std::string nodes = "[";
    for (int i = 0; i < count; ++i) {
        nodes += i == 0 ? "{}" : ",{}";
    }
    return nodes + "]";
}

} // namespace

TEST_F(GltfTest, AMillionNodesOfAnEmptySceneLoadAsNoEntities) {
    // Costs time and memory in proportion to the file (tinygltf keeps ~0.5 KB per node), nothing more.
    const std::string text =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{}],"nodes":)" + emptyNodes(1'000'000) + "}";
    EXPECT_EQ(GltfLoader::loadFromMemory(bytesOf(text), {}, "mem.gltf").scene.size(), 0u);
}

TEST_F(GltfTest, WithoutScenesEveryRootNodeIsAnEntity) {
    const std::string text = R"({"asset":{"version":"2.0"},"nodes":)" + emptyNodes(100'000) + "}";
    EXPECT_EQ(GltfLoader::loadFromMemory(bytesOf(text), {}, "mem.gltf").scene.size(), 100'000u);
}

TEST_F(GltfTest, MeshDataBeyondTheLimitIsRejectedBeforeAllocating) {
    // One 36-byte triangle instanced by 1000 nodes: each instance is charged, so a small file cannot demand
    // gigabytes by repeating a reference.
    std::string nodes = "[";
    std::string roots;
    for (int i = 0; i < 1000; ++i) {
        nodes += (i == 0 ? "" : ",") + std::string(R"({"mesh":0})");
        roots += (i == 0 ? "" : ",") + std::to_string(i);
    }
    nodes += "]";
    const std::string text = withNodes(nodes, R"("scene":0,"scenes":[{"nodes":[)" + roots + "]}],");
    EXPECT_EQ(GltfLoader::loadFromMemory(bytesOf(text), {}, "mem.gltf").scene.size(), 1000u);
    SceneLoadOptions options;
    options.meshByteLimit = 10'000; // 48 bytes per instance: room for 208 of them
    const std::string message = memoryLoadError(text, {}, options);
    EXPECT_NE(
        message.find("mem.gltf: accessors[0] (meshes[0].primitives[0].POSITION) needs 36 bytes of mesh data, "
                     "more than is left of the 10000 bytes the scene may use"),
        std::string::npos)
        << message;

    // Subdivision is charged by its estimated output before OpenSubdiv runs: the triangle's welded cage at
    // level 6 is 4^6 triangles.
    TriangleGltf subdivided;
    subdivided.extraNodeFields = R"(,"extras":{"subdivision":{"scheme":"loop","level":6}})";
    options.meshByteLimit = 100'000;
    EXPECT_NE(memoryLoadError(subdivided.json(), {}, options)
                  .find("mem.gltf: nodes[0].extras.subdivision needs 196608 bytes of mesh data"),
              std::string::npos)
        << memoryLoadError(subdivided.json(), {}, options);
}

TEST_F(GltfTest, ExternalFilesMustLieInsideTheBaseFolder) {
    const auto inside = folder_ / "scene";
    std::filesystem::create_directories(inside);
    std::vector<unsigned char> bytes =
        withIndices(interleavedQuad(), std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    std::ofstream(folder_ / "quad.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    std::string text = quadGltf(4, 5123, 6, 12, "");
    text.replace(text.find(R"("uri":"quad.bin")"), 16, R"("uri":"../quad.bin")");
    std::string message = memoryLoadError(text, inside);
    EXPECT_NE(message.find("mem.gltf: external file '"), std::string::npos) << message;
    EXPECT_NE(message.find("was not read: it lies outside the folder " +
                           std::filesystem::weakly_canonical(inside).string()),
              std::string::npos)
        << message;

    // Percent-encoded and absolute URIs are resolved the same way.
    text.replace(text.find(R"("uri":"../quad.bin")"), 19, R"("uri":"%2e%2e/quad.bin")");
    EXPECT_NE(memoryLoadError(text, inside).find("lies outside the folder"), std::string::npos);

    // Without a base folder nothing external is read, not even from the working directory.
    text = quadGltf(4, 5123, 6, 12, "");
    message = memoryLoadError(text);
    EXPECT_NE(message.find("external file 'quad.bin' was not read: no external file may be read"),
              std::string::npos)
        << message;
    // ...and the same file next to the scene still loads through load().
    std::filesystem::copy_file(folder_ / "quad.bin", inside / "quad.bin");
    std::ofstream(inside / "quad.gltf") << text;
    EXPECT_EQ(GltfLoader::load(inside / "quad.gltf").scene.size(), 1u);

    // Images are optional (and unused): one outside the folder is left out with a warning.
    TriangleGltf textured;
    textured.extraTopLevel = R"(,"images":[{"uri":"../texture.png"}])";
    const LoadedScene loaded = GltfLoader::loadFromMemory(bytesOf(textured.json()), inside, "mem.gltf");
    ASSERT_FALSE(loaded.warnings.empty());
    EXPECT_NE(loaded.warnings.front().find("mem.gltf: external file '"), std::string::npos)
        << loaded.warnings.front();
    EXPECT_NE(loaded.warnings.front().find("texture.png' was not read: it lies outside the folder"),
              std::string::npos)
        << loaded.warnings.front();

    TriangleGltf cage;
    cage.extraNodeFields = R"(,"extras":{"subdivision":{"cage":"knob.obj"}})";
    EXPECT_NE(memoryLoadError(cage.json())
                  .find("mem.gltf: nodes[0].extras.subdivision.cage 'knob.obj' cannot be read: the scene was "
                        "loaded from memory without a base folder"),
              std::string::npos)
        << memoryLoadError(cage.json());
}

struct BadValueCase {
    const char* name;
    const char* nodeFields;
    const char* topLevel;
    const char* expected;
};

class GltfBadValueTest : public GltfTest, public testing::WithParamInterface<BadValueCase> {};

TEST_P(GltfBadValueTest, FailsWithMessageNamingTheField) {
    TriangleGltf gltf;
    gltf.extraNodeFields = GetParam().nodeFields;
    gltf.extraTopLevel = GetParam().topLevel;
    const std::string message = memoryLoadError(gltf.json());
    EXPECT_EQ(message.rfind("mem.gltf: ", 0), 0u) << message;
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GltfBadValueTest,
    testing::Values(
        // 1e300 is a finite double but an infinite float.
        BadValueCase{"hugeTranslation", R"(,"translation":[1e300,0,0])", "",
                     "nodes[0].translation must hold 3 finite numbers"},
        BadValueCase{"zeroQuaternion", R"(,"rotation":[0,0,0,0])", "",
                     "nodes[0].rotation must be a non-zero quaternion"},
        BadValueCase{"hugeMatrix", R"(,"matrix":[1e300,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1])", "",
                     "nodes[0].matrix must hold 16 finite numbers"},
        // Each entry fits a float, but the first column's length (the scale) does not.
        BadValueCase{"matrixScaleOverflows", R"(,"matrix":[3e38,3e38,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1])", "",
                     "nodes[0].matrix has no finite translation, rotation and scale"},
        BadValueCase{
            "flatOrthographicCamera", R"(,"camera":0)",
            R"(,"cameras":[{"type":"orthographic","orthographic":{"xmag":1,"ymag":0,"znear":0,"zfar":9}}])",
            "needs a finite ymag > 0"},
        BadValueCase{"castsShadowsNotBoolean", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"directional",)"
                     R"("extras":{"castsShadows":"yes"}}]}})",
                     "light 0 extras.castsShadows must be true or false"},
        BadValueCase{
            "negativeLightColor", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
            R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"directional","color":[1,-1,1]}]}})",
            "light 0 needs a color of finite, non-negative numbers"},
        // KHR_lights_punctual: range, when present, must be > 0; an absent range is the unlimited one.
        BadValueCase{
            "pointRangeZero", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
            R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","name":"bulb",)"
            R"("range":0}]}})",
            "light 0 ('bulb'): extensions.KHR_lights_punctual.lights[0].range must be a finite number > 0 "
            "(leave it out for an unlimited range), not 0"},
        BadValueCase{
            "pointRangeNegative", R"(,"extensions":{"KHR_lights_punctual":{"light":1}})",
            R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"},)"
            R"({"type":"point","name":"lamp","range":-2.5}]}})",
            "light 1 ('lamp'): extensions.KHR_lights_punctual.lights[1].range must be a finite number > 0 "
            "(leave it out for an unlimited range), not -2.5"},
        // 1e300 is a finite double but an infinite float, which the engine stores.
        BadValueCase{"pointRangeInfiniteAsFloat", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","range":1e300}]}})",
                     "light 0: extensions.KHR_lights_punctual.lights[0].range must be a finite number > 0 "
                     "(leave it out for an unlimited range), not 1e+300"},
        // A light's size (extras, for soft shadows): the sun's angular diameter, a local light's radius.
        BadValueCase{"negativeRadius", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","name":"bulb",)"
                     R"("extras":{"radius":-0.1}}]}})",
                     "light 0 ('bulb') extras.radius must be a number in [0, 3.40282e+38), not -0.1"},
        BadValueCase{"radiusNotANumber", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"spot","spot":{},)"
                     R"("extras":{"radius":"big"}}]}})",
                     "light 0 extras.radius must be a number in [0, 3.40282e+38), not a non-number"},
        BadValueCase{"radiusBeyondTheRange", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","range":2,)"
                     R"("extras":{"radius":5}}]}})",
                     "light 0 extras.radius must be a number in [0, 2) (the light's range), not 5"},
        BadValueCase{"hugeAngularDiameter", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"directional",)"
                     R"("extras":{"angularDiameter":2}}]}})",
                     "light 0 extras.angularDiameter must be a number in [0, 1.5708) radians, not 2"},
        BadValueCase{"radiusOfASun", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
                     R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"directional",)"
                     R"("extras":{"radius":1}}]}})",
                     "light 0 extras.radius is for spot and point lights; a directional light's size is "
                     "extras.angularDiameter"},
        BadValueCase{
            "spotRangeZero", R"(,"extensions":{"KHR_lights_punctual":{"light":0}})",
            R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"spot","name":"cone",)"
            R"("spot":{},"range":0}]}})",
            "light 0 ('cone'): extensions.KHR_lights_punctual.lights[0].range must be a finite number > 0"}),
    [](const auto& test) { return std::string(test.param.name); });
