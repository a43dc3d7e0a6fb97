#include "PeerOutputs.h"

#include <engine/AtomicFile.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace osgpeer {
namespace {

float luminance(const std::uint8_t* rgb) {
    return (0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]) / 255.0f;
}

} // namespace

FrameTimes summarize(std::vector<double> milliseconds) {
    FrameTimes times;
    if (milliseconds.empty()) {
        return times;
    }
    std::sort(milliseconds.begin(), milliseconds.end());
    const std::size_t n = milliseconds.size();
    times.median = n % 2 == 1 ? milliseconds[n / 2] : 0.5 * (milliseconds[n / 2 - 1] + milliseconds[n / 2]);
    times.min = milliseconds.front();
    times.max = milliseconds.back();
    return times;
}

std::vector<float> visibility(const RgbFrame& shadowed, const RgbFrame& unshadowed) {
    if (shadowed.size != unshadowed.size || shadowed.rgb.size() != unshadowed.rgb.size()) {
        throw std::invalid_argument("visibility: shadowed and unshadowed frames differ in size");
    }
    const std::size_t pixels = shadowed.rgb.size() / 3;
    std::vector<float> result(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const float lit = luminance(&unshadowed.rgb[3 * i]);
        // Below one 8-bit step the ratio is quantisation noise, and there is no lit surface to shadow.
        if (lit < 1.0f / 255.0f) {
            result[i] = -1.0f;
        } else {
            result[i] = std::clamp(luminance(&shadowed.rgb[3 * i]) / lit, 0.0f, 1.0f);
        }
    }
    return result;
}

void writePfm(const std::filesystem::path& path, glm::ivec2 size, const std::vector<float>& values) {
    if (values.size() != static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y)) {
        throw std::invalid_argument("writePfm: " + path.string() + ": value count does not match the size");
    }
    // The header's negative scale promises little-endian floats whatever machine wrote them.
    std::vector<char> bytes(values.size() * sizeof(float));
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::uint32_t bits = std::bit_cast<std::uint32_t>(values[i]);
        for (std::size_t b = 0; b < 4; ++b) {
            bytes[4 * i + b] = static_cast<char>((bits >> (8 * b)) & 0xffu);
        }
    }
    const std::string header = "Pf\n" + std::to_string(size.x) + " " + std::to_string(size.y) + "\n-1.0\n";
    engine::writeAtomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream file(temporary, std::ios::binary);
        file.write(header.data(), static_cast<std::streamsize>(header.size()));
        file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        file.close();
        return static_cast<bool>(file);
    });
}

engine::Image toImage(const RgbFrame& frame) {
    engine::Image image;
    image.size = frame.size;
    const auto width = static_cast<std::size_t>(frame.size.x);
    const auto height = static_cast<std::size_t>(frame.size.y);
    image.pixels.resize(width * height * 4);
    for (std::size_t y = 0; y < height; ++y) {
        const std::uint8_t* source = &frame.rgb[(height - 1 - y) * width * 3];
        std::uint8_t* target = &image.pixels[y * width * 4];
        for (std::size_t x = 0; x < width; ++x) {
            std::memcpy(target + 4 * x, source + 3 * x, 3);
            target[4 * x + 3] = 255;
        }
    }
    return image;
}

} // namespace osgpeer
