#include "GLTestContext.h"
#include "LitCubeScene.h"

#include <engine/Engine.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Texture.h>

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

using namespace engine;

namespace {

// Larger than one of llvmpipe's 64x64 tiles, so a scissor box can cut across them.
constexpr glm::ivec2 kDepthTargetSize{160, 120};

/// Asks for the view's depth twice in its pre-pass, counting the primitives each call draws; then, given a
/// scissor box, restricts the lighting pass to it (as the sandbox's split view does).
class ViewDepthReader final : public Module {
public:
    [[nodiscard]] std::string_view name() const override { return "view-depth-reader"; }
    void attach(ModuleHost& host) override { host_ = &host; }
    void renderPrePasses(const FrameContext& frame) override {
        texture = 0;
        if (!ask) {
            return;
        }
        GLuint queries[2] = {};
        glCreateQueries(GL_PRIMITIVES_GENERATED, 2, queries);
        glBeginQuery(GL_PRIMITIVES_GENERATED, queries[0]);
        texture = host_->viewDepth(frame);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        glBeginQuery(GL_PRIMITIVES_GENERATED, queries[1]);
        again = host_->viewDepth(frame);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        glGetQueryObjectuiv(queries[0], GL_QUERY_RESULT, &firstPrimitives);
        glGetQueryObjectuiv(queries[1], GL_QUERY_RESULT, &secondPrimitives);
        glDeleteQueries(2, queries);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &boundAfter);
        glGetIntegerv(GL_VIEWPORT, viewportAfter);
        if (scissor) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(scissor->x, scissor->y, scissor->z, scissor->w);
        }
    }
    void debugDraw(const FrameContext&) override { glDisable(GL_SCISSOR_TEST); }

    bool ask = true;
    std::optional<glm::ivec4> scissor; // x, y, width, height
    GLuint texture = 0;
    GLuint again = 0;
    GLuint firstPrimitives = 0;
    GLuint secondPrimitives = 0;
    GLint boundAfter = -1;
    GLint viewportAfter[4] = {};

private:
    ModuleHost* host_ = nullptr;
};

/// The lit cube with a smaller cube in front of it and one behind it, so the depth test decides pixels, seen
/// in perspective: depths near 1, which a copy that converts them may not keep.
LitCubeScene occludedCube() {
    LitCubeScene fixture({0.5f, 0.25f, 0.125f});
    fixture.scene.entity(fixture.camera).camera->projection = ProjectionType::Perspective;
    fixture.addDirectionalLight(0.3f, 1.0f);
    const auto addCube = [&](const char* name, glm::vec3 at, glm::vec3 color) {
        auto mesh = std::make_shared<MeshData>(primitives::cube(1.0f));
        mesh->material.baseColor = color;
        const EntityId id = fixture.scene.create(name);
        fixture.scene.entity(id).mesh = MeshComponent{mesh};
        fixture.scene.entity(id).transform.translation = at;
    };
    addCube("front", {0.6f, 0.4f, 1.5f}, {0.1f, 0.7f, 0.2f});
    addCube("behind", {-1.2f, -0.9f, -2.0f}, {0.2f, 0.2f, 0.9f});
    return fixture;
}

/// A framebuffer of an sRGB colour texture and a depth texture of `depthFormat` (none: GL_NONE).
struct DepthTarget {
    gl::Texture color{GL_SRGB8_ALPHA8, kDepthTargetSize};
    std::optional<gl::Texture> depth;
    gl::Framebuffer framebuffer{"view depth test target"};

    explicit DepthTarget(GLenum depthFormat) {
        framebuffer.attach(GL_COLOR_ATTACHMENT0, color);
        if (depthFormat != GL_NONE) {
            depth.emplace(depthFormat, kDepthTargetSize);
            framebuffer.attach(GL_DEPTH_ATTACHMENT, *depth);
        }
        framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        framebuffer.check();
    }
    [[nodiscard]] FrameTarget frame() const { return {framebuffer.id(), kDepthTargetSize}; }
    [[nodiscard]] std::vector<std::uint8_t> pixels() const {
        std::vector<std::uint8_t> data(static_cast<std::size_t>(kDepthTargetSize.x * kDepthTargetSize.y) * 4);
        glNamedFramebufferReadBuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, kDepthTargetSize.x, kDepthTargetSize.y, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
        return data;
    }
    [[nodiscard]] std::vector<float> depths() const {
        std::vector<float> data(static_cast<std::size_t>(kDepthTargetSize.x * kDepthTargetSize.y));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
        glReadPixels(0, 0, kDepthTargetSize.x, kDepthTargetSize.y, GL_DEPTH_COMPONENT, GL_FLOAT, data.data());
        return data;
    }
};

