#pragma once

#include <engine/ShaderLibrary.h>
#include <engine/gl/Program.h>

#include <memory>

namespace shadows {

/// @brief The page-marking shader (shadows/pages.comp) in its two variants, each compiled the first time a
/// light needs it: a directional light's clipmap, and the perspective maps of spot and point lights. Kept
/// apart because one program holding both paid for the perspective path on every directional pixel too.
class PageMarkPrograms {
public:
    explicit PageMarkPrograms(const engine::ShaderLibrary& shaders) : shaders_(shaders) {}

    /// @brief The variant for a light with `faces` perspective maps (0 for a directional light's clipmap).
    [[nodiscard]] const engine::gl::Program& forFaces(int faces);

private:
    const engine::ShaderLibrary& shaders_;
    std::unique_ptr<engine::gl::Program> clipmap_;
    std::unique_ptr<engine::gl::Program> perspective_;
};

} // namespace shadows
