#pragma once

#include <string>
#include <vector>

namespace engine {

/// @brief Routes KHR_debug messages of the current context: errors are kept until checked,
/// other high/medium severity messages go to stderr.
///
/// The callback must not throw through the driver, so errors are collected and `check()` throws.
class GlDebug {
public:
    /// @brief Installs the callback (synchronous output) on the current context.
    static void install();
    /// @brief Throws GlError listing every GL error recorded since the last check, prefixed by `where`.
    static void check(const std::string& where);
    /// @brief Returns and forgets the errors recorded so far.
    static std::vector<std::string> takeErrors();
};

} // namespace engine
