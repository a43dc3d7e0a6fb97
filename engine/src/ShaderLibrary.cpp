#include <engine/Error.h>
#include <engine/ShaderLibrary.h>

#include <optional>
#include <set>

namespace engine {

namespace {

std::string_view trimLeft(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    return first == std::string_view::npos ? std::string_view{} : text.substr(first);
}

bool startsWithDirective(std::string_view line, std::string_view directive) {
    line = trimLeft(line);
    if (line.empty() || line.front() != '#') {
        return false;
    }
    line = trimLeft(line.substr(1));
    return line.starts_with(directive) &&
           (line.size() == directive.size() || line[directive.size()] == ' ' ||
            line[directive.size()] == '\t' || line[directive.size()] == '(' || line[directive.size()] == '"');
}

std::string_view directoryOf(std::string_view path) {
    const auto slash = path.rfind('/');
    return slash == std::string_view::npos ? std::string_view{} : path.substr(0, slash + 1);
}

/// Extracts the text between the first pair of `open`/`close` delimiters, or nullopt.
std::optional<std::string_view> between(std::string_view line, char open, char close) {
    const auto first = line.find(open);
    if (first == std::string_view::npos) {
        return std::nullopt;
    }
    const auto last = line.find(close, first + 1);
    if (last == std::string_view::npos) {
        return std::nullopt;
    }
    return line.substr(first + 1, last - first - 1);
}

class Preprocessor {
public:
    Preprocessor(const std::map<std::string, std::string, std::less<>>& files,
                 std::span<const std::string> defines, std::span<const ShaderChunk> chunks)
        : files_(files), defines_(defines), chunks_(chunks) {}

    gl::ShaderStageSource run(GLenum stage, std::string_view name) {
        const auto root = files_.find(name);
        if (root == files_.end()) {
            throw ShaderError("shader '" + std::string(name) + "' is not in the shader library");
        }
        included_.insert(root->first);
        emitFile(root->first, root->second, true);
        if (!sawVersion_) {
            throw ShaderError(root->first + ":1: the first line must be a #version directive");
        }
        return {stage, std::move(out_), std::move(fileNames_)};
    }

private:
    void emitFile(const std::string& name, const std::string& source, bool isRoot) {
        const std::size_t index = fileNames_.size();
        fileNames_.push_back(name);
        if (!isRoot) {
            out_ += lineDirective(index, 1);
        }
        std::size_t lineNumber = 0;
        std::size_t position = 0;
        while (position <= source.size()) {
            const auto end = source.find('\n', position);
            const std::string_view line = std::string_view(source).substr(
                position, end == std::string::npos ? std::string::npos : end - position);
            ++lineNumber;
            const std::string where = name + ":" + std::to_string(lineNumber) + ": ";
            if (lineNumber >= static_cast<std::size_t>(gl::kShaderLinesPerFile)) {
                throw ShaderError(name + ": more than " + std::to_string(gl::kShaderLinesPerFile - 1) +
                                  " lines");
            }
            const std::string resume = lineDirective(index, lineNumber + 1);
            if (startsWithDirective(line, "version")) {
                if (!isRoot || lineNumber != 1) {
                    throw ShaderError(where + "#version must be the first line of the top-level shader");
                }
                sawVersion_ = true;
                out_ += std::string(line) + "\n";
                for (const std::string& define : defines_) {
                    out_ += define + "\n";
                }
                out_ += resume;
            } else if (startsWithDirective(line, "include")) {
                const auto target = between(line, '"', '"');
                if (!target || target->empty()) {
                    throw ShaderError(where + "malformed #include (expected #include \"file.glsl\")");
                }
                includeFile(where, name, *target);
                out_ += resume;
            } else if (startsWithDirective(line, "pragma") &&
                       trimLeft(line).find("gs_slot") != std::string_view::npos) {
                const auto slot = between(line, '(', ')');
                if (!slot || slot->empty()) {
                    throw ShaderError(where + "malformed slot (expected #pragma gs_slot(name))");
                }
                fillSlot(*slot);
                out_ += resume;
            } else {
                out_ += line;
                out_ += '\n';
            }
            if (end == std::string::npos) {
                break;
            }
            position = end + 1;
        }
    }

    static std::string lineDirective(std::size_t file, std::size_t line) {
        return "#line " + std::to_string(file * gl::kShaderLinesPerFile + line) + " 0\n";
    }

    void includeFile(const std::string& where, const std::string& includer, std::string_view target) {
        auto found = files_.find(std::string(directoryOf(includer)) + std::string(target));
        if (found == files_.end()) {
            found = files_.find(target);
        }
        if (found == files_.end()) {
            throw ShaderError(where + "cannot find include \"" + std::string(target) + "\"");
        }
        if (included_.insert(found->first).second) {
            emitFile(found->first, found->second, false);
        }
    }

    /// Chunks are preprocessed like files, so they may `#include` the module's own GLSL files.
    void fillSlot(std::string_view slot) {
        for (const ShaderChunk& chunk : chunks_) {
            if (chunk.slot == slot) {
                emitFile(chunk.origin, chunk.source, false);
            }
        }
    }

    const std::map<std::string, std::string, std::less<>>& files_;
    std::span<const std::string> defines_;
    std::span<const ShaderChunk> chunks_;
    std::set<std::string, std::less<>> included_;
    std::vector<std::string> fileNames_;
    std::string out_;
    bool sawVersion_ = false;
};

} // namespace

void ShaderLibrary::add(std::span<const EmbeddedShaderFile> files) {
    for (const EmbeddedShaderFile& file : files) {
        add(std::string(file.name), std::string(file.source));
    }
}

void ShaderLibrary::add(std::string name, std::string source) {
    files_[std::move(name)] = std::move(source);
}

bool ShaderLibrary::contains(std::string_view name) const {
    return files_.find(name) != files_.end();
}

gl::ShaderStageSource ShaderLibrary::preprocess(GLenum stage, std::string_view name,
                                                std::span<const std::string> defines,
                                                std::span<const ShaderChunk> chunks) const {
    return Preprocessor(files_, defines, chunks).run(stage, name);
}

} // namespace engine
