// readTerragen: the chunks of the format, elevation scaling, the padding after an odd point count, and named
// errors for broken files; heightfieldMesh: grid, winding and normals.
#include <TerragenReader.h>

#include <content/ContentError.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

/// A Terragen file of `size`+1 square points, written the way the format describes it.
class TerFile {
public:
    TerFile() { text("TERRAGENTERRAIN "); }
    TerFile& text(const std::string& t) {
        bytes.insert(bytes.end(), t.begin(), t.end());
        return *this;
    }
    TerFile& int16(int v) {
        bytes.push_back(static_cast<std::uint8_t>(v & 0xff));
        bytes.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
        return *this;
    }
    TerFile& float32(float f) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &f, 4);
        for (int i = 0; i < 4; ++i) {
            bytes.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
        }
        return *this;
    }
    std::vector<std::uint8_t> bytes;
};

TerFile threeByThree() {
    TerFile f;
    f.text("SIZE").int16(2).int16(0).text("SCAL").float32(10.0f).float32(10.0f).float32(2.0f);
    f.text("ALTW").int16(16384).int16(5); // height scale 0.25 per unit, base 5
    for (int i = 0; i < 9; ++i) {
        f.int16(i * 2);
    }
    f.int16(0).text("EOF "); // 9 points: 2 bytes of padding
    return f;
}

TEST(TerragenReaderTest, ReadsChunksAndScalesElevations) {
    const corpus::Heightfield field = corpus::readTerragen(threeByThree().bytes, "mem.ter");
    EXPECT_EQ(field.columns, 3);
    EXPECT_EQ(field.rows, 3);
    EXPECT_FLOAT_EQ(field.spacing, 10.0f);
    ASSERT_EQ(field.elevations.size(), 9u);
    // (base + value * scale / 65536) * SCAL.z = (5 + 2i * 0.25) * 2
    EXPECT_FLOAT_EQ(field.elevations[0], 10.0f);
    EXPECT_FLOAT_EQ(field.elevations[8], (5.0f + 4.0f) * 2.0f);
}

TEST(TerragenReaderTest, XptsAndYptsOverrideSize) {
    TerFile f;
    f.text("SIZE").int16(3).int16(0).text("XPTS").int16(2).int16(0).text("YPTS").int16(3).int16(0);
    f.text("ALTW").int16(1).int16(0);
    for (int i = 0; i < 6; ++i) {
        f.int16(0);
    }
    f.text("EOF ");
    const corpus::Heightfield field = corpus::readTerragen(f.bytes, "mem.ter");
    EXPECT_EQ(field.columns, 2);
    EXPECT_EQ(field.rows, 3);
}

void expectError(const std::vector<std::uint8_t>& bytes, const std::string& fragment) {
    try {
        (void)corpus::readTerragen(bytes, "bad.ter");
        FAIL() << "accepted a broken file; wanted an error containing '" << fragment << "'";
    } catch (const content::ContentError& error) {
        EXPECT_NE(std::string(error.what()).find("bad.ter"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
}

TEST(TerragenReaderTest, BrokenFilesAreRefusedNamingTheProblem) {
    expectError({'x', 'y'}, "TERRAGENTERRAIN");
    std::vector<std::uint8_t> truncated = threeByThree().bytes;
    truncated.resize(truncated.size() - 12);
    expectError(truncated, "ALTW is truncated");
    TerFile unknown;
    unknown.text("WHAT").int16(0);
    expectError(unknown.bytes, "unknown chunk 'WHAT'");
    TerFile noElevations;
    noElevations.text("SIZE").int16(2).int16(0).text("EOF ");
    expectError(noElevations.bytes, "no ALTW");
    TerFile hugeGrid;
    hugeGrid.text("XPTS").int16(-5).int16(0).text("YPTS").int16(3).int16(0).text("ALTW");
    expectError(hugeGrid.bytes, "not in 2..16384");
}

TEST(TerragenReaderTest, MeshIsAGridFacingUpWithUnitNormals) {
    corpus::Heightfield field;
    field.columns = 4;
    field.rows = 3;
    field.spacing = 2.0f;
    field.elevations.assign(12, 1.0f);
    const engine::MeshData mesh = corpus::heightfieldMesh(field);
    EXPECT_EQ(mesh.positions.size(), 12u);
    EXPECT_EQ(mesh.triangleCount(), 2u * 3u * 2u);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[i]];
        const glm::vec3 b = mesh.positions[mesh.indices[i + 1]];
        const glm::vec3 c = mesh.positions[mesh.indices[i + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f); // counter-clockwise seen from above
    }
    for (const glm::vec3& n : mesh.normals) {
        EXPECT_NEAR(n.y, 1.0f, 1e-6f);
    }
    EXPECT_FLOAT_EQ(mesh.positions.front().x, -3.0f); // centred: 3 cells of 2 m
}

} // namespace
