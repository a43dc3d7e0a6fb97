#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace engine {

/// @brief 8-bit RGBA image, rows top to bottom.
struct Image {
    glm::ivec2 size{0};
    std::vector<std::uint8_t> pixels;

    [[nodiscard]] glm::u8vec4 at(int x, int y) const;
};

/// @brief Writes `image` as PNG atomically: to a temporary file beside `path`, then renamed over it,
/// so a reader never sees half a file. Creates missing parent folders. Throws IoError naming the path.
void writePng(const std::filesystem::path& path, const Image& image);

/// @brief Reads a PNG (or any format stb_image reads) as 8-bit RGBA. Throws IoError naming the path and the
/// reason when it cannot.
Image readPng(const std::filesystem::path& path);

/// @brief Writes `text` to `path` atomically (temporary file + rename). Throws IoError naming the path.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

} // namespace engine
