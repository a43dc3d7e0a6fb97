#include "content/CageWriter.h"

#include "content/ContentError.h"

#include <array>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>

namespace content {
namespace {

// Shortest decimal form that reads back to the same float, so files stay both exact and readable.
std::string formatFloat(float value) {
    std::array<char, 32> buffer{}; // the longest float form, e.g. "-1.17549435e-38", needs 15
    const std::to_chars_result result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

} // namespace

void CageWriter::writeObj(const Cage& cage, const std::filesystem::path& path, std::string_view comment) {
    std::ofstream out(path);
    if (!out) {
        throw ContentError(path.string(), "cannot be opened for writing");
    }
    std::istringstream commentLines{std::string(comment)};
    for (std::string line; std::getline(commentLines, line);) {
        out << "# " << line << '\n';
    }
    for (const glm::vec3& p : cage.positions) {
        out << "v " << formatFloat(p.x) << ' ' << formatFloat(p.y) << ' ' << formatFloat(p.z) << '\n';
    }
    for (const auto& face : cage.faces) {
        out << 'f';
        for (const std::uint32_t v : face) {
            out << ' ' << v + 1;
        }
        out << '\n';
    }
    for (const EdgeCrease& crease : cage.creases) {
        out << "# crease " << crease.v0 + 1 << ' ' << crease.v1 + 1 << ' ' << formatFloat(crease.sharpness)
            << '\n';
    }
    for (const VertexCorner& corner : cage.corners) {
        out << "# corner " << corner.vertex + 1 << ' ' << formatFloat(corner.sharpness) << '\n';
    }
    if (!out.flush()) {
        throw ContentError(path.string(), "write failed");
    }
}

} // namespace content