std::vector<float> textureDepths(GLuint texture) {
    std::vector<float> data(static_cast<std::size_t>(kDepthTargetSize.x * kDepthTargetSize.y));
    glGetTextureImage(texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
    return data;
}

struct FormatCase {
    const char* name;
    GLenum depthFormat;
};

} // namespace

class ViewDepthGLTest : public testing::TestWithParam<FormatCase> {};

TEST_P(ViewDepthGLTest, DrawnOnceAndShadedAgainstWithTheSameImage) {
    glTestContext();
    const LitCubeScene fixture = occludedCube();
    const DepthTarget shared(GetParam().depthFormat);
    const DepthTarget own(GetParam().depthFormat);

    Engine engine;
    auto& reader = static_cast<ViewDepthReader&>(engine.addModule(std::make_unique<ViewDepthReader>()));
    const FrameStats sharedStats = engine.renderFrame(fixture.scene, fixture.camera, shared.frame());
    ASSERT_NE(reader.texture, 0u);
    EXPECT_EQ(reader.again, reader.texture);
    EXPECT_GT(reader.firstPrimitives, 0u);
    EXPECT_EQ(reader.secondPrimitives, 0u) << "the second call of a frame draws nothing";
    EXPECT_EQ(reader.boundAfter, static_cast<GLint>(shared.framebuffer.id()));
    EXPECT_EQ(reader.viewportAfter[2], kDepthTargetSize.x);
    EXPECT_EQ(reader.viewportAfter[3], kDepthTargetSize.y);
    EXPECT_TRUE(sharedStats.sharedViewDepth);
    EXPECT_EQ(textureDepths(reader.texture), shared.depths()) << "the target holds a copy of the view depth";

    Engine apart;
    apart.renderer().shareViewDepth = false;
    auto& refused = static_cast<ViewDepthReader&>(apart.addModule(std::make_unique<ViewDepthReader>()));
    const FrameStats ownStats = apart.renderFrame(fixture.scene, fixture.camera, own.frame());
    EXPECT_EQ(refused.texture, 0u);
    EXPECT_EQ(refused.firstPrimitives, 0u);
    EXPECT_FALSE(ownStats.sharedViewDepth);
    EXPECT_EQ(shared.pixels(), own.pixels());
    EXPECT_EQ(shared.depths(), own.depths());
    EXPECT_EQ(sharedStats.drawCalls, ownStats.drawCalls);
}

INSTANTIATE_TEST_SUITE_P(Formats, ViewDepthGLTest,
                         testing::Values(FormatCase{"D16", GL_DEPTH_COMPONENT16},
                                         FormatCase{"D24", GL_DEPTH_COMPONENT24},
                                         FormatCase{"D32F", GL_DEPTH_COMPONENT32F},
                                         FormatCase{"D32FS8", GL_DEPTH32F_STENCIL8}),
                         [](const auto& test) { return std::string(test.param.name); });

// A lighting pass scissored to part of the target (the sandbox's split view) copies only that box's depth,
// exactly: the pixels outside keep their colour and depth, those inside match the pass that draws its own.
TEST(ViewDepthGLTest, ScissoredLightingPassCopiesOnlyItsBox) {
    glTestContext();
    const LitCubeScene fixture = occludedCube();
    const glm::ivec4 box{37, 21, 70, 64}; // across tile edges at 64 and 128
    std::vector<std::vector<std::uint8_t>> pixels;
    std::vector<std::vector<float>> depths;
    for (const bool share : {true, false}) {
        const DepthTarget target(GL_DEPTH_COMPONENT24);
        const float clearColor[4] = {0.25f, 0.5f, 0.75f, 1.0f};
        const float clearDepth = 0.5f;
        glDisable(GL_FRAMEBUFFER_SRGB); // the lighting pass leaves it on; the clear would encode the colour
        glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, 0, clearColor);
        glClearNamedFramebufferfv(target.framebuffer.id(), GL_DEPTH, 0, &clearDepth);
        Engine engine;
        engine.renderer().shareViewDepth = share;
        auto& reader = static_cast<ViewDepthReader&>(engine.addModule(std::make_unique<ViewDepthReader>()));
        reader.scissor = box;
        EXPECT_EQ(engine.renderFrame(fixture.scene, fixture.camera, target.frame()).sharedViewDepth, share);
        EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
        pixels.push_back(target.pixels());
        depths.push_back(target.depths());
    }
    EXPECT_EQ(pixels[0], pixels[1]);
    EXPECT_EQ(depths[0], depths[1]);
    const auto at = [](int x, int y) { return static_cast<std::size_t>(y * kDepthTargetSize.x + x); };
    // D24 holds 0.5 a step above it.
    EXPECT_NEAR(depths[0][at(box.x - 1, box.y + 5)], 0.5f, 1e-7f) << "outside the box: the depth it held";
    EXPECT_NEAR(depths[0][at(box.x + 5, box.y - 1)], 0.5f, 1e-7f);
    EXPECT_GT(depths[0][at(80, 60)], 0.9f) << "inside: the cube's depth, not the 0.5 it held";
}

