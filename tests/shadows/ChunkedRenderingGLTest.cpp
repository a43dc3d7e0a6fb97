// Chunking and culling are exact: a scene drawn in small chunks, culled against the camera and the light,
// equals the scene drawn whole and unculled, pixel for pixel (0 differing channels beyond 1/255): a mesh
// larger than one chunk, a mesh wholly outside the view and a caster outside the view that shadows visible
// ground. The depth pre-pass gives the same image too.
#include "../engine/GLTestContext.h"

#include <engine/Engine.h>
#include <engine/Primitives.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

namespace {

constexpr int kMaxChannelDifference = 1; // of 255
constexpr glm::ivec2 kSize{160, 120};

struct CullingScene {
    engine::Scene scene;
    engine::EntityId camera = engine::kNoEntity;
    engine::EntityId offViewCaster = engine::kNoEntity;

    CullingScene() {
        using namespace engine;
        add("ground", primitives::plane(20.0f, 48), {});                     // 4608 triangles
        add("sphere", primitives::sphere(1.0f, 48, 96), {0.0f, 1.2f, 0.0f}); // ~9000 triangles
        add("behind camera", primitives::cube(1.0f), {0.0f, 1.0f, 30.0f});
        // Above the ground left of the view; the sun (from -X, above) throws its shadow into the view.
        offViewCaster = add("off-view caster", primitives::cube(1.5f), {-9.0f, 4.0f, 0.0f});
        camera = scene.create("camera");
        scene.entity(camera).camera = CameraComponent{};
        scene.entity(camera).camera->farPlane = 40.0f;
        scene.entity(camera).transform = Transform::lookAt({0.0f, 5.0f, 9.0f}, {-1.0f, 0.0f, 0.0f});
        const EntityId sun = scene.create("sun");
        scene.entity(sun).light = LightComponent{};
        scene.entity(sun).transform = Transform::lookAt({-6.0f, 4.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
    }

    engine::EntityId add(const std::string& name, engine::MeshData mesh, glm::vec3 at) {
        const engine::EntityId id = scene.create(name);
        scene.entity(id).mesh = engine::MeshComponent{std::make_shared<engine::MeshData>(std::move(mesh))};
        scene.entity(id).transform.translation = at;
        return id;
    }
};

struct Rendered {
    engine::Image image;
    engine::FrameStats stats;
};

Rendered render(const engine::Scene& scene, engine::EntityId camera, std::uint32_t chunkTriangles,
                bool culling, bool depthPrePass) {
    glTestContext();
    engine::Engine engine;
    engine.renderer().chunkLimits.maxTriangles = chunkTriangles;
    engine.renderer().culling = culling;
    engine.renderer().depthPrePass = depthPrePass;
    // Without a pre-pass, depth is drawn by the lighting pass itself, not by the sample pass's shared one
    // (ViewDepthGLTest, SharedViewDepth).
    engine.renderer().shareViewDepth = false;
    shadows::ShadowSettings settings;
    settings.technique = shadows::ShadowTechnique::Gsm;
    settings.resolution = 1024;
    engine.addModule(std::make_unique<shadows::ShadowModule>(settings));
    engine::RenderTarget target(kSize);
    Rendered result;
    result.stats = engine.renderFrame(scene, camera, target);
    result.image = target.readPixels();
    return result;
}

int differingChannels(const engine::Image& a, const engine::Image& b) {
    int count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        count +=
            std::abs(static_cast<int>(a.pixels[i]) - static_cast<int>(b.pixels[i])) > kMaxChannelDifference;
    }
    return count;
}

TEST(ChunkedRenderingGLTest, ChunkedAndCulledEqualsWholeAndUnculled) {
    const CullingScene s;
    const Rendered whole = render(s.scene, s.camera, 1u << 24, false, false);
    const Rendered chunked = render(s.scene, s.camera, 256, true, false);
    EXPECT_EQ(whole.stats.drawCalls, 4u); // one per mesh
    EXPECT_EQ(whole.stats.culledChunks, 0u);
    EXPECT_GT(chunked.stats.drawCalls, 20u);   // the ground and the sphere span many chunks
    EXPECT_GT(chunked.stats.culledChunks, 2u); // at least the two cubes and the ground's far corners
    EXPECT_LT(chunked.stats.triangles, whole.stats.triangles);
    EXPECT_EQ(differingChannels(whole.image, chunked.image), 0);
}

TEST(ChunkedRenderingGLTest, DepthPrePassGivesTheSameImage) {
    const CullingScene s;
    const Rendered plain = render(s.scene, s.camera, 256, true, false);
    const Rendered prePass = render(s.scene, s.camera, 256, true, true);
    EXPECT_EQ(prePass.stats.drawCalls, plain.stats.drawCalls);
    EXPECT_EQ(differingChannels(plain.image, prePass.image), 0);
}

TEST(ChunkedRenderingGLTest, CasterOutsideTheViewStillShadowsVisibleGround) {
    CullingScene s;
    const Rendered withCaster = render(s.scene, s.camera, 256, true, false);
    s.scene.entity(s.offViewCaster).mesh.reset();
    const Rendered without = render(s.scene, s.camera, 256, true, false);
    // The caster itself is not in view: removing it changes only the pixels its shadow darkens.
    int darker = 0;
    int lighter = 0;
    for (std::size_t i = 0; i < withCaster.image.pixels.size(); i += 4) {
        const int delta =
            static_cast<int>(without.image.pixels[i + 1]) - static_cast<int>(withCaster.image.pixels[i + 1]);
        darker += delta > 20;
        lighter += delta < -kMaxChannelDifference;
    }
    EXPECT_GT(darker, 200);
    // The map covers where shadows can fall, so without the caster it shrinks to the sphere's footprint and
    // the sphere's shadow edge lands on a finer texel grid: a pixel or two of it may come out lighter.
    EXPECT_LE(lighter, 3);
    EXPECT_EQ(withCaster.stats.drawCalls, without.stats.drawCalls); // it was culled from the lighting pass
}

} // namespace
