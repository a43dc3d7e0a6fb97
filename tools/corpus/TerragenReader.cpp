#include "TerragenReader.h"

#include <content/ContentError.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace corpus {

namespace {

/// Little-endian cursor over the file; every read checks the remaining length.
class Cursor {
public:
    Cursor(std::span<const std::uint8_t> bytes, const std::string& source) : bytes_(bytes), source_(source) {}

    [[nodiscard]] bool atEnd() const { return offset_ >= bytes_.size(); }
    std::string tag(std::size_t length) {
        need(length, "header");
        std::string text(reinterpret_cast<const char*>(bytes_.data() + offset_), length);
        offset_ += length;
        return text;
    }
    std::int16_t int16(const std::string& chunk) {
        need(2, chunk);
        const auto value = static_cast<std::int16_t>(bytes_[offset_] | (bytes_[offset_ + 1] << 8));
        offset_ += 2;
        return value;
    }
    float float32(const std::string& chunk) {
        need(4, chunk);
        std::uint32_t bits = 0;
        for (int i = 3; i >= 0; --i) {
            bits = (bits << 8) | bytes_[offset_ + static_cast<std::size_t>(i)];
        }
        offset_ += 4;
        float value = 0.0f;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }
    void skip(std::size_t count, const std::string& chunk) {
        need(count, chunk);
        offset_ += count;
    }

private:
    void need(std::size_t count, const std::string& chunk) const {
        if (bytes_.size() - offset_ < count) {
            throw content::ContentError(source_, "chunk " + chunk + " is truncated at byte " +
                                                     std::to_string(offset_));
        }
    }
    std::span<const std::uint8_t> bytes_;
    const std::string& source_;
    std::size_t offset_ = 0;
};

} // namespace

Heightfield readTerragen(std::span<const std::uint8_t> bytes, const std::string& source) {
    Cursor cursor(bytes, source);
    if (bytes.size() < 16 || cursor.tag(16) != "TERRAGENTERRAIN ") {
        throw content::ContentError(source, "not a Terragen terrain (header 'TERRAGENTERRAIN ' missing)");
    }
    int size = -1;
    int xPoints = -1;
    int yPoints = -1;
    float verticalScale = 30.0f;
    Heightfield field;
    bool haveElevations = false;
    while (!cursor.atEnd()) {
        const std::string chunk = cursor.tag(4);
        if (chunk == "EOF ") {
            break;
        }
        if (chunk == "SIZE" || chunk == "XPTS" || chunk == "YPTS") {
            const int value = cursor.int16(chunk);
            cursor.skip(2, chunk); // padding
            (chunk == "SIZE" ? size : chunk == "XPTS" ? xPoints : yPoints) = value;
        } else if (chunk == "SCAL") {
            field.spacing = cursor.float32(chunk);
            cursor.float32(chunk); // the file's y spacing; the grid is square in every writer we know of
            verticalScale = cursor.float32(chunk);
        } else if (chunk == "CRAD") {
            cursor.float32(chunk); // planet radius: the terrain is rendered flat
        } else if (chunk == "CRVM") {
            cursor.skip(4, chunk);
        } else if (chunk == "ALTW") {
            field.columns = xPoints > 0 ? xPoints : size + 1;
            field.rows = yPoints > 0 ? yPoints : size + 1;
            if (field.columns < 2 || field.rows < 2 || field.columns > 16384 || field.rows > 16384) {
                throw content::ContentError(source, "ALTW: grid of " + std::to_string(field.columns) + "x" +
                                                        std::to_string(field.rows) +
                                                        " points (SIZE/XPTS/YPTS) is not in 2..16384");
            }
            const float heightScale = cursor.int16(chunk);
            const float baseHeight = cursor.int16(chunk);
            field.elevations.resize(static_cast<std::size_t>(field.columns) * field.rows);
            for (float& elevation : field.elevations) {
                elevation = (baseHeight + cursor.int16(chunk) * heightScale / 65536.0f) * verticalScale;
            }
            if (field.elevations.size() % 2 == 1 && !cursor.atEnd()) {
                cursor.skip(2, chunk); // chunks start on 4-byte boundaries
            }
            haveElevations = true;
        } else {
            throw content::ContentError(source, "unknown chunk '" + chunk + "'");
        }
    }
    if (!haveElevations) {
        throw content::ContentError(source, "no ALTW (elevation) chunk");
    }
    if (!(field.spacing > 0.0f) || !std::isfinite(field.spacing) || !std::isfinite(verticalScale)) {
        throw content::ContentError(source, "SCAL: spacing must be a positive finite number");
    }
    return field;
}

Heightfield readTerragen(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw content::ContentError(path.string(), "cannot open the file");
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                          std::istreambuf_iterator<char>());
    return readTerragen(bytes, path.string());
}

engine::MeshData heightfieldMesh(const Heightfield& field) {
    engine::MeshData mesh;
    mesh.name = "terrain";
    const auto at = [&](int x, int y) {
        x = std::clamp(x, 0, field.columns - 1);
        y = std::clamp(y, 0, field.rows - 1);
        return field.elevations[static_cast<std::size_t>(y) * field.columns + x];
    };
    const glm::vec2 origin =
        -0.5f * field.spacing *
        glm::vec2(static_cast<float>(field.columns - 1), static_cast<float>(field.rows - 1));
    for (int y = 0; y < field.rows; ++y) {
        for (int x = 0; x < field.columns; ++x) {
            mesh.positions.emplace_back(origin.x + static_cast<float>(x) * field.spacing, at(x, y),
                                        -(origin.y + static_cast<float>(y) * field.spacing));
            // Central differences; the file's +y is the mesh's -Z.
            const float dx = (at(x + 1, y) - at(x - 1, y)) / (2.0f * field.spacing);
            const float dy = (at(x, y + 1) - at(x, y - 1)) / (2.0f * field.spacing);
            mesh.normals.push_back(glm::normalize(glm::vec3(-dx, 1.0f, dy)));
        }
    }
    for (int y = 0; y + 1 < field.rows; ++y) {
        for (int x = 0; x + 1 < field.columns; ++x) {
            const auto i = static_cast<std::uint32_t>(y * field.columns + x);
            const auto up = i + static_cast<std::uint32_t>(field.columns);
            // Counter-clockwise seen from above (+Y) with file y mapped to -Z.
            mesh.indices.insert(mesh.indices.end(), {i, i + 1, up + 1, i, up + 1, up});
        }
    }
    mesh.material.baseColor = {0.55f, 0.52f, 0.45f};
    return mesh;
}

} // namespace corpus