// llvmpipe copies the depth of packed 24-bit depth and stencil alone through a shader, not exactly: such a
// target (a window's usual buffer) draws its own depth, with the same image.
TEST(ViewDepthGLTest, ZeroWherePackedDepthAndStencilWouldNotCopyExactly) {
    glTestContext();
    const LitCubeScene fixture = occludedCube();
    const DepthTarget target(GL_DEPTH24_STENCIL8);
    const DepthTarget plain(GL_DEPTH_COMPONENT24);
    Engine engine;
    auto& reader = static_cast<ViewDepthReader&>(engine.addModule(std::make_unique<ViewDepthReader>()));
    EXPECT_FALSE(engine.renderFrame(fixture.scene, fixture.camera, target.frame()).sharedViewDepth);
    EXPECT_EQ(reader.texture, 0u);
    EXPECT_EQ(reader.firstPrimitives, 0u);
    EXPECT_TRUE(engine.renderFrame(fixture.scene, fixture.camera, plain.frame()).sharedViewDepth);
    EXPECT_EQ(target.pixels(), plain.pixels());
}

TEST(ViewDepthGLTest, ZeroWhereTheTargetHasNoDepthBuffer) {
    glTestContext();
    const LitCubeScene fixture = occludedCube();
    const DepthTarget target(GL_NONE);
    Engine engine;
    auto& reader = static_cast<ViewDepthReader&>(engine.addModule(std::make_unique<ViewDepthReader>()));
    const FrameStats stats = engine.renderFrame(fixture.scene, fixture.camera, target.frame());
    EXPECT_EQ(reader.texture, 0u);
    EXPECT_EQ(reader.firstPrimitives, 0u);
    EXPECT_FALSE(stats.sharedViewDepth);
}

TEST(ViewDepthGLTest, ZeroWhereTheTargetIsMultisampled) {
    glTestContext();
    const LitCubeScene fixture = occludedCube();
    GLuint renderbuffers[2] = {};
    glCreateRenderbuffers(2, renderbuffers);
    glNamedRenderbufferStorageMultisample(renderbuffers[0], 4, GL_SRGB8_ALPHA8, kDepthTargetSize.x,
                                          kDepthTargetSize.y);
    glNamedRenderbufferStorageMultisample(renderbuffers[1], 4, GL_DEPTH_COMPONENT24, kDepthTargetSize.x,
                                          kDepthTargetSize.y);
    GLuint framebuffer = 0;
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferRenderbuffer(framebuffer, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[0]);
    glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
    ASSERT_EQ(glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER), GLenum{GL_FRAMEBUFFER_COMPLETE});
    {
        Engine engine;
        auto& reader = static_cast<ViewDepthReader&>(engine.addModule(std::make_unique<ViewDepthReader>()));
        const FrameStats stats =
            engine.renderFrame(fixture.scene, fixture.camera, FrameTarget{framebuffer, kDepthTargetSize});
        EXPECT_EQ(reader.texture, 0u);
        EXPECT_FALSE(stats.sharedViewDepth);
    }
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(2, renderbuffers);
}

TEST(ViewDepthGLTest, ALaterFrameThatDoesNotAskDrawsItsOwnDepth) {
    glTestContext();
    const LitCubeScene fixture = occludedCube();
    const DepthTarget target(GL_DEPTH_COMPONENT24);
    Engine engine;
    auto& reader = static_cast<ViewDepthReader&>(engine.addModule(std::make_unique<ViewDepthReader>()));
    EXPECT_TRUE(engine.renderFrame(fixture.scene, fixture.camera, target.frame()).sharedViewDepth);
    const std::vector<std::uint8_t> asked = target.pixels();
    reader.ask = false;
    EXPECT_FALSE(engine.renderFrame(fixture.scene, fixture.camera, target.frame()).sharedViewDepth);
    EXPECT_EQ(target.pixels(), asked);
    // A depth drawn for one frame is never copied into another: asked again, the next frame draws it anew.
    reader.ask = true;
    EXPECT_TRUE(engine.renderFrame(fixture.scene, fixture.camera, target.frame()).sharedViewDepth);
    EXPECT_GT(reader.firstPrimitives, 0u);
    EXPECT_EQ(target.pixels(), asked);
}
