#include <engine/Error.h>
#include <engine/ShaderVariantKey.h>

#include <algorithm>
#include <cctype>

namespace engine {

namespace {
bool isIdentifier(std::string_view name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) {
        return false;
    }
    return std::all_of(name.begin(), name.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}
} // namespace

ShaderVariantKey ShaderVariantLayout::flag(std::string_view defineName) {
    const auto found = std::find(names_.begin(), names_.end(), defineName);
    if (found != names_.end()) {
        return ShaderVariantKey{1} << (found - names_.begin());
    }
    if (!isIdentifier(defineName)) {
        throw Error("shader variant flag '" + std::string(defineName) + "' is not a valid GLSL identifier");
    }
    if (names_.size() == kMaxFlags) {
        throw Error("shader variant flag '" + std::string(defineName) + "': all 64 variant bits are in use");
    }
    names_.emplace_back(defineName);
    return ShaderVariantKey{1} << (names_.size() - 1);
}

std::vector<std::string> ShaderVariantLayout::defines(ShaderVariantKey key) const {
    std::vector<std::string> result;
    for (std::size_t bit = 0; bit < names_.size(); ++bit) {
        if (key & (ShaderVariantKey{1} << bit)) {
            result.push_back("#define " + names_[bit] + " 1");
        }
    }
    return result;
}

} // namespace engine
