#include "GLTestContext.h"

#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/GlDebug.h>
#include <engine/Image.h>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <filesystem>

using namespace engine;

namespace {

std::string compileError(Engine& engine, const ProgramDesc& desc) {
    try {
        (void)engine.programs().get(desc, 0);
    } catch (const ShaderError& error) {
        return error.what();
    }
    return "(compiled)";
}

bool contains(const std::string& text, const std::string& needle) {
    return text.find(needle) != std::string::npos;
}

} // namespace

TEST(ShaderGLTest, CompileErrorNamesTheIncludedFileAndLine) {
    glTestContext();
    Engine engine;
    engine.shaders().add("test/broken.frag", "#version 450 core\n#include \"helpers.glsl\"\nout vec4 c;\n"
                                             "void main() { c = vec4(helper()); }\n");
    engine.shaders().add("test/helpers.glsl",
                         "float helper() {\n  float x = 1.0;\n  return undefinedThing;\n}\n");
    const std::string message = compileError(engine, {"forward.vert", "test/broken.frag"});
    EXPECT_TRUE(contains(message, "test/helpers.glsl:3")) << message;
    EXPECT_TRUE(contains(message, "fragment shader failed to compile")) << message;
    EXPECT_TRUE(contains(message, "forward.vert+test/broken.frag")) << message;
}

TEST(ShaderGLTest, ErrorInTopLevelFileAfterIncludeKeepsItsLineNumber) {
    glTestContext();
    Engine engine;
    engine.shaders().add(
        "test/late.frag",
        "#version 450 core\n#include \"frame.glsl\"\nout vec4 c;\nvoid main() {\n  c = nope;\n}\n");
    const std::string message = compileError(engine, {"forward.vert", "test/late.frag"});
    EXPECT_TRUE(contains(message, "test/late.frag:5")) << message;
}

TEST(ShaderGLTest, MissingIncludeIsReportedBeforeCompiling) {
    glTestContext();
    Engine engine;
    engine.shaders().add("test/missing.frag",
                         "#version 450 core\n#include \"absent.glsl\"\nvoid main() {}\n");
    const std::string message = compileError(engine, {"forward.vert", "test/missing.frag"});
    EXPECT_TRUE(contains(message, "test/missing.frag:2: cannot find include \"absent.glsl\"")) << message;
    EXPECT_EQ(engine.programs().compileCount(), 0u);
}

TEST(ShaderGLTest, ModuleChunkErrorNamesTheChunk) {
    glTestContext();
    Engine engine;
    engine.programs().setChunks({{"light_visibility", "mymodule/visibility", "visibility = notDeclared;"}});
    const std::string message = compileError(engine, {"forward.vert", "forward.frag"});
    EXPECT_TRUE(contains(message, "mymodule/visibility:1")) << message;
}

TEST(ImageGLTest, PngRoundTripsAndLeavesNoTemporaryFile) {
    glTestContext();
    const auto folder =
        std::filesystem::temp_directory_path() / ("gs_png_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    Image image;
    image.size = {3, 2};
    for (int i = 0; i < 6; ++i) {
        image.pixels.insert(image.pixels.end(), {static_cast<std::uint8_t>(40 * i), 7, 200, 255});
    }
    const auto path = folder / "nested" / "out.png";
    writePng(path, image);
    int w = 0;
    int h = 0;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(w, 3);
    EXPECT_EQ(h, 2);
    EXPECT_EQ(std::vector<std::uint8_t>(data, data + 24), image.pixels);
    stbi_image_free(data);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(path.parent_path()), {}), 1);
    std::filesystem::remove_all(folder);
}

TEST(ImageGLTest, UnwritablePathIsAnIoErrorNamingIt) {
    Image image;
    image.size = {1, 1};
    image.pixels = {1, 2, 3, 4};
    try {
        writePng("/proc/definitely/not/here.png", image);
        FAIL();
    } catch (const IoError& error) {
        EXPECT_TRUE(contains(error.what(), "/proc/definitely/not/here.png")) << error.what();
    }
    image.pixels.pop_back();
    EXPECT_THROW(writePng("/tmp/never.png", image), IoError);
}

TEST(GlDebugGLTest, GlErrorsSurfaceAsExceptionsNamingWhere) {
    glTestContext();
    GlDebug::takeErrors();
    glEnable(0xFFFF); // GL_INVALID_ENUM
    try {
        GlDebug::check("deliberate misuse");
        FAIL() << "expected GlError";
    } catch (const GlError& error) {
        EXPECT_NE(std::string(error.what()).find("deliberate misuse: OpenGL reported 1 error"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_NO_THROW(GlDebug::check("after"));
}
