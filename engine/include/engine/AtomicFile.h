#pragma once

#include <filesystem>
#include <functional>

namespace engine {

/// @brief Writes a file so readers never see it half-written: `write` fills a temporary file beside `path`
/// (returning false on failure), which is then renamed over `path`. Creates missing parent folders.
/// Throws IoError naming `path` when any step fails; the temporary file is removed then.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<bool(const std::filesystem::path& temporary)>& write);

} // namespace engine
