#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

/// @brief Bitmask naming one shader permutation; each set bit becomes one `#define`.
using ShaderVariantKey = std::uint64_t;

/// @brief Assigns variant bits to define names. The engine and every module register the flags they use;
/// a program is compiled once per distinct key actually drawn.
class ShaderVariantLayout {
public:
    static constexpr int kMaxFlags = 64;

    /// @brief Returns the bit for `defineName`, registering it on first use.
    /// Throws Error when all 64 bits are taken or the name is not a valid GLSL identifier.
    ShaderVariantKey flag(std::string_view defineName);

    /// @brief `#define NAME 1` lines for every bit set in `key`, in bit order.
    [[nodiscard]] std::vector<std::string> defines(ShaderVariantKey key) const;
    [[nodiscard]] std::size_t flagCount() const { return names_.size(); }

private:
    std::vector<std::string> names_;
};

} // namespace engine
