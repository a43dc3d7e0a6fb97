#include "TestSupport.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <set>
#include <sys/wait.h>

namespace sandbox::test {

RunResult runSandbox(const std::string& arguments, const std::string& environment) {
    const std::string command = environment + " '" GS_SANDBOX "' " + arguments + " 2>&1";
    RunResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
        result.output = "cannot run: " + command;
        return result;
    }
    std::array<char, 4096> buffer{};
    while (const std::size_t read = std::fread(buffer.data(), 1, buffer.size(), pipe)) {
        result.output.append(buffer.data(), read);
    }
    const int status = pclose(pipe);
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::path(GS_TEST_OUT) / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

engine::Image loadPng(const std::filesystem::path& path) {
    engine::Image image;
    int width = 0;
    int height = 0;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) {
        return image;
    }
    image.size = {width, height};
    image.pixels.assign(data, data + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(data);
    return image;
}

ImageDifference compare(const engine::Image& a, const engine::Image& b, int tolerance) {
    ImageDifference difference;
    std::size_t above = 0;
    const std::size_t pixels = a.pixels.size() / 4;
    for (std::size_t p = 0; p < pixels; ++p) {
        int largest = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            largest = std::max(largest, std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c])));
        }
        difference.maxAbsDiff = std::max(difference.maxAbsDiff, largest);
        above += largest > tolerance ? 1 : 0;
    }
    difference.fractionAbove = pixels ? static_cast<double>(above) / static_cast<double>(pixels) : 1.0;
    return difference;
}

std::size_t distinctCentreColours(const engine::Image& image) {
    std::set<std::uint32_t> colours;
    for (int y = image.size.y / 4; y < image.size.y * 3 / 4; ++y) {
        for (int x = image.size.x / 4; x < image.size.x * 3 / 4; ++x) {
            const glm::u8vec4 c = image.at(x, y);
            colours.insert(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
        }
    }
    return colours.size();
}

} // namespace sandbox::test
