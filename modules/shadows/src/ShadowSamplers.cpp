#include "ShadowSamplers.h"

namespace shadows {

namespace {

engine::gl::GlObject<engine::gl::detail::deleteSampler> makeSampler(GLenum filter, bool compare) {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    glSamplerParameteri(name, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    glSamplerParameteri(name, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    // Outside the map counts as unoccluded: a border at the far plane.
    glSamplerParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glSamplerParameterfv(name, GL_TEXTURE_BORDER_COLOR, border);
    if (compare) {
        glSamplerParameteri(name, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(name, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL); // lit when reference <= stored
    }
    return engine::gl::GlObject<engine::gl::detail::deleteSampler>(name);
}

} // namespace

ShadowSamplers::ShadowSamplers()
    : compareNearest_(makeSampler(GL_NEAREST, true)), compareLinear_(makeSampler(GL_LINEAR, true)),
      depthLinear_(makeSampler(GL_LINEAR, false)), moments_(makeSampler(GL_LINEAR, false)),
      momentMips_(makeSampler(GL_LINEAR, false)) {
    // Bilinear (the moments have one level), or trilinear over their chain; edges clamp (a quantised border
    // would not be "far").
    glSamplerParameteri(momentMips_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    for (const GLuint sampler : {moments_.id(), momentMips_.id()}) {
        glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
}

GLuint ShadowSamplers::forMap(MapSampler sampler) const {
    switch (sampler) {
    case MapSampler::CompareNearest:
        return compareNearest_.id();
    case MapSampler::CompareLinear:
        return compareLinear_.id();
    case MapSampler::DepthLinear:
        return depthLinear_.id();
    case MapSampler::Moments:
        return moments_.id();
    case MapSampler::MomentMips:
        return momentMips_.id();
    }
    return compareNearest_.id();
}

} // namespace shadows
