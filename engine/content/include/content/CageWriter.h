#pragma once

#include "content/Cage.h"

#include <filesystem>
#include <string_view>

namespace content {

/// @brief Writes control cages as OBJ files that CageLoader reads back, creases included.
class CageWriter {
public:
    /// @brief Writes `cage` to `path` as OBJ, with creases and corners as `# crease` / `# corner` comments.
    /// @param comment Free text written as leading comment lines (one per line of the text); its lines must
    /// not start with "crease" or "corner", which CageLoader would read as crease data.
    /// @throws ContentError if the file cannot be written.
    static void writeObj(const Cage& cage, const std::filesystem::path& path, std::string_view comment = {});
};

} // namespace content
