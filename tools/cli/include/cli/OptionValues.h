#pragma once

#include <glm/vec2.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

/// @brief Values of command-line options, shared by the project's CLIs. Each throws std::invalid_argument
/// whose message names the option and the text, e.g. "--size: '0' is not an integer in [1, 16384]".
namespace cli {

inline int integerIn(std::string_view option, const std::string& text, int low, int high) {
    std::size_t used = 0;
    int value = 0;
    try {
        value = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size() || value < low || value > high) {
        throw std::invalid_argument(std::string(option) + ": '" + text + "' is not an integer in [" +
                                    std::to_string(low) + ", " + std::to_string(high) + "]");
    }
    return value;
}

inline float numberIn(std::string_view option, const std::string& text, float low, float high) {
    std::size_t used = 0;
    float value = 0.0f;
    try {
        value = std::stof(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size() || !(value >= low && value <= high)) {
        throw std::invalid_argument(std::string(option) + ": '" + text + "' is not a number in [" +
                                    std::to_string(low) + ", " + std::to_string(high) + "]");
    }
    return value;
}

/// @brief "WIDTHxHEIGHT", each side in [low, high].
inline glm::ivec2 sizeIn(std::string_view option, const std::string& text, int low, int high) {
    const auto x = text.find('x');
    if (x == std::string::npos) {
        throw std::invalid_argument(std::string(option) + ": '" + text + "' is not WIDTHxHEIGHT");
    }
    return {integerIn(option, text.substr(0, x), low, high),
            integerIn(option, text.substr(x + 1), low, high)};
}

/// @brief A tool's name and usage text, for the command-line errors every tool reports alike.
struct Tool {
    std::string_view name;
    std::string_view usage;

    /// @brief "<name>: <message>" and the usage on stderr, then exit 2, the status of a bad command line.
    [[noreturn]] void fail(const std::string& message) const {
        std::cerr << name << ": " << message << "\n" << usage << "\n";
        std::exit(2);
    }

    /// @brief `parser(argc, argv)`; a std::invalid_argument from it (a bad option value) goes to fail().
    template <typename Parse>
    auto parse(Parse parser, int argc, char** argv) const {
        try {
            return parser(argc, argv);
        } catch (const std::invalid_argument& error) {
            fail(error.what());
        }
    }
};

/// @brief A command line's arguments in order, for option loops: `next()` moves to the next argument and
/// `value()` takes the argument after the current option.
class ArgumentList {
public:
    /// @brief The arguments of `tool`'s command line; `--help` anywhere prints its usage and exits 0.
    ArgumentList(int argc, char** argv, const Tool& tool) : arguments_(argv + 1, argv + argc), tool_(tool) {}

    /// @brief Moves to the next argument; false after the last.
    bool next() {
        if (++index_ < arguments_.size() && current() == "--help") {
            std::cout << tool_.usage << "\n";
            std::exit(0);
        }
        return index_ < arguments_.size();
    }
    [[nodiscard]] const std::string& current() const { return arguments_[index_]; }
    /// @brief The current option's value (the next argument). Throws std::invalid_argument("<option> needs a
    /// value") after the last argument.
    std::string value() {
        if (index_ + 1 >= arguments_.size()) {
            throw std::invalid_argument(current() + " needs a value");
        }
        return arguments_[++index_];
    }

private:
    std::vector<std::string> arguments_;
    const Tool& tool_;
    std::size_t index_ = static_cast<std::size_t>(-1); // before the first
};

/// @brief Whether a --scene value names a file (it has a folder or a glTF extension) rather than a content
/// scene.
inline bool namesSceneFile(const std::filesystem::path& scene) {
    return scene.has_parent_path() || scene.extension() == ".gltf" || scene.extension() == ".glb";
}

/// @brief The real-model corpus that tools/corpus.sh builds: the folder `corpus/` beside `contentFolder`.
inline std::filesystem::path corpusFolder(const std::filesystem::path& contentFolder) {
    std::filesystem::path content = std::filesystem::absolute(contentFolder).lexically_normal();
    if (!content.has_filename()) {
        content = content.parent_path(); // "content/" names the folder itself
    }
    return content.parent_path() / "corpus";
}

/// @brief The glTF a --scene value means: the file itself, the content scene
/// <contentFolder>/scenes/<name>.gltf, or else the corpus scene <corpusFolder>/<name>.glb when that exists.
inline std::filesystem::path scenePath(const std::string& scene, const std::filesystem::path& contentFolder) {
    if (namesSceneFile(scene)) {
        return scene;
    }
    const std::filesystem::path contentScene = contentFolder / "scenes" / (scene + ".gltf");
    const std::filesystem::path corpusScene = corpusFolder(contentFolder) / (scene + ".glb");
    return !std::filesystem::exists(contentScene) && std::filesystem::exists(corpusScene) ? corpusScene
                                                                                          : contentScene;
}

} // namespace cli
