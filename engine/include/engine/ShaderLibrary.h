#pragma once

#include <engine/EmbeddedShaderFile.h>
#include <engine/gl/Program.h>

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

/// @brief GLSL code a module injects at a named `#pragma gs_slot(<slot>)` point of an engine shader.
struct ShaderChunk {
    /// Slot name, e.g. "declarations" or "light_visibility" (see docs/MODULES.md for each slot's contract).
    std::string slot;
    /// Name used in error messages, e.g. "shadows/visibility.glsl".
    std::string origin;
    std::string source;
};

/// @brief Holds GLSL files by name and preprocesses them: `#include`, define injection and slot filling.
///
/// Includes resolve first relative to the including file's folder, then from the root. Each file is
/// included at most once per stage (include-guard semantics), which also makes cycles harmless.
class ShaderLibrary {
public:
    /// @brief Adds embedded files; a later file of the same name replaces an earlier one.
    void add(std::span<const EmbeddedShaderFile> files);
    void add(std::string name, std::string source);
    [[nodiscard]] bool contains(std::string_view name) const;

    /// @brief Preprocesses `name` for `stage`, injecting `defines` after `#version` and filling slots
    /// with `chunks`. Throws ShaderError naming file and line for a missing include or bad directive.
    [[nodiscard]] gl::ShaderStageSource preprocess(GLenum stage, std::string_view name,
                                                   std::span<const std::string> defines,
                                                   std::span<const ShaderChunk> chunks = {}) const;

private:
    std::map<std::string, std::string, std::less<>> files_;
};

} // namespace engine
