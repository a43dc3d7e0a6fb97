#include <engine/Error.h>
#include <engine/Scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace engine;

namespace {
void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}
glm::vec3 transformPoint(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}
} // namespace

TEST(SceneTest, WorldMatrixComposesParentThenChild) {
    Scene scene;
    const EntityId parent = scene.create("parent");
    const EntityId child = scene.create("child", parent);
    scene.entity(parent).transform.translation = {10, 0, 0};
    scene.entity(parent).transform.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    scene.entity(parent).transform.scale = glm::vec3(2.0f);
    scene.entity(child).transform.translation = {1, 0, 0};
    // Child origin: scaled by 2, rotated 90° about Y (x → -z), then moved by +10 x.
    expectNear(transformPoint(scene.worldMatrix(child), {0, 0, 0}), {10, 0, -2});
    EXPECT_EQ(scene.entity(parent).children, std::vector<EntityId>{child});
}

TEST(SceneTest, ReparentingMovesChildAndRejectsCycles) {
    Scene scene;
    const EntityId a = scene.create("a");
    const EntityId b = scene.create("b", a);
    const EntityId c = scene.create("c", b);
    EXPECT_THROW(scene.setParent(a, c), Error);
    scene.setParent(c, a);
    EXPECT_EQ(scene.entity(c).parent, a);
    EXPECT_TRUE(scene.entity(b).children.empty());
    EXPECT_EQ(scene.entity(a).children, (std::vector<EntityId>{b, c}));
    scene.setParent(c, kNoEntity);
    EXPECT_EQ(scene.entity(c).parent, kNoEntity);
}

TEST(SceneTest, UnknownIdsAreClearErrors) {
    Scene scene;
    scene.create("only");
    try {
        (void)scene.entity(7);
        FAIL() << "expected an error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("entity id 7 does not exist"), std::string::npos)
            << error.what();
    }
    EXPECT_THROW(scene.create("orphan", 42), Error);
}

TEST(SceneTest, FindsByNameAndFirstCamera) {
    Scene scene;
    scene.create("a");
    const EntityId camera = scene.create("cam");
    EXPECT_FALSE(scene.firstCamera());
    scene.entity(camera).camera = CameraComponent{};
    EXPECT_EQ(scene.firstCamera(), camera);
    EXPECT_EQ(scene.find("cam"), camera);
    EXPECT_FALSE(scene.find("missing"));
}

struct LookAtCase {
    const char* name;
    glm::vec3 eye;
    glm::vec3 target;
};

class TransformLookAtTest : public testing::TestWithParam<LookAtCase> {};

TEST_P(TransformLookAtTest, MinusZPointsAtTargetAndBasisIsOrthonormal) {
    const LookAtCase& c = GetParam();
    const glm::mat4 m = Transform::lookAt(c.eye, c.target).matrix();
    expectNear(-glm::vec3(m[2]), glm::normalize(c.target - c.eye));
    expectNear(glm::vec3(m[3]), c.eye);
    EXPECT_NEAR(glm::dot(glm::vec3(m[0]), glm::vec3(m[1])), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(m[0])), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::determinant(glm::mat3(m)), 1.0f, 1e-5f);
}

INSTANTIATE_TEST_SUITE_P(Cases, TransformLookAtTest,
                         testing::Values(LookAtCase{"oblique", {1, 2, 3}, {0, 0, 0}},
                                         LookAtCase{
                                             "straightDown", {0, 5, 0}, {0, 0, 0}}, // up parallel to view
                                         LookAtCase{"straightUp", {0, -5, 0}, {0, 0, 0}},
                                         LookAtCase{"alongZ", {0, 0, 5}, {0, 0, 0}}),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(CameraTest, PerspectiveAndOrthographicMapNearAndFarToClipRange) {
    CameraComponent camera;
    camera.nearPlane = 0.5f;
    camera.farPlane = 50.0f;
    for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
        camera.projection = type;
        const glm::mat4 p = camera.projectionMatrix(1.5f);
        const glm::vec4 nearPoint = p * glm::vec4(0, 0, -0.5f, 1);
        const glm::vec4 farPoint = p * glm::vec4(0, 0, -50.0f, 1);
        EXPECT_NEAR(nearPoint.z / nearPoint.w, -1.0f, 1e-4f);
        EXPECT_NEAR(farPoint.z / farPoint.w, 1.0f, 1e-4f);
    }
}
