#include <engine/Error.h>
#include <engine/gl/Program.h>

#include <glm/gtc/type_ptr.hpp>

#include <regex>
#include <vector>

namespace engine::gl {

namespace {

std::string stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER:
        return "vertex";
    case GL_FRAGMENT_SHADER:
        return "fragment";
    case GL_GEOMETRY_SHADER:
        return "geometry";
    case GL_COMPUTE_SHADER:
        return "compute";
    default:
        return "shader";
    }
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) {
        isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
                  : glGetShaderInfoLog(object, length, nullptr, log.data());
        log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    }
    return log;
}

} // namespace

std::string mapShaderLog(std::string_view log, std::span<const std::string> fileNames) {
    // Mesa: "0:12(3): error", NVIDIA: "0(12) : error", AMD/Intel: "ERROR: 0:12: ".
    static const std::regex location(R"((\d+):(\d+)\((\d+)\)|(\d+)\((\d+)\)|(\d+):(\d+):)");
    auto fileAndLine = [&](const std::string& globalLine) {
        const unsigned long number = std::stoul(globalLine);
        const unsigned long file = number / kShaderLinesPerFile;
        const std::string line = std::to_string(number % kShaderLinesPerFile);
        return (file < fileNames.size() ? fileNames[file] : "source " + std::to_string(file)) + ":" + line;
    };
    std::string out;
    const std::string text(log);
    std::smatch match;
    auto begin = text.cbegin();
    while (std::regex_search(begin, text.cend(), match, location)) {
        out.append(begin, match[0].first);
        if (match[1].matched) {
            out += fileAndLine(match[2]) + ":" + match[3].str();
        } else if (match[4].matched) {
            out += fileAndLine(match[5]);
        } else {
            out += fileAndLine(match[7]) + ":";
        }
        begin = match[0].second;
    }
    out.append(begin, text.cend());
    return out;
}

Program::Program(std::string_view label, std::span<const ShaderStageSource> stages)
    : object_(glCreateProgram()), label_(label) {
    glObjectLabel(GL_PROGRAM, object_.id(), static_cast<GLsizei>(label_.size()), label_.data());
    std::vector<GlObject<detail::deleteShader>> shaders;
    for (const ShaderStageSource& stage : stages) {
        GlObject<detail::deleteShader> shader(glCreateShader(stage.stage));
        const char* text = stage.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) {
            throw ShaderError("program '" + label_ + "': " + stageName(stage.stage) +
                              " shader failed to compile:\n" +
                              mapShaderLog(infoLog(shader.id(), false), stage.fileNames));
        }
        glAttachShader(object_.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(object_.id());
    for (const auto& shader : shaders) {
        glDetachShader(object_.id(), shader.id());
    }
    GLint linked = GL_FALSE;
    glGetProgramiv(object_.id(), GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        throw ShaderError("program '" + label_ + "' failed to link:\n" + infoLog(object_.id(), true));
    }
}

void Program::use() const {
    glUseProgram(object_.id());
}

GLint Program::uniformLocation(std::string_view name) const {
    auto found = locations_.find(std::string(name));
    if (found != locations_.end()) {
        return found->second;
    }
    const std::string key(name);
    const GLint location = glGetUniformLocation(object_.id(), key.c_str());
    locations_.emplace(key, location);
    return location;
}

void Program::set(std::string_view name, int value) const {
    glProgramUniform1i(id(), uniformLocation(name), value);
}
void Program::set(std::string_view name, float value) const {
    glProgramUniform1f(id(), uniformLocation(name), value);
}
void Program::set(std::string_view name, const glm::ivec2& v) const {
    glProgramUniform2iv(id(), uniformLocation(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec2& v) const {
    glProgramUniform2fv(id(), uniformLocation(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec3& v) const {
    glProgramUniform3fv(id(), uniformLocation(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec4& v) const {
    glProgramUniform4fv(id(), uniformLocation(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::mat2& m) const {
    glProgramUniformMatrix2fv(id(), uniformLocation(name), 1, GL_FALSE, glm::value_ptr(m));
}
void Program::set(std::string_view name, const glm::mat3& m) const {
    glProgramUniformMatrix3fv(id(), uniformLocation(name), 1, GL_FALSE, glm::value_ptr(m));
}
void Program::set(std::string_view name, const glm::mat4& m) const {
    glProgramUniformMatrix4fv(id(), uniformLocation(name), 1, GL_FALSE, glm::value_ptr(m));
}

} // namespace engine::gl
