#include <shadowbench/PeerRun.h>

#include <engine/Error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

namespace shadowbench {

namespace {

std::vector<char> readBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw engine::Error(path.string() + ": cannot open the file");
    }
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

PassTiming timing(const nlohmann::json& document, const char* field, const std::filesystem::path& path) {
    if (!document.contains(field) || !document[field].is_object()) {
        throw engine::Error(path.string() + ": " + field + ": expected an object with median, min, max");
    }
    const nlohmann::json& times = document[field];
    for (const char* key : {"median", "min", "max"}) {
        if (!times.contains(key) || !times[key].is_number()) {
            throw engine::Error(path.string() + ": " + field + "." + key + ": expected a number");
        }
    }
    return {times["median"].get<double>(), times["min"].get<double>(), times["max"].get<double>()};
}

/// Single-channel little-endian PFM, rows bottom to top in the file, returned top to bottom.
std::vector<float> readPfm(const std::filesystem::path& path, glm::ivec2 size) {
    const std::vector<char> bytes = readBytes(path);
    std::istringstream header(
        std::string(bytes.begin(),
                    bytes.begin() + std::min<std::ptrdiff_t>(64, static_cast<std::ptrdiff_t>(bytes.size()))));
    std::string magic;
    int width = 0;
    int height = 0;
    float scale = 0.0f;
    header >> magic >> width >> height >> scale;
    if (!header || magic != "Pf" || scale >= 0.0f) {
        throw engine::Error(path.string() +
                            ": not a little-endian single-channel PFM ('Pf', negative scale)");
    }
    if (width != size.x || height != size.y) {
        throw engine::Error(path.string() + ": image is " + std::to_string(width) + "x" +
                            std::to_string(height) + ", the benchmark renders " + std::to_string(size.x) +
                            "x" + std::to_string(size.y));
    }
    const auto dataStart =
        static_cast<std::size_t>(header.tellg()) + 1; // one whitespace byte ends the header
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (bytes.size() < dataStart + 4 * count) {
        throw engine::Error(path.string() + ": pixel data is truncated");
    }
    std::vector<float> values(count);
    for (int y = 0; y < height; ++y) {
        const std::size_t fileRow = static_cast<std::size_t>(height - 1 - y);
        std::memcpy(values.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width),
                    bytes.data() + dataStart + 4 * fileRow * static_cast<std::size_t>(width),
                    4 * static_cast<std::size_t>(width));
    }
    return values;
}

} // namespace

std::vector<std::string> peerRunNames(const std::filesystem::path& folder, const std::string& scene) {
    std::vector<std::string> names = {"vdsm", "sm", "lispsm", "ssm"};
    std::vector<std::string> others;
    std::error_code error; // a missing folder ends the iteration at once
    for (const auto& entry : std::filesystem::directory_iterator(folder / scene, error)) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".json" &&
            std::find(names.begin(), names.end(), stem) == names.end()) {
            others.push_back(stem);
        }
    }
    std::sort(others.begin(), others.end());
    names.insert(names.end(), others.begin(), others.end());
    return names;
}

std::optional<PeerRun> loadPeerRun(const std::filesystem::path& folder, const std::string& scene,
                                   const std::string& technique, glm::ivec2 size) {
    const std::filesystem::path jsonPath = folder / scene / (technique + ".json");
    if (!std::filesystem::exists(jsonPath)) {
        return std::nullopt;
    }
    const std::vector<char> text = readBytes(jsonPath);
    const nlohmann::json document = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (document.is_discarded() || !document.is_object()) {
        throw engine::Error(jsonPath.string() + ": not a JSON object");
    }
    PeerRun run;
    run.technique = technique;
    run.osgClass = document.value("osgClass", std::string());
    run.renderer = document.value("renderer", std::string());
    run.mapSize = document.value("mapSize", 0);
    run.shadowMaps = document.value("shadowMaps", 1);
    run.shadowed = timing(document, "shadowedMs", jsonPath);
    run.unshadowed = timing(document, "unshadowedMs", jsonPath);
    if (const auto tuned = document.find("allocatorTuned"); tuned != document.end()) {
        if (!tuned->is_boolean()) {
            throw engine::Error(jsonPath.string() + ": allocatorTuned is not true or false");
        }
        run.allocatorTuned = tuned->get<bool>();
    }
    run.visibility = readPfm(folder / scene / (technique + ".visibility.pfm"), size);
    return run;
}

} // namespace shadowbench
