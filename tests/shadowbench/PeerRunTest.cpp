// Reading the OpenSceneGraph peer's runs (tools/osgpeer) from a --peer folder: which runs are found and what
// a run's JSON gives (no GL).
#include <shadowbench/PeerRun.h>

#include <engine/Error.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace shadowbench;

namespace {

/// A fresh, empty folder under gtest's temporary directory, named after the running test.
std::filesystem::path freshFolder() {
    const std::filesystem::path folder = std::filesystem::path(testing::TempDir()) / "PeerRunTest" /
                                         testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// The peer's JSON and a 2x1 visibility PFM (lit, umbra) as gs-osgshadow writes them.
void writeRun(const std::filesystem::path& prefix, const std::string& extraJson) {
    writeText(prefix.string() + ".json",
              R"({"technique": "pssm", "osgClass": "osgShadow::ParallelSplitShadowMap",
        "mapSize": 1024, )" +
                  extraJson + R"("shadowedMs": {"median": 2, "min": 1, "max": 3},
        "unshadowedMs": {"median": 1, "min": 1, "max": 1}})");
    const float pixels[2] = {1.0f, 0.0f};
    std::ofstream pfm(prefix.string() + ".visibility.pfm", std::ios::binary);
    pfm << "Pf\n2 1\n-1.0\n";
    pfm.write(reinterpret_cast<const char*>(pixels), sizeof(pixels)); // the test machines are little-endian
}

} // namespace

TEST(PeerRunTest, NamesTheFourTechniquesThenEveryOtherRunSorted) {
    const std::filesystem::path folder = freshFolder();
    std::filesystem::create_directories(folder / "terrain");
    for (const char* name : {"vdsm-csm2", "pssm3", "vdsm", "pssm1"}) {
        writeText(folder / "terrain" / (std::string(name) + ".json"), "{}");
        writeText(folder / "terrain" / (std::string(name) + ".visibility.pfm"), "");
    }
    writeText(folder / "terrain" / "notes.txt", "");
    writeText(folder / "terrain" / "pssm3.png", "");

    const std::vector<std::string> expected = {"vdsm", "sm", "lispsm", "ssm", "pssm1", "pssm3", "vdsm-csm2"};
    EXPECT_EQ(peerRunNames(folder, "terrain"), expected);
}

TEST(PeerRunTest, AMissingSceneFolderGivesTheFourTechniques) {
    const std::vector<std::string> expected = {"vdsm", "sm", "lispsm", "ssm"};
    EXPECT_EQ(peerRunNames(freshFolder(), "no-such-scene"), expected);
}

TEST(PeerRunTest, ReadsShadowMapsAndDefaultsToOneForOlderRuns) {
    const std::filesystem::path folder = freshFolder();
    std::filesystem::create_directories(folder / "torus");
    writeRun(folder / "torus" / "pssm3", R"("shadowMaps": 3, )");
    writeRun(folder / "torus" / "vdsm", "");

    const std::optional<PeerRun> split = loadPeerRun(folder, "torus", "pssm3", {2, 1});
    ASSERT_TRUE(split.has_value());
    EXPECT_EQ(split->technique, "pssm3");
    EXPECT_EQ(split->osgClass, "osgShadow::ParallelSplitShadowMap");
    EXPECT_EQ(split->mapSize, 1024);
    EXPECT_EQ(split->shadowMaps, 3);
    EXPECT_EQ(split->shadowed.median, 2.0);
    EXPECT_EQ(split->visibility, (std::vector<float>{1.0f, 0.0f}));

    const std::optional<PeerRun> older = loadPeerRun(folder, "torus", "vdsm", {2, 1});
    ASSERT_TRUE(older.has_value());
    EXPECT_EQ(older->shadowMaps, 1);
    EXPECT_FALSE(loadPeerRun(folder, "torus", "sm", {2, 1}).has_value());
}

TEST(PeerRunTest, ReadsAllocatorTunedAndLeavesItEmptyForOlderRuns) {
    const std::filesystem::path folder = freshFolder();
    std::filesystem::create_directories(folder / "torus");
    writeRun(folder / "torus" / "vdsm", R"("allocatorTuned": true, )");
    writeRun(folder / "torus" / "sm", R"("allocatorTuned": false, )");
    writeRun(folder / "torus" / "lispsm", "");
    writeRun(folder / "torus" / "ssm", R"("allocatorTuned": "yes", )");

    EXPECT_EQ(loadPeerRun(folder, "torus", "vdsm", {2, 1})->allocatorTuned, std::optional<bool>(true));
    EXPECT_EQ(loadPeerRun(folder, "torus", "sm", {2, 1})->allocatorTuned, std::optional<bool>(false));
    EXPECT_FALSE(loadPeerRun(folder, "torus", "lispsm", {2, 1})->allocatorTuned.has_value());
    EXPECT_THROW(loadPeerRun(folder, "torus", "ssm", {2, 1}), engine::Error);
}
