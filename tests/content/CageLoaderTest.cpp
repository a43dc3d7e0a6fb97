#include "content/CageLoader.h"
#include "content/CageShapes.h"
#include "content/CageWriter.h"
#include "content/ContentError.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <memory>
#include <string>
#include <thread>

namespace content {
namespace {

/// Writes `text` to a file named after the running test, so parallel test processes never share files.
std::filesystem::path writeTempFile(const std::string& text, const std::string& extension) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name) {
        if (c == '/') {
            c = '_'; // parameterised test names contain slashes
        }
    }
    const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / (name + extension);
    std::ofstream(path) << text;
    return path;
}

/// Expects `action` to throw a ContentError whose message is exactly `expected`.
template <typename Action>
void expectContentError(Action&& action, const std::string& expected) {
    try {
        action();
        ADD_FAILURE() << "no ContentError; expected \"" << expected << "\"";
    } catch (const ContentError& error) {
        EXPECT_EQ(error.what(), expected);
    }
}

TEST(CageLoaderTest, LoadsObjWithCreasesAndSlashedNegativeIndices) {
    const auto path = writeTempFile("# a quad and a triangle sharing an edge\n"
                                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                                    "v 2 0.5 0\n"
                                    "f 1/1/1 2/1/1 3/1/1 4/1/1\n"
                                    "f -4//1 -1//1 -3//1\n"
                                    "# crease 2 3 2.5\n"
                                    "#corner 1 4\n",
                                    ".obj");
    const Cage cage = CageLoader::load(path);
    EXPECT_EQ(cage.source, path.string());
    EXPECT_EQ(cage.indexBase, 1u);
    EXPECT_EQ(cage.scheme, Scheme::CatmullClark);
    ASSERT_EQ(cage.positions.size(), 5u);
    EXPECT_EQ(cage.positions[4], glm::vec3(2.0f, 0.5f, 0.0f));
    ASSERT_EQ(cage.faces.size(), 2u);
    EXPECT_EQ(cage.faces[0], (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(cage.faces[1], (std::vector<std::uint32_t>{1, 4, 2}));
    ASSERT_EQ(cage.creases.size(), 1u);
    EXPECT_EQ(cage.creases[0].v0, 1u);
    EXPECT_EQ(cage.creases[0].v1, 2u);
    EXPECT_FLOAT_EQ(cage.creases[0].sharpness, 2.5f);
    ASSERT_EQ(cage.corners.size(), 1u);
    EXPECT_EQ(cage.corners[0].vertex, 0u);
    EXPECT_FLOAT_EQ(cage.corners[0].sharpness, 4.0f);
}

TEST(CageLoaderTest, LoadsOffWithColours) {
    const auto path =
        writeTempFile("COFF\n4 4 6\n"
                      "0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n"
                      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3 128 128 128\n",
                      ".off");
    const Cage cage = CageLoader::load(path);
    EXPECT_EQ(cage.indexBase, 0u);
    EXPECT_EQ(cage.scheme, Scheme::Loop) << "an all-triangle cage defaults to Loop";
    EXPECT_EQ(cage.positions.size(), 4u);
    EXPECT_EQ(cage.faces.size(), 4u);
    EXPECT_EQ(cage.faces[3], (std::vector<std::uint32_t>{1, 2, 3}));
}

TEST(CageLoaderTest, ExplicitSchemeOverridesTheDefault) {
    const auto path =
        writeTempFile("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", ".off");
    EXPECT_EQ(CageLoader::load(path, Scheme::CatmullClark).scheme, Scheme::CatmullClark);
}

TEST(CageLoaderTest, WriterOutputLoadsBackIdentically) {
    Cage cage = CageShapes::box({2, 1, 1}, {2.0f, 1.0f, 1.0f});
    cage.creases.push_back({cage.faces[0][0], cage.faces[0][1], 1.25f});
    cage.corners.push_back({3, 0.1f});
    const auto path = writeTempFile("", ".obj");
    CageWriter::writeObj(cage, path, "round trip");

    const Cage loaded = CageLoader::load(path);
    EXPECT_EQ(loaded.positions, cage.positions);
    EXPECT_EQ(loaded.faces, cage.faces);
    ASSERT_EQ(loaded.creases.size(), 1u);
    EXPECT_EQ(loaded.creases[0].v0, cage.creases[0].v0);
    EXPECT_EQ(loaded.creases[0].v1, cage.creases[0].v1);
    EXPECT_EQ(loaded.creases[0].sharpness, 1.25f);
    ASSERT_EQ(loaded.corners.size(), 1u);
    EXPECT_EQ(loaded.corners[0].vertex, 3u);
    EXPECT_EQ(loaded.corners[0].sharpness, 0.1f);
}

TEST(CageLoaderTest, MissingFileIsReported) {
    const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / "no_such_cage.obj";
    expectContentError([&] { (void)CageLoader::load(path); }, path.string() + ": file not found");
}

TEST(CageLoaderTest, UnsupportedExtensionIsReported) {
    const auto path = writeTempFile("solid x\n", ".stl");
    expectContentError([&] { (void)CageLoader::load(path); },
                       path.string() + ": unsupported file type '.stl' (expected .obj or .off)");
}

TEST(CageLoaderTest, LoopOnQuadsNamesTheFace) {
    const auto path =
        writeTempFile("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 -1 0\nf 2 1 5\nf 1 2 3 4\n", ".obj");
    expectContentError([&] { (void)CageLoader::load(path, Scheme::Loop); },
                       path.string() + ": face 2 has 4 vertices, but Loop subdivision needs triangles");
}

struct BadFile {
    const char* name;
    const char* extension;
    const char* text;
    /// Expected message after "<path>"; OBJ indices are 1-based and OFF indices 0-based, like the files.
    const char* message;
};

class CageLoaderBadFileTest : public ::testing::TestWithParam<BadFile> {};

TEST_P(CageLoaderBadFileTest, FailsWithAMessageNamingTheElement) {
    const BadFile& bad = GetParam();
    const auto path = writeTempFile(bad.text, bad.extension);
    expectContentError([&] { (void)CageLoader::load(path); }, path.string() + bad.message);
}

// Two closed tetrahedra that touch only at vertex 1.
constexpr const char* kTwoConesTouching = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
                                          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                                          "f 1 7 5\nf 1 5 6\nf 1 6 7\nf 5 7 6\n";

const BadFile kBadFiles[] = {
    {"NanVertex", ".obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n",
     ": vertex 3 has non-finite coordinate (nan)"},
    {"InfVertex", ".obj", "v 0 0 0\nv 1 0 -inf\nv 0 1 0\nf 1 2 3\n",
     ": vertex 2 has non-finite coordinate (-inf)"},
    {"NanVertexOff", ".off", "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n",
     ": vertex 2 has non-finite coordinate (nan)"},
    {"EdgeSharedByThreeFaces", ".obj",
     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n",
     ": edge (1,2) is non-manifold (3 faces)"},
    {"TwoConesTouchingAtAVertex", ".obj", kTwoConesTouching,
     ": vertex 1 is non-manifold (its faces form 2 separate fans)"},
    {"ZeroAreaFace", ".obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 3 2\n",
     ": face 2 is degenerate (zero area)"},
    {"RepeatedVertexInFace", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2 3\n",
     ": face 1 is degenerate (vertex 2 repeated)"},
    {"FaceWithTwoVertices", ".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
     ": face 0 has 2 vertices (at least 3 needed)"},
    {"IndexOutOfRange", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
     ": face 1 index 9 is out of range (3 vertices)"},
    {"IndexOutOfRangeOff", ".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
     ": face 0 index 3 is out of range (3 vertices)"},
    {"ZeroIndex", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", ":4: index 0 is out of range"},
    {"NoFaces", ".obj", "v 0 0 0\nv 1 0 0\n", ": no faces"},
    {"UnusedVertex", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n",
     ": vertex 4 is not used by any face"},
    {"InconsistentOrientation", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nf 1 2 3\nf 1 2 4\n",
     ": edge (1,2) has inconsistent orientation (faces 1 and 2 traverse it in the same direction)"},
    {"CreaseNotAnEdge", ".obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n# crease 1 3 2\n",
     ": crease (1,3) is not an edge of the cage"},
    {"NegativeCreaseSharpness", ".obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n# crease 1 2 -1\n",
     ": crease (1,2) has invalid sharpness (-1)"},
    {"CornerOutOfRange", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# corner 7 1\n",
     ": corner 7 is out of range (3 vertices)"},
    {"MalformedCrease", ".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# crease 1 2\n",
     ":5: expected '# crease v0 v1 sharpness'"},
    {"MalformedCoordinate", ".obj", "v 0 0 0\nv 1 zero 0\n", ":2: 'zero' is not a number"},
    {"TruncatedOff", ".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", ":4: file ends after 2 of 3 vertices"},
    {"BinaryOff", ".off", "OFF BINARY\n", ":1: binary OFF is not supported"},
    // OpenMesh's OFF reader reads nothing from these layouts (while reporting success).
    {"CommentInOff", ".off", "OFF\n3 1 0\n# first vertex\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
     ":3: comments are not supported in OFF files"},
    {"CountsOnOffHeaderLine", ".off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
     ":1: the element counts must be on the line after the header"},
};

INSTANTIATE_TEST_SUITE_P(BadFiles, CageLoaderBadFileTest, ::testing::ValuesIn(kBadFiles),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(CageValidateTest, CodeBuiltCagesUseZeroBasedIndicesAndTheirLabel) {
    Cage cage = CageShapes::box({1, 1, 1}, {1.0f, 1.0f, 1.0f});
    cage.positions[5].y = std::numeric_limits<float>::infinity();
    expectContentError([&] { cage.validate(); }, "CageShapes::box: vertex 5 has non-finite coordinate (inf)");
}

TEST(CageValidateTest, ShapesAreValid) {
    EXPECT_NO_THROW(CageShapes::box({3, 2, 1}, {1.0f, 2.0f, 3.0f}).validate());
    EXPECT_NO_THROW(CageShapes::quadSphere(4, 2.0f).validate());
    EXPECT_NO_THROW(CageShapes::torus(12, 5, 2.0f, 0.5f).validate());
}

// Robustness: inputs in memory, limits and inputs written against the loader (see docs/ROBUSTNESS.md).

TEST(CageLoaderMemoryTest, ParsesBothFormatsAndNamesTheSource) {
    const Cage off = CageLoader::loadFromMemory(
        "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
        CageLoader::Format::Off, "mem.off");
    EXPECT_EQ(off.source, "mem.off");
    EXPECT_EQ(off.faces.size(), 4u);
    expectContentError(
        [] { (void)CageLoader::loadFromMemory("v 0 0 0\nv 1 x 0\n", CageLoader::Format::Obj, "mem.obj"); },
        "mem.obj:2: 'x' is not a number");
    expectContentError(
        [] { (void)CageLoader::loadFromMemory("v 0 0 0\n", CageLoader::Format::Off, "mem.off"); },
        "mem.off:1: missing OFF header");
}

TEST(CageLoaderMemoryTest, GarbageIsAContentError) {
    std::string garbage;
    for (int i = 0; i < 4096; ++i) {
        garbage += static_cast<char>((i * 7919) % 256);
    }
    for (const auto format : {CageLoader::Format::Obj, CageLoader::Format::Off}) {
        try {
            (void)CageLoader::loadFromMemory(garbage, format, "garbage");
            ADD_FAILURE() << "garbage loaded";
        } catch (const ContentError& error) {
            EXPECT_EQ(std::string(error.what()).rfind("garbage", 0), 0u) << error.what();
        }
    }
}

TEST(CageLoaderMemoryTest, NumbersMustEndAtTheirTokensEnd) {
    // strtof stopped at the '\0' and read "1\0junk" as 1.
    const std::string text("v 0 0 0\nv 1\0junk 0 0\nv 0 1 0\nf 1 2 3\n", 33);
    expectContentError([&] { (void)CageLoader::loadFromMemory(text, CageLoader::Format::Obj, "mem.obj"); },
                       "mem.obj:2: '1\\x00junk' is not a number");
}

TEST(CageLoaderMemoryTest, HugeIndicesAndCountsAreRejected) {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expectContentError(
        [&] {
            (void)CageLoader::loadFromMemory(triangle + "f 1 2 4294967296\n", CageLoader::Format::Obj, "m");
        },
        "m:4: index 4294967296 is out of range");
    expectContentError(
        [&] {
            (void)CageLoader::loadFromMemory(triangle + "f 1 2 4294967295\n", CageLoader::Format::Obj, "m");
        },
        "m: face 1 index 4294967295 is out of range (3 vertices)");
    expectContentError(
        [&] {
            (void)CageLoader::loadFromMemory(triangle + "f 1 2 99999999999999999999\n",
                                             CageLoader::Format::Obj, "m");
        },
        "m:4: '99999999999999999999' is not an integer");
    // Counts are never used to reserve memory: the file runs out first.
    expectContentError(
        [] {
            (void)CageLoader::loadFromMemory("OFF\n1000000000000 1\n0 0 0\n", CageLoader::Format::Off, "m");
        },
        "m:3: file ends after 1 of 1000000000000 vertices");
    expectContentError(
        [&] {
            (void)CageLoader::loadFromMemory(triangle + "f 1 2 3\n# crease 1 2 nan\n",
                                             CageLoader::Format::Obj, "m");
        },
        "m: crease (1,2) has invalid sharpness (nan)");
}

TEST(CageLoaderMemoryTest, FacesBeyondOpenSubdivsValenceLimitAreNamed) {
    // A polygon of n vertices on the unit circle, as OBJ.
    auto polygon = [](std::size_t n, const std::string& extraIndex) {
        std::string text;
        for (std::size_t i = 0; i < n; ++i) {
            const double angle = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
            text += "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
        }
        text += "f";
        for (std::size_t i = 1; i <= n; ++i) {
            text += " " + std::to_string(i);
        }
        return text + extraIndex + "\n";
    };
    // OpenSubdiv refused it with a console message only ("face with 70000 vertices > 65535 max").
    expectContentError(
        [&] { (void)CageLoader::loadFromMemory(polygon(70000, ""), CageLoader::Format::Obj, "m"); },
        "m: face 1 has 70000 vertices (at most 65535 supported)");
    // Repeats were found by comparing every pair of corners: seconds for this face, minutes for 10^5 corners.
    expectContentError(
        [&] { (void)CageLoader::loadFromMemory(polygon(65534, " 7"), CageLoader::Format::Obj, "m"); },
        "m: face 1 is degenerate (vertex 7 repeated)");
}

TEST(CageLoaderMemoryTest, VerticesBeyondOpenSubdivsValenceLimitAreNamed) {
    // A disc fan of 65536 triangles around vertex 1.
    const int n = 65536;
    std::string text = "v 0 0 0\n";
    for (int i = 0; i < n; ++i) {
        const double angle = 6.283185307179586 * i / n;
        text += "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
    }
    for (int i = 0; i < n; ++i) {
        text += "f 1 " + std::to_string(i + 2) + " " + std::to_string((i + 1) % n + 2) + "\n";
    }
    expectContentError([&] { (void)CageLoader::loadFromMemory(text, CageLoader::Format::Obj, "m"); },
                       "m: vertex 1 is used by 65536 faces (at most 65535 supported)");
}

TEST(CageLoaderTest, MtllibIsNeverFollowed) {
    // OpenMesh's OBJ reader, which used to read the file after the scan, opened whatever `mtllib` named
    // relative to the file ("../../etc/passwd"; a FIFO or /dev/stdin blocked the load forever). The loader
    // now hands OpenMesh only the parsed cage. A FIFO without a writer makes any attempt to open it hang, so
    // the load runs on a thread the test gives up on.
    const auto folder =
        std::filesystem::path(::testing::TempDir()) / ("gs_mtllib_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const auto fifo = folder / "material.mtl";
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto path = folder / "tri.obj";
    std::ofstream(path) << "mtllib material.mtl\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

    auto loaded = std::make_shared<std::promise<std::size_t>>();
    std::thread([loaded, path] {
        try {
            loaded->set_value(CageLoader::load(path).faces.size());
        } catch (...) {
            loaded->set_exception(std::current_exception());
        }
    }).detach();
    auto result = loaded->get_future();
    ASSERT_EQ(result.wait_for(std::chrono::seconds(20)), std::future_status::ready)
        << "the load blocked on mtllib";
    EXPECT_EQ(result.get(), 1u);
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace content
