// engine::aimLight: each light type keeps what it lights when swung to new angles.
#include <engine/Error.h>
#include <engine/LightAim.h>
#include <engine/Primitives.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

using namespace engine;

namespace {

/// A 2-unit cube centred at (1, 1, -2) (the meshes' centre) and one light of `type` at `lightPosition` facing
/// `lightTarget`.
struct AimScene {
    Scene scene;
    EntityId light = kNoEntity;
    static constexpr glm::vec3 kCentre{1.0f, 1.0f, -2.0f};

    AimScene(LightType type, glm::vec3 lightPosition, glm::vec3 lightTarget) {
        const EntityId box = scene.create("box");
        scene.entity(box).mesh = MeshComponent{std::make_shared<MeshData>(primitives::cube(2.0f))};
        scene.entity(box).transform.translation = kCentre;
        light = scene.create("light");
        LightComponent component;
        component.type = type;
        scene.entity(light).light = component;
        scene.entity(light).transform = Transform::lookAt(lightPosition, lightTarget);
    }

    [[nodiscard]] glm::vec3 position() const { return glm::vec3(scene.worldMatrix(light)[3]); }
    [[nodiscard]] glm::vec3 forward() const {
        return glm::normalize(-glm::vec3(scene.worldMatrix(light)[2]));
    }
};

void expectNear(glm::vec3 actual, glm::vec3 expected, const char* what) {
    EXPECT_LT(glm::length(actual - expected), 1e-4f)
        << what << ": (" << actual.x << ", " << actual.y << ", " << actual.z << ") instead of (" << expected.x
        << ", " << expected.y << ", " << expected.z << ")";
}

} // namespace

TEST(LightAimTest, PointLightSwingsAroundTheMeshesCentreAtItsDistance) {
    // Facing away from the box: a point light's axis means nothing, only its distance to the centre counts.
    AimScene s(LightType::Point, AimScene::kCentre + glm::vec3(0, 3, 4),
               AimScene::kCentre + glm::vec3(0, 9, 9));
    const LightAngles angles{90.0f, 30.0f};
    aimLight(s.scene, s.light, angles);
    expectNear(s.position(), AimScene::kCentre + towardsLight(angles) * 5.0f, "position");
    expectNear(s.forward(), -towardsLight(angles), "facing");
}

TEST(LightAimTest, PointLightAtTheCentreIsPlacedTwiceTheRadiusAway) {
    AimScene s(LightType::Point, AimScene::kCentre, AimScene::kCentre + glm::vec3(0, 0, 1));
    const LightAngles angles{0.0f, 90.0f};
    aimLight(s.scene, s.light, angles);
    // The box's bounding-sphere radius is sqrt(3) (half its diagonal).
    expectNear(s.position(), AimScene::kCentre + glm::vec3(0, 2.0f * std::sqrt(3.0f), 0), "position");
}

TEST(LightAimTest, SpotLightSwingsAroundThePointItsAxisPassesNearestTheCentre) {
    // The axis passes 1 unit to the side of the centre, 6 units from the light.
    const glm::vec3 aimedAt = AimScene::kCentre + glm::vec3(1, 0, 0);
    AimScene s(LightType::Spot, aimedAt + glm::vec3(0, 6, 0), aimedAt);
    const LightAngles angles{45.0f, 60.0f};
    aimLight(s.scene, s.light, angles);
    expectNear(s.position(), aimedAt + towardsLight(angles) * 6.0f, "position");
    expectNear(s.forward(), -towardsLight(angles), "axis");
}

TEST(LightAimTest, DirectionalLightShinesFromTheAngles) {
    AimScene s(LightType::Directional, {0, 10, 0}, {0, 0, 0});
    const LightAngles angles{200.0f, 15.0f};
    aimLight(s.scene, s.light, angles);
    expectNear(s.forward(), -towardsLight(angles), "direction");
}

TEST(LightAimTest, BadInputIsNamed) {
    AimScene s(LightType::Point, {0, 5, 0}, {0, 0, 0});
    const EntityId plain = s.scene.create("plain");
    auto message = [&](EntityId id, LightAngles angles) {
        try {
            aimLight(s.scene, id, angles);
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(message(plain, {}), "aimLight: entity 'plain' has no light");
    EXPECT_EQ(message(s.light, {std::numeric_limits<float>::quiet_NaN(), 10.0f}),
              "aimLight: light 'light': azimuth and elevation must be finite");
}
