#include <engine/ProgramCache.h>

#include <array>
#include <sstream>

namespace engine {

ProgramCache::ProgramCache(const ShaderLibrary& library, const ShaderVariantLayout& layout)
    : library_(library), layout_(layout) {}

const gl::Program& ProgramCache::get(const ProgramDesc& desc, ShaderVariantKey key) {
    auto found = programs_.find({desc, key});
    if (found != programs_.end()) {
        return *found->second;
    }
    const std::vector<std::string> defines = layout_.defines(key);
    const std::array stages = {library_.preprocess(GL_VERTEX_SHADER, desc.vertex, defines, chunks_),
                               library_.preprocess(GL_FRAGMENT_SHADER, desc.fragment, defines, chunks_)};
    std::ostringstream label;
    label << desc.vertex << '+' << desc.fragment << " [variant 0x" << std::hex << key << ']';
    auto program = std::make_unique<gl::Program>(label.str(), stages);
    ++compileCount_;
    return *programs_.emplace(std::pair{desc, key}, std::move(program)).first->second;
}

void ProgramCache::setChunks(std::vector<ShaderChunk> chunks) {
    chunks_ = std::move(chunks);
    clear();
}

void ProgramCache::clear() {
    programs_.clear();
}

} // namespace engine
