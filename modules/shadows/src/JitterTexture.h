#pragma once

#include <engine/gl/GlObject.h>

namespace shadows {

/// @brief The 3D texture of stratified offsets of jittered PCF (soft shadows reference), two per texel.
class JitterTexture {
public:
    explicit JitterTexture(int tapCount);

    [[nodiscard]] int taps() const { return taps_; }
    [[nodiscard]] GLuint id() const { return texture_.id(); }

private:
    int taps_;
    engine::gl::GlObject<engine::gl::detail::deleteTexture> texture_;
};

} // namespace shadows
