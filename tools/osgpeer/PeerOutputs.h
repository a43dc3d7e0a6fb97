#pragma once

#include <engine/Image.h>

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace osgpeer {

/// @brief An RGB8 frame as glReadPixels returns it: rows bottom to top, 3 bytes a pixel, no padding.
struct RgbFrame {
    glm::ivec2 size{0};
    std::vector<std::uint8_t> rgb;
};

/// @brief Median, fastest and slowest of a set of frame times, milliseconds.
struct FrameTimes {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

/// @brief Summarises `milliseconds` (median of an even count = mean of the middle two). Empty gives zeros.
[[nodiscard]] FrameTimes summarize(std::vector<double> milliseconds);

/// @brief Per-pixel shadow visibility, rows bottom to top like the frames: luminance(shadowed) /
/// luminance(unshadowed) clamped to [0, 1], or -1 where the unshadowed luminance is below 1/255 (background
/// or a surface facing away from the light). Luminance uses Rec. 709 weights. Frames must match in size.
[[nodiscard]] std::vector<float> visibility(const RgbFrame& shadowed, const RgbFrame& unshadowed);

/// @brief Writes a single-channel Portable Float Map ("Pf", scale -1 = little-endian), `values` rows bottom
/// to top, atomically. Throws engine::IoError naming the path.
void writePfm(const std::filesystem::path& path, glm::ivec2 size, const std::vector<float>& values);

/// @brief The frame as an RGBA image with rows top to bottom (engine::writePng's order), alpha 255.
[[nodiscard]] engine::Image toImage(const RgbFrame& frame);

} // namespace osgpeer
