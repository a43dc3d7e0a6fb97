#include "JitterTexture.h"

#include <shadows/TapPattern.h>

namespace shadows {

JitterTexture::JitterTexture(int tapCount) : taps_(tapCount) {
    const JitterTexels texels = makeJitterTexels(tapCount);
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &name);
    texture_ = engine::gl::GlObject<engine::gl::detail::deleteTexture>(name);
    glTextureStorage3D(name, 1, GL_RGBA16, texels.size, texels.size, texels.pairs);
    glTextureSubImage3D(name, 0, 0, 0, 0, texels.size, texels.size, texels.pairs, GL_RGBA, GL_UNSIGNED_SHORT,
                        texels.texels.data());
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

} // namespace shadows
