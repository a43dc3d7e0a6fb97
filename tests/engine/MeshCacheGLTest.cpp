// The renderer's mesh cache: a mesh is uploaded once, kept while a scene references it, and released (its GL
// buffers deleted) once no scene does, so switching scenes for hours does not accumulate GPU memory.
#include "GLTestContext.h"
#include "LitCubeScene.h"

#include <engine/Engine.h>
#include <engine/RenderTarget.h>

#include <gtest/gtest.h>

#include <optional>

namespace {

/// Buffer objects alive in the context among the first few thousand names (names are reused from the bottom).
int liveBuffers() {
    int count = 0;
    for (GLuint name = 1; name < 4096; ++name) {
        count += glIsBuffer(name) == GL_TRUE;
    }
    return count;
}

TEST(MeshCacheGLTest, MeshesNoSceneReferencesAreReleased) {
    glTestContext();
    engine::Engine engine;
    engine::RenderTarget target({32, 32});
    const LitCubeScene kept;
    engine.renderFrame(kept.scene, kept.camera, target);
    const int baseline = liveBuffers();
    const std::size_t baselineBytes = engine.renderer().meshBytes();
    EXPECT_EQ(engine.renderer().cachedMeshCount(), 1u);

    std::optional<LitCubeScene> dropped(std::in_place);
    engine.renderFrame(dropped->scene, dropped->camera, target);
    EXPECT_EQ(engine.renderer().cachedMeshCount(), 2u);
    EXPECT_EQ(liveBuffers(), baseline + 2); // its vertices and indices
    EXPECT_GT(engine.renderer().meshBytes(), baselineBytes);

    dropped.reset();
    engine.renderFrame(kept.scene, kept.camera, target);
    EXPECT_EQ(engine.renderer().cachedMeshCount(), 1u);
    EXPECT_EQ(liveBuffers(), baseline);
    EXPECT_EQ(engine.renderer().meshBytes(), baselineBytes);
}

TEST(MeshCacheGLTest, AMeshStillReferencedIsKeptWhenNotDrawn) {
    glTestContext();
    engine::Engine engine;
    engine::RenderTarget target({32, 32});
    const LitCubeScene first;
    const LitCubeScene second;
    engine.renderFrame(first.scene, first.camera, target);
    engine.renderFrame(second.scene, second.camera, target); // `first` is alive, just not drawn
    EXPECT_EQ(engine.renderer().cachedMeshCount(), 2u);
}

} // namespace

TEST(MeshCacheGLTest, EnginesSharingAScenesMeshesEachReleaseThem) {
    // The sandbox's two sides: two engines draw one scene; once it is dropped, neither may keep its meshes
    // alive for the other.
    glTestContext();
    engine::Engine left;
    engine::Engine right;
    engine::RenderTarget target({32, 32});
    const LitCubeScene kept;
    left.renderFrame(kept.scene, kept.camera, target);
    right.renderFrame(kept.scene, kept.camera, target);
    const int baseline = liveBuffers();

    std::optional<LitCubeScene> dropped(std::in_place);
    left.renderFrame(dropped->scene, dropped->camera, target);
    right.renderFrame(dropped->scene, dropped->camera, target);
    EXPECT_EQ(liveBuffers(), baseline + 4);
    dropped.reset();
    left.renderFrame(kept.scene, kept.camera, target);
    right.renderFrame(kept.scene, kept.camera, target);
    EXPECT_EQ(left.renderer().cachedMeshCount(), 1u);
    EXPECT_EQ(right.renderer().cachedMeshCount(), 1u);
    EXPECT_EQ(liveBuffers(), baseline);
}
