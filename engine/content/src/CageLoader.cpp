#include "content/CageLoader.h"

#include "content/ContentError.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iterator>
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

/// A token from the file as error messages show it: control and non-ASCII bytes as \xNN (a '\0' would end the
/// message early), and cut short, since a token may be as long as the file.
std::string shown(const std::string& token) {
    constexpr std::size_t kLongest = 40;
    std::string out;
    for (const char c : token.substr(0, kLongest)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte >= 0x7f) {
            constexpr const char* kHex = "0123456789abcdef";
            out += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
        } else {
            out += c;
        }
    }
    return token.size() > kLongest ? out + "..." : out;
}

/// Reads text line by line, reporting syntax errors as "<source>:<line>: <detail>".
class LineReader {
public:
    LineReader(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

    bool next(std::string& line) {
        if (position_ >= text_.size()) {
            return false;
        }
        const std::size_t end = std::min(text_.find('\n', position_), text_.size());
        line.assign(text_.substr(position_, end - position_));
        position_ = end + 1;
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
    // Both parsers must consume the whole token: stopping at a '\0' inside it would accept "1\0junk" as 1.
    float parseFloat(const std::string& token) const {
        char* end = nullptr;
        const float value = std::strtof(token.c_str(), &end);
        if (end == token.c_str() || end != token.c_str() + token.size()) {
            fail("'" + shown(token) + "' is not a number");
        }
        return value;
    }

    long long parseInteger(const std::string& token) const {
        char* end = nullptr;
        errno = 0;
        const long long value = std::strtoll(token.c_str(), &end, 10);
        if (end == token.c_str() || end != token.c_str() + token.size() || errno == ERANGE) {
            fail("'" + shown(token) + "' is not an integer");
        }
        return value;
    }

    // Converts a 1-based index as written in the file to a 0-based one; values beyond the vertex count are
    // left for Cage::validate() to report against the face that uses them.
    std::uint32_t toZeroBased(long long oneBased, const std::string& token) const {
        if (oneBased < 1 || oneBased > std::numeric_limits<std::uint32_t>::max()) {
            fail("index " + shown(token) + " is out of range");
        }
        return static_cast<std::uint32_t>(oneBased - 1);
    }

    std::uint32_t parseOneBasedIndex(const std::string& token) const {
        return toZeroBased(parseInteger(token), token);
    }

private:
    std::string_view text_;
    std::size_t position_ = 0;
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
void scanObj(std::string_view text, Cage& cage) {
    LineReader reader(text, cage.source);
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
/// the layout OpenMesh's OFF reader understands, so accepted files stay readable by OpenMesh-based tools: the
/// header alone on the first line, the counts on the next, and no comments. OpenMesh reports success on other
/// layouts but reads nothing.
void scanOff(std::string_view text, Cage& cage) {
    LineReader reader(text, cage.source);
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

/// Builds OpenMesh's half-edge mesh from the validated cage: OpenMesh refuses faces it cannot link (complex
/// vertices or edges), a second opinion on the topology from the library the cage format was designed
/// against.
void checkWithOpenMesh(const Cage& cage) {
    PolyMesh mesh;
    std::vector<PolyMesh::VertexHandle> vertices;
    vertices.reserve(cage.positions.size());
    for (const glm::vec3& p : cage.positions) {
        vertices.push_back(mesh.add_vertex(PolyMesh::Point(p.x, p.y, p.z)));
    }
    std::vector<PolyMesh::VertexHandle> face;
    for (std::size_t f = 0; f < cage.faces.size(); ++f) {
        face.clear();
        for (const std::uint32_t v : cage.faces[f]) {
            face.push_back(vertices[v]);
        }
        if (!mesh.add_face(face).is_valid()) {
            throw ContentError(cage.source, "face " + std::to_string(f + cage.indexBase) +
                                                " cannot be added to OpenMesh's half-edge mesh");
        }
    }
}

} // namespace

Cage CageLoader::load(const std::filesystem::path& path, std::optional<Scheme> scheme) {
    const std::string source = path.string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw ContentError(source, "file not found");
    }
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".obj" && extension != ".off") {
        throw ContentError(source, "unsupported file type '" + extension + "' (expected .obj or .off)");
    }
    if (const auto size = std::filesystem::file_size(path, error);
        !error && size > std::numeric_limits<std::uint32_t>::max()) {
        throw ContentError(source, "is larger than 4 GiB, which cages may not be");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw ContentError(source, "cannot be opened");
    }
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    return loadFromMemory(text, extension == ".obj" ? Format::Obj : Format::Off, source, scheme);
}

Cage CageLoader::loadFromMemory(std::string_view text, Format format, const std::string& sourceName,
                                std::optional<Scheme> scheme) {
    // Every face corner takes at least two characters, so this keeps Cage::validate's 32-bit corner count
    // from wrapping around.
    if (text.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw ContentError(sourceName, "is larger than 4 GiB, which cages may not be");
    }
    Cage cage;
    cage.source = sourceName;
    if (format == Format::Obj) {
        cage.indexBase = 1;
        scanObj(text, cage);
    } else {
        cage.indexBase = 0;
        scanOff(text, cage);
    }
    cage.scheme = scheme.value_or(cage.isAllTriangles() ? Scheme::Loop : Scheme::CatmullClark);
    cage.validate();
    checkWithOpenMesh(cage);
    return cage;
}

} // namespace content
