#pragma once

#include <engine/Image.h>

#include <filesystem>
#include <string>

namespace sandbox::test {

/// @brief Exit status and combined stdout/stderr of a finished command.
struct RunResult {
    int status = -1;
    std::string output;
};

/// @brief Runs gs-sandbox with `arguments` (shell words), prefixed by `environment` (e.g. "env -u DISPLAY").
RunResult runSandbox(const std::string& arguments, const std::string& environment = "");

/// @brief A fresh, empty folder for one test's files under the build tree.
std::filesystem::path freshFolder(const std::string& name);

/// @brief Reads a PNG as 8-bit RGBA (size {0,0} when it cannot be read).
engine::Image loadPng(const std::filesystem::path& path);

/// @brief How two equally sized images differ, per channel in 0..255.
struct ImageDifference {
    int maxAbsDiff = 0;
    /// Fraction of pixels whose largest channel difference exceeds the tolerance given to compare().
    double fractionAbove = 0.0;
};
ImageDifference compare(const engine::Image& a, const engine::Image& b, int tolerance);

/// @brief Distinct colours in the centre half (both axes) of `image`: a rendered scene has many, an empty or
/// UI-only frame few.
std::size_t distinctCentreColours(const engine::Image& image);

} // namespace sandbox::test
