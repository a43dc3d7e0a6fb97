#include "SceneCatalog.h"

#include <cli/OptionValues.h>

#include "SandboxError.h"

#include <algorithm>
#include <system_error>

namespace sandbox {

namespace {

/// Stems of the files in `folder` with `extension`, sorted; none when the folder does not exist.
std::vector<std::string> sortedStems(const std::filesystem::path& folder, const std::string& extension) {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == extension) {
            names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

SceneCatalog::SceneCatalog(std::filesystem::path contentFolder) : contentFolder_(std::move(contentFolder)) {
    // Content scenes first, then the real-model corpus when tools/corpus.sh has built it.
    names_ = sortedStems(contentFolder_ / "scenes", ".gltf");
    contentSceneCount_ = names_.size();
    const std::vector<std::string> corpus = sortedStems(cli::corpusFolder(contentFolder_), ".glb");
    names_.insert(names_.end(), corpus.begin(), corpus.end());
}

std::filesystem::path SceneCatalog::resolve(const std::string& scene) const {
    const std::filesystem::path given = scene;
    if (cli::namesSceneFile(given)) {
        if (!std::filesystem::is_regular_file(given)) {
            throw SandboxError("scene file '" + scene + "' does not exist");
        }
        return given;
    }
    if (std::find(names_.begin(), names_.end(), scene) == names_.end()) {
        std::string known;
        for (const std::string& name : names_) {
            known += (known.empty() ? "" : ", ") + name;
        }
        throw SandboxError("unknown scene '" + scene + "' (scenes: " + known +
                           "; or give a .gltf/.glb path)");
    }
    return cli::scenePath(scene, contentFolder_);
}

} // namespace sandbox
