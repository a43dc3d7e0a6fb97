#pragma once

#include "content/Cage.h"

#include <filesystem>
#include <optional>

namespace content {

/// @brief Reads control cages from OBJ and OFF files.
///
/// Geometry and faces are read through OpenMesh. Because OpenMesh silently drops (or refuses with a
/// console message) faces it cannot represent, the file is also scanned by this class first and validated
/// with Cage::validate(), so every problem is reported as a ContentError naming the file and element.
///
/// OBJ files may carry crease data in comments, with 1-based indices like the rest of the file:
/// @code
/// # crease v0 v1 sharpness
/// # corner v sharpness
/// @endcode
class CageLoader {
public:
    /// @brief Loads and validates the cage in `path` (extension .obj or .off, case-insensitive; ASCII OFF
    /// only).
    /// @param scheme Scheme to assign; when empty, Loop for all-triangle cages and Catmull-Clark otherwise.
    /// @throws ContentError if the file is missing, unreadable or describes an invalid cage.
    [[nodiscard]] static Cage load(const std::filesystem::path& path,
                                   std::optional<Scheme> scheme = std::nullopt);
};

} // namespace content
