#pragma once

#include <engine/Error.h>

namespace sandbox {

/// @brief Bad input to the sandbox: a command-line value, a settings file or a scene name. The message names
/// the option or the file and field; the command line reports it and exits with status 2.
class SandboxError : public engine::Error {
public:
    using engine::Error::Error;
};

} // namespace sandbox
