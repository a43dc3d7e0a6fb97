#include "content/CageLoader.h"

#include "content/ContentError.h"

#include <OpenMesh/Core/IO/MeshIO.hh> // must precede the mesh type so the readers get registered
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace content {
namespace {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

/// Splits a line into whitespace-separated tokens.
std::vector<std::string> tokenize(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> tokens;
    for (std::string token; in >> token;) {
        tokens.push_back(std::move(token));
    }
    return tokens;
}

/// Reads a file line by line, reporting syntax errors as "<file>:<line>: <detail>".
class LineReader {
public:
    LineReader(const std::filesystem::path& path, std::string source)
        : in_(path), source_(std::move(source)) {
        if (!in_) {
            throw ContentError(source_, "cannot be opened");
        }
    }

    bool next(std::string& line) {
        if (!std::getline(in_, line)) {
            return false;
        }
        ++lineNumber_;
        if (!line.empty() && line.back() == '\r') {
            line.pop_back(); // files written on Windows
        }
        return true;
    }

    [[noreturn]] void fail(const std::string& detail) const {
        throw ContentError(source_ + ":" + std::to_string(lineNumber_), detail);
    }

    // strtof rather than stream extraction: it accepts "nan" and "inf", which must reach validation so the
    // error names the vertex instead of complaining about syntax.
    float parseFloat(const std::string& token) const {
        char* end = nullptr;
        const float value = std::strtof(token.c_str(), &end);
        if (end == token.c_str() || *end != '\0') {
            fail("'" + token + "' is not a number");
        }
        return value;
    }

    long long parseInteger(const std::string& token) const {
        char* end = nullptr;
        errno = 0;
        const long long value = std::strtoll(token.c_str(), &end, 10);
        if (end == token.c_str() || *end != '\0' || errno == ERANGE) {
            fail("'" + token + "' is not an integer");
        }
        return value;
    }

    // Converts a 1-based index as written in the file to a 0-based one; values beyond the vertex count are
    // left for Cage::validate() to report against the face that uses them.
    std::uint32_t toZeroBased(long long oneBased, const std::string& token) const {
        if (oneBased < 1 || oneBased > std::numeric_limits<std::uint32_t>::max()) {
            fail("index " + token + " is out of range");
        }
        return static_cast<std::uint32_t>(oneBased - 1);
    }

    std::uint32_t parseOneBasedIndex(const std::string& token) const {
        return toZeroBased(parseInteger(token), token);
    }

private:
    std::ifstream in_;
    std::string source_;
    int lineNumber_ = 0;
};

/// Parses a "# crease v0 v1 s" or "# corner v s" comment; other comments are ignored.
void parseCreaseComment(const LineReader& reader, const std::string& line, Cage& cage) {
    const auto tokens = tokenize(line.substr(line.find('#') + 1));
    if (tokens.empty()) {
        return;
    }
    if (tokens[0] == "crease") {
        if (tokens.size() != 4) {
            reader.fail("expected '# crease v0 v1 sharpness'");
        }
        cage.creases.push_back({reader.parseOneBasedIndex(tokens[1]), reader.parseOneBasedIndex(tokens[2]),
                                reader.parseFloat(tokens[3])});
    } else if (tokens[0] == "corner") {
        if (tokens.size() != 3) {
            reader.fail("expected '# corner v sharpness'");
        }
        cage.corners.push_back({reader.parseOneBasedIndex(tokens[1]), reader.parseFloat(tokens[2])});
    }
}

/// Raw OBJ scan: vertices, faces and crease comments; other statements (vt, vn, g, usemtl...) are ignored.
void scanObj(const std::filesystem::path& path, Cage& cage) {
    LineReader reader(path, cage.source);
    for (std::string line; reader.next(line);) {
        const auto tokens = tokenize(line);
        if (tokens.empty()) {
            continue;
        }
        if (tokens[0].front() == '#') {
            parseCreaseComment(reader, line, cage);
        } else if (tokens[0] == "v") {
            if (tokens.size() < 4) {
                reader.fail("vertex needs 3 coordinates");
            }
            cage.positions.emplace_back(reader.parseFloat(tokens[1]), reader.parseFloat(tokens[2]),
                                        reader.parseFloat(tokens[3]));
        } else if (tokens[0] == "f") {
            std::vector<std::uint32_t> face;
            for (std::size_t i = 1; i < tokens.size(); ++i) {
                // "v", "v/vt", "v//vn" or "v/vt/vn"; negative indices count back from the latest vertex.
                const std::string vertexToken = tokens[i].substr(0, tokens[i].find('/'));
                const long long value = reader.parseInteger(vertexToken);
                const long long resolved =
                    value < 0 ? static_cast<long long>(cage.positions.size()) + value + 1 : value;
                face.push_back(reader.toZeroBased(resolved, vertexToken));
            }
            cage.faces.push_back(std::move(face));
        }
    }
}

/// Raw ASCII OFF scan ([ST][C][N]OFF header; extra per-vertex and per-face values are ignored). Accepts only
/// the layout OpenMesh's OFF reader understands: the header alone on the first line, the counts on the next,
/// and no comments. OpenMesh reports success on other layouts but reads nothing.
void scanOff(const std::filesystem::path& path, Cage& cage) {
    LineReader reader(path, cage.source);
    auto nextTokens = [&reader](std::vector<std::string>& tokens) {
        for (std::string line; reader.next(line);) {
            if (line.find('#') != std::string::npos) {
                reader.fail("comments are not supported in OFF files");
            }
            tokens = tokenize(line);
            if (!tokens.empty()) {
                return true;
            }
        }
        return false;
    };

    std::vector<std::string> tokens;
    if (!nextTokens(tokens) || tokens[0].size() < 3 || tokens[0].substr(tokens[0].size() - 3) != "OFF") {
        reader.fail("missing OFF header");
    }
    if (tokens.size() > 1) {
        reader.fail(tokens[1] == "BINARY" ? "binary OFF is not supported"
                                          : "the element counts must be on the line after the header");
    }
    if (!nextTokens(tokens) || tokens.size() < 2) {
        reader.fail("expected vertex and face counts");
    }
    const long long vertexCount = reader.parseInteger(tokens[0]);
    const long long faceCount = reader.parseInteger(tokens[1]);
    if (vertexCount < 0 || faceCount < 0) {
        reader.fail("negative element count");
    }

    for (long long v = 0; v < vertexCount; ++v) {
        if (!nextTokens(tokens)) {
            reader.fail("file ends after " + std::to_string(v) + " of " + std::to_string(vertexCount) +
                        " vertices");
        }
        if (tokens.size() < 3) {
            reader.fail("vertex needs 3 coordinates");
        }
        cage.positions.emplace_back(reader.parseFloat(tokens[0]), reader.parseFloat(tokens[1]),
                                    reader.parseFloat(tokens[2]));
    }
    for (long long f = 0; f < faceCount; ++f) {
        if (!nextTokens(tokens)) {
            reader.fail("file ends after " + std::to_string(f) + " of " + std::to_string(faceCount) +
                        " faces");
        }
        const long long size = reader.parseInteger(tokens[0]);
        if (size < 0 || static_cast<std::size_t>(size) >= tokens.size()) {
            reader.fail("face lists fewer indices than its size " + tokens[0]);
        }
        std::vector<std::uint32_t> face;
        for (long long i = 1; i <= size; ++i) {
            const long long index = reader.parseInteger(tokens[static_cast<std::size_t>(i)]);
            if (index < 0 || index > std::numeric_limits<std::uint32_t>::max()) {
                reader.fail("index " + tokens[static_cast<std::size_t>(i)] + " is out of range");
            }
            face.push_back(static_cast<std::uint32_t>(index));
        }
        cage.faces.push_back(std::move(face));
    }
}

/// Replaces the scanned geometry with OpenMesh's reading of the file, after checking it kept every element.
void readThroughOpenMesh(const std::filesystem::path& path, Cage& cage) {
    PolyMesh mesh;
    if (!OpenMesh::IO::read_mesh(mesh, path.string())) {
        throw ContentError(cage.source, "OpenMesh could not read the file");
    }
    // The scanned cage already passed validation, so any shortfall means OpenMesh refused elements itself.
    if (mesh.n_vertices() != cage.positions.size() || mesh.n_faces() != cage.faces.size()) {
        throw ContentError(cage.source, "OpenMesh read " + std::to_string(mesh.n_vertices()) +
                                            " vertices and " + std::to_string(mesh.n_faces()) +
                                            " faces, but the file has " +
                                            std::to_string(cage.positions.size()) + " and " +
                                            std::to_string(cage.faces.size()));
    }
    for (const auto vh : mesh.vertices()) {
        const auto& p = mesh.point(vh);
        cage.positions[static_cast<std::size_t>(vh.idx())] = glm::vec3(p[0], p[1], p[2]);
    }
    for (const auto fh : mesh.faces()) {
        auto& face = cage.faces[static_cast<std::size_t>(fh.idx())];
        face.clear();
        for (const auto vh : mesh.fv_range(fh)) {
            face.push_back(static_cast<std::uint32_t>(vh.idx()));
        }
    }
}

} // namespace

Cage CageLoader::load(const std::filesystem::path& path, std::optional<Scheme> scheme) {
    Cage cage;
    cage.source = path.string();
    if (!std::filesystem::is_regular_file(path)) {
        throw ContentError(cage.source, "file not found");
    }

    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".obj") {
        cage.indexBase = 1;
        scanObj(path, cage);
    } else if (extension == ".off") {
        cage.indexBase = 0;
        scanOff(path, cage);
    } else {
        throw ContentError(cage.source, "unsupported file type '" + extension + "' (expected .obj or .off)");
    }

    cage.scheme = scheme.value_or(cage.isAllTriangles() ? Scheme::Loop : Scheme::CatmullClark);
    cage.validate();
    readThroughOpenMesh(path, cage);
    return cage;
}

} // namespace content
