#pragma once

#include <epoxy/gl.h>

namespace testsupport {

/// @brief For its lifetime, a sampler with depth comparison and linear filtering bound to texture unit
/// `unit`, as a fitted map's lookup leaves one there: what samples through that unit must not depend on it.
class ComparisonSamplerLeftOnUnit {
public:
    explicit ComparisonSamplerLeftOnUnit(GLuint unit) : unit_(unit) {
        glCreateSamplers(1, &sampler_);
        glSamplerParameteri(sampler_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(sampler_, GL_TEXTURE_COMPARE_FUNC, GL_LESS);
        glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glBindSampler(unit_, sampler_);
    }
    ~ComparisonSamplerLeftOnUnit() {
        glBindSampler(unit_, 0);
        glDeleteSamplers(1, &sampler_);
    }
    ComparisonSamplerLeftOnUnit(const ComparisonSamplerLeftOnUnit&) = delete;
    ComparisonSamplerLeftOnUnit& operator=(const ComparisonSamplerLeftOnUnit&) = delete;

private:
    GLuint unit_;
    GLuint sampler_ = 0;
};

} // namespace testsupport
