#pragma once

#include <engine/Error.h>

#include <string>

namespace content {

/// @brief Invalid content: an unreadable file or a cage that cannot be subdivided.
///
/// The message always has the form "<source>: <detail>", where the source is the file path (or a
/// label for cages built in code) and the detail names the offending element, e.g.
/// "cages/bad.obj: edge (3,7) is non-manifold (3 faces)".
class ContentError : public engine::Error {
public:
    /// @brief Builds the error message "<source>: <detail>".
    ContentError(const std::string& source, const std::string& detail);
};

} // namespace content
