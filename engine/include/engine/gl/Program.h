#pragma once

#include <engine/gl/GlObject.h>

#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace engine::gl {

/// @brief Line `n` of preprocessed file `i` is numbered `i * kShaderLinesPerFile + n` through `#line`.
///
/// The file is encoded in the line number rather than in `#line`'s source-string number because Mesa
/// drops the source number on locations of compound expressions (it keeps the line).
inline constexpr int kShaderLinesPerFile = 100000;

/// @brief Fully preprocessed source of one shader stage; `fileNames[i]` names file `i` of the
/// numbering above, so driver messages can be mapped back to the file that holds the offending line.
struct ShaderStageSource {
    GLenum stage = GL_VERTEX_SHADER;
    std::string text;
    std::vector<std::string> fileNames;
};

/// @brief Linked GLSL program with a uniform location cache.
class Program {
public:
    /// @brief Compiles and links; throws ShaderError whose message names `label`, file and line.
    Program(std::string_view label, std::span<const ShaderStageSource> stages);

    void use() const;
    /// @brief Location of uniform `name`, or -1 when the linker removed or never had it.
    [[nodiscard]] GLint uniformLocation(std::string_view name) const;

    void set(std::string_view name, int value) const;
    void set(std::string_view name, float value) const;
    void set(std::string_view name, const glm::ivec2& value) const;
    void set(std::string_view name, const glm::vec2& value) const;
    void set(std::string_view name, const glm::vec3& value) const;
    void set(std::string_view name, const glm::vec4& value) const;
    void set(std::string_view name, const glm::mat2& value) const;
    void set(std::string_view name, const glm::mat3& value) const;
    void set(std::string_view name, const glm::mat4& value) const;

    [[nodiscard]] GLuint id() const { return object_.id(); }
    [[nodiscard]] const std::string& label() const { return label_; }

private:
    GlObject<detail::deleteProgram> object_;
    std::string label_;
    mutable std::unordered_map<std::string, GLint> locations_;
};

/// @brief Rewrites driver log locations such as `0:100012(3)` (Mesa), `0(100012)` (NVIDIA) or `0:100012:`
/// (AMD/Intel) into `file.glsl:12:3` / `file.glsl:12` / `file.glsl:12:` using `fileNames`.
std::string mapShaderLog(std::string_view log, std::span<const std::string> fileNames);

} // namespace engine::gl
