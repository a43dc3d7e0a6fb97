#include <engine/Error.h>
#include <engine/ShaderLibrary.h>

#include <gtest/gtest.h>

using namespace engine;

namespace {

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const ShaderError& error) {
        return error.what();
    }
    return "(no error)";
}

int countOf(const std::string& text, const std::string& needle) {
    int count = 0;
    for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) {
        ++count;
    }
    return count;
}

} // namespace

TEST(ShaderLibraryTest, ResolvesNestedIncludesOnceEach) {
    ShaderLibrary library;
    library.add("main.frag", "#version 450 core\n#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n");
    library.add("a.glsl", "#include \"common.glsl\"\nfloat a;\n");
    library.add("b.glsl", "#include \"common.glsl\"\nfloat b;\n");
    library.add("common.glsl", "float common;\n");
    const auto source = library.preprocess(GL_FRAGMENT_SHADER, "main.frag", {});
    EXPECT_EQ(countOf(source.text, "float common;"), 1);
    EXPECT_LT(source.text.find("float common;"), source.text.find("float a;"));
    EXPECT_LT(source.text.find("float a;"), source.text.find("float b;"));
    EXPECT_EQ(source.fileNames, (std::vector<std::string>{"main.frag", "a.glsl", "common.glsl", "b.glsl"}));
}

TEST(ShaderLibraryTest, IncludeCyclesTerminate) {
    ShaderLibrary library;
    library.add("main.vert", "#version 450 core\n#include \"x.glsl\"\n");
    library.add("x.glsl", "#include \"y.glsl\"\nfloat x;\n");
    library.add("y.glsl", "#include \"x.glsl\"\nfloat y;\n");
    const auto source = library.preprocess(GL_VERTEX_SHADER, "main.vert", {});
    EXPECT_EQ(countOf(source.text, "float x;"), 1);
    EXPECT_EQ(countOf(source.text, "float y;"), 1);
}

TEST(ShaderLibraryTest, IncludesResolveRelativeToTheIncludingFileFirst) {
    ShaderLibrary library;
    library.add("main.frag", "#version 450 core\n#include \"shadows/api.glsl\"\n");
    library.add("shadows/api.glsl", "#include \"math.glsl\"\n");
    library.add("shadows/math.glsl", "float shadowMath;\n");
    library.add("math.glsl", "float rootMath;\n");
    const auto source = library.preprocess(GL_FRAGMENT_SHADER, "main.frag", {});
    EXPECT_NE(source.text.find("shadowMath"), std::string::npos);
    EXPECT_EQ(source.text.find("rootMath"), std::string::npos);
}

TEST(ShaderLibraryTest, DefinesFollowVersionAndLineNumbersResume) {
    ShaderLibrary library;
    library.add("main.frag", "#version 450 core\nfloat first;\n#include \"inc.glsl\"\nfloat fourth;\n");
    library.add("inc.glsl", "float included;\n");
    const std::vector<std::string> defines{"#define GS_X 1"};
    const auto text = library.preprocess(GL_FRAGMENT_SHADER, "main.frag", defines).text;
    EXPECT_EQ(text.rfind("#version 450 core\n#define GS_X 1\n#line 2 0\nfloat first;\n", 0), 0u) << text;
    EXPECT_NE(text.find("#line 100001 0\nfloat included;\n"), std::string::npos) << text;
    EXPECT_NE(text.find("#line 4 0\nfloat fourth;\n"), std::string::npos) << text;
}

