#pragma once

#include <shadows/ShadowTechniqueTraits.h>

#include <engine/gl/GlObject.h>

namespace shadows {

/// @brief One sampler object per way the lighting pass reads a map (MapSampler), made on first use.
class ShadowSamplers {
public:
    ShadowSamplers();

    [[nodiscard]] GLuint forMap(MapSampler sampler) const;
    /// @brief Linear filtering without comparison: GSM depth and stored gradients.
    [[nodiscard]] GLuint linear() const { return depthLinear_.id(); }

private:
    using Sampler = engine::gl::GlObject<engine::gl::detail::deleteSampler>;
    Sampler compareNearest_;
    Sampler compareLinear_;
    Sampler depthLinear_;
    Sampler moments_;
    Sampler momentMips_;
};

} // namespace shadows
