#pragma once

#include <engine/ShaderLibrary.h>
#include <engine/ShaderVariantKey.h>
#include <engine/gl/Program.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace engine {

/// @brief Names the shader files of one program; variants of it differ only by ShaderVariantKey.
struct ProgramDesc {
    std::string vertex;
    std::string fragment;
    auto operator<=>(const ProgramDesc&) const = default;
};

/// @brief Lazy program cache: a (program, variant) pair is compiled the first time it is requested.
class ProgramCache {
public:
    ProgramCache(const ShaderLibrary& library, const ShaderVariantLayout& layout);

    /// @brief Returns the program for `desc` at `key`, compiling it now if it is new.
    const gl::Program& get(const ProgramDesc& desc, ShaderVariantKey key);
    /// @brief Chunks injected into every program's slots; changing them drops every compiled program.
    void setChunks(std::vector<ShaderChunk> chunks);
    /// @brief Drops every compiled program (e.g. after modules changed their chunks).
    void clear();

    /// @brief Number of programs compiled since construction (never decreases); shows laziness in tests.
    [[nodiscard]] std::size_t compileCount() const { return compileCount_; }
    [[nodiscard]] std::size_t size() const { return programs_.size(); }

private:
    const ShaderLibrary& library_;
    const ShaderVariantLayout& layout_;
    std::vector<ShaderChunk> chunks_;
    std::map<std::pair<ProgramDesc, ShaderVariantKey>, std::unique_ptr<gl::Program>> programs_;
    std::size_t compileCount_ = 0;
};

} // namespace engine