TEST(ShaderLibraryTest, SlotsReceiveMatchingChunksInOrder) {
    ShaderLibrary library;
    library.add("main.frag", "#version 450 core\n#pragma gs_slot(declarations)\nvoid main() {\n"
                             "#pragma gs_slot(body)\n}\n");
    const std::vector<ShaderChunk> chunks{{"body", "m1/body", "m1();"},
                                          {"declarations", "m1/decl", "void m1() {}"},
                                          {"body", "m2/body", "m2();"},
                                          {"elsewhere", "m3/x", "unused();"}};
    const auto source = library.preprocess(GL_FRAGMENT_SHADER, "main.frag", {}, chunks);
    EXPECT_LT(source.text.find("void m1() {}"), source.text.find("void main"));
    EXPECT_LT(source.text.find("m1();"), source.text.find("m2();"));
    EXPECT_GT(source.text.find("m1();"), source.text.find("void main"));
    EXPECT_EQ(source.text.find("unused();"), std::string::npos);
    EXPECT_EQ(source.fileNames, (std::vector<std::string>{"main.frag", "m1/decl", "m1/body", "m2/body"}));
}

struct BadSourceCase {
    const char* name;
    const char* mainSource;
    const char* expectedMessage;
};

class ShaderLibraryErrorTest : public testing::TestWithParam<BadSourceCase> {};

TEST_P(ShaderLibraryErrorTest, NamesFileAndLine) {
    ShaderLibrary library;
    library.add("main.frag", GetParam().mainSource);
    library.add("inc.glsl", "float ok;\n#include \"nowhere.glsl\"\n");
    const std::string message =
        errorOf([&] { (void)library.preprocess(GL_FRAGMENT_SHADER, "main.frag", {}); });
    EXPECT_NE(message.find(GetParam().expectedMessage), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ShaderLibraryErrorTest,
    testing::Values(BadSourceCase{"missingInclude", "#version 450 core\n\n#include \"missing.glsl\"\n",
                                  "main.frag:3: cannot find include \"missing.glsl\""},
                    BadSourceCase{"missingNestedInclude", "#version 450 core\n#include \"inc.glsl\"\n",
                                  "inc.glsl:2: cannot find include \"nowhere.glsl\""},
                    BadSourceCase{"malformedInclude", "#version 450 core\n#include <angle.glsl>\n",
                                  "main.frag:2: malformed #include"},
                    BadSourceCase{"noVersion", "float x;\n",
                                  "main.frag:1: the first line must be a #version directive"},
                    BadSourceCase{"lateVersion", "float x;\n#version 450 core\n",
                                  "main.frag:2: #version must be the first"},
                    BadSourceCase{"malformedSlot", "#version 450 core\n#pragma gs_slot\n",
                                  "main.frag:2: malformed slot"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(ShaderLibraryTest, UnknownShaderIsAnError) {
    ShaderLibrary library;
    EXPECT_NE(
        errorOf([&] { (void)library.preprocess(GL_VERTEX_SHADER, "nope.vert", {}); }).find("'nope.vert'"),
        std::string::npos);
}

struct LogCase {
    const char* name;
    const char* driverLog;
    const char* mapped;
};

class ShaderLogMappingTest : public testing::TestWithParam<LogCase> {};

TEST_P(ShaderLogMappingTest, RewritesSourceNumbersToFileNames) {
    const std::vector<std::string> files{"main.frag", "lighting.glsl"};
    EXPECT_EQ(gl::mapShaderLog(GetParam().driverLog, files), GetParam().mapped);
}

INSTANTIATE_TEST_SUITE_P(Drivers, ShaderLogMappingTest,
                         testing::Values(LogCase{"mesa", "0:100012(3): error: `x' undeclared",
                                                 "lighting.glsl:12:3: error: `x' undeclared"},
                                         LogCase{"nvidia", "0(7) : error C1008: undefined variable",
                                                 "main.frag:7 : error C1008: undefined variable"},
                                         LogCase{"amd", "ERROR: 0:100005: 'x' : undeclared identifier",
                                                 "ERROR: lighting.glsl:5: 'x' : undeclared identifier"},
                                         LogCase{"unknownFile", "0:900001(1): error: y",
                                                 "source 9:1:1: error: y"}),
                         [](const auto& test) { return std::string(test.param.name); });
