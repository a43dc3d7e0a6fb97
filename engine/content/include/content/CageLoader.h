#pragma once

#include "content/Cage.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace content {

/// @brief Reads control cages from OBJ and OFF text.
///
/// The text is parsed by this class alone and validated with Cage::validate(), so every problem is reported
/// as a ContentError naming the source, line or element; OpenMesh then builds its half-edge mesh from the
/// parsed cage as a second topology check. OpenMesh never reads the text itself: its OBJ reader follows
/// `mtllib` to other files and it silently drops (or refuses with a console message) faces it cannot
/// represent.
///
/// OBJ files may carry crease data in comments, with 1-based indices like the rest of the file:
/// @code
/// # crease v0 v1 sharpness
/// # corner v sharpness
/// @endcode
class CageLoader {
public:
    /// @brief Text formats: Wavefront OBJ (`v`/`f` statements, 1-based or negative indices) and ASCII OFF.
    enum class Format { Obj, Off };

    /// @brief Loads and validates the cage in `path` (extension .obj or .off, case-insensitive; ASCII OFF
    /// only) with loadFromMemory.
    /// @param scheme Scheme to assign; when empty, Loop for all-triangle cages and Catmull-Clark otherwise.
    /// @throws ContentError if the file is missing, unreadable or describes an invalid cage.
    [[nodiscard]] static Cage load(const std::filesystem::path& path,
                                   std::optional<Scheme> scheme = std::nullopt);

    /// @brief Parses and validates a cage held in memory.
    /// @param sourceName Names the text in every error ("<sourceName>:<line>: ..." for syntax errors) and
    /// becomes Cage::source.
    /// @param scheme As for load().
    /// @throws ContentError if the text describes an invalid cage.
    [[nodiscard]] static Cage loadFromMemory(std::string_view text, Format format,
                                             const std::string& sourceName,
                                             std::optional<Scheme> scheme = std::nullopt);
};

} // namespace content
