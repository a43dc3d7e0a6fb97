#pragma once

#include <filesystem>
#include <system_error>

namespace cli {

/// @brief The content folder scene names resolve in by default. An installed tool uses the installed content
/// (<prefix>/share/GradientShadows/content, reached from the executable's folder, so a moved prefix still
/// works); a tool run from the build tree uses the source tree's content/.
inline std::filesystem::path defaultContentFolder() {
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path installed =
            (executable.parent_path() / GS_CONTENT_DIR_FROM_BINDIR).lexically_normal();
        if (std::filesystem::is_directory(installed / "scenes", error)) {
            return installed;
        }
    }
    return GS_SOURCE_CONTENT_DIR;
}

} // namespace cli
