#pragma once

#include <span>
#include <string_view>

namespace engine {

/// @brief One GLSL file embedded into a binary at build time (see cmake/EmbedShaders.cmake).
struct EmbeddedShaderFile {
    /// Path relative to the shader root; the name `#include` directives refer to.
    std::string_view name;
    std::string_view source;
};

} // namespace engine
