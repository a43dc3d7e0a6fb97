#pragma once

#include <stdexcept>
#include <string>

namespace engine {

/// @brief Base of every error the engine reports; messages name the file, field or object at fault.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief No usable GL context (no EGL device/driver, no display, version too old).
class ContextError : public Error {
public:
    using Error::Error;
};

/// @brief GLSL preprocessing, compile or link failure; the message names file and line.
class ShaderError : public Error {
public:
    using Error::Error;
};

/// @brief An OpenGL error reported through KHR_debug.
class GlError : public Error {
public:
    using Error::Error;
};

/// @brief A module could not be found, loaded or did not match the engine's ABI.
class ModuleError : public Error {
public:
    using Error::Error;
};

/// @brief File input/output failure (path named in the message).
class IoError : public Error {
public:
    using Error::Error;
};

} // namespace engine
