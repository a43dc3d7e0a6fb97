#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sandbox {

/// @brief The content scenes (content/scenes/NAME.gltf), the real-model corpus (corpus/NAME.glb, when built)
/// and how scene names given by people resolve to files.
class SceneCatalog {
public:
    explicit SceneCatalog(std::filesystem::path contentFolder);

    /// @brief Names of the content scenes, sorted, then those of the corpus, sorted.
    [[nodiscard]] const std::vector<std::string>& names() const { return names_; }
    /// @brief Names of the content scenes only, sorted.
    [[nodiscard]] std::vector<std::string> contentNames() const {
        return {names_.begin(), names_.begin() + static_cast<std::ptrdiff_t>(contentSceneCount_)};
    }

    /// @brief The file of `scene`: a bare name is a content scene; anything with a folder or a .gltf/.glb
    /// extension is a path. Throws SandboxError when the content scene or the file does not exist (listing
    /// the content scenes).
    [[nodiscard]] std::filesystem::path resolve(const std::string& scene) const;

private:
    std::filesystem::path contentFolder_;
    std::vector<std::string> names_;
    std::size_t contentSceneCount_ = 0;
};

} // namespace sandbox
