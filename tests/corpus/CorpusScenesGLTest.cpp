// The real-model corpus (bash tools/corpus.sh): every staged model loads, casts shadows onto visible ground
// at the defaults, and renders identically in chunks with culling and whole without it. Skipped, saying so,
// when the corpus has not been built.
#include "../engine/GLTestContext.h"

#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

namespace {

const std::filesystem::path kCorpus = CORPUS_DIR;

struct Frame {
    engine::Image image;
    engine::FrameStats stats;
};

Frame render(const engine::Scene& scene, std::uint32_t chunkTriangles, bool culling) {
    glTestContext();
    engine::Engine engine;
    engine.renderer().chunkLimits.maxTriangles = chunkTriangles;
    engine.renderer().culling = culling;
    shadows::ShadowSettings settings;
    settings.technique = shadows::ShadowTechnique::Gsm;
    settings.debugView = shadows::ShadowDebugView::Visibility;
    engine.addModule(std::make_unique<shadows::ShadowModule>(settings));
    engine::RenderTarget target({160, 120});
    Frame frame;
    frame.stats = engine.renderFrame(scene, *scene.firstCamera(), target);
    frame.image = target.readPixels();
    return frame;
}

class CorpusScenesGLTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusScenesGLTest, ShadowsVisibleAndChunkingExact) {
    const std::filesystem::path path = kCorpus / (GetParam() + ".glb");
    if (!std::filesystem::exists(path)) {
        GTEST_SKIP() << "the real-model corpus is absent (" << path.string()
                     << " missing): run bash tools/corpus.sh (needs assimp-utils and assimp-testmodels)";
    }
    const content::LoadedScene loaded = content::GltfLoader::load(path);
    ASSERT_TRUE(loaded.scene.firstCamera().has_value());
    const Frame whole = render(loaded.scene, 1u << 24, false);
    const Frame chunked = render(loaded.scene, 1024, true);
    int differing = 0;
    int shadowed = 0;
    int lit = 0;
    for (std::size_t i = 0; i < whole.image.pixels.size(); i += 4) {
        differing += std::abs(whole.image.pixels[i] - chunked.image.pixels[i]) > 1;
        shadowed += chunked.image.pixels[i] < 40; // the visibility view: black in shadow
        lit += chunked.image.pixels[i] > 215;
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(shadowed, 200) << "no shadow in view";
    EXPECT_GT(lit, 2000) << "no lit ground in view";
    EXPECT_GE(chunked.stats.drawCalls, whole.stats.drawCalls);
}

INSTANTIATE_TEST_SUITE_P(Models, CorpusScenesGLTest,
                         ::testing::Values("suzanne", "human-subdivided", "fzk-haus", "at-at", "jeep", "duck",
                                           "wuson", "epileptic", "dwarf", "cylinder-engine", "terrain"),
                         [](const ::testing::TestParamInfo<std::string>& model) {
                             std::string name = model.param;
                             std::erase(name, '-');
                             return name;
                         });

} // namespace
