#include "SceneCatalog.h"

#include <cli/OptionValues.h>

#include "SandboxError.h"

#include <algorithm>
#include <system_error>

namespace sandbox {

SceneCatalog::SceneCatalog(std::filesystem::path contentFolder)
    : scenesFolder_(std::move(contentFolder) / "scenes") {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(scenesFolder_, error)) {
        if (entry.path().extension() == ".gltf") {
            names_.push_back(entry.path().stem().string());
        }
    }
    std::sort(names_.begin(), names_.end());
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
        throw SandboxError("unknown scene '" + scene + "' (content scenes: " + known +
                           "; or give a .gltf/.glb path)");
    }
    return scenesFolder_ / (scene + ".gltf");
}

} // namespace sandbox
