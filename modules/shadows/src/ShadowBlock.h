#pragma once

#include <engine/ForwardRenderer.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>

namespace shadows {

/// Shadow maps the lighting pass can read at once (GS_SHADOW_MAX_MAPS in shaders/shadows/receiver.glsl).
inline constexpr int kMaxMaps = 4;
/// Uniform buffer binding of the block; 0 is the engine's FrameBlock.
inline constexpr GLuint kShadowBlockBinding = 1;

static_assert(engine::ForwardRenderer::kMaxLights % 4 == 0, "light slots are packed four to an ivec4");

/// @brief std140 mirror of GsShadowBlock in shaders/shadows/block.glsl: every scalar the passes read,
/// written once per frame.
struct alignas(16) ShadowBlock {
    glm::mat4 worldToShadow[kMaxMaps];
    /// x resolution, y 1/resolution, z texel scale, w 1 for perspective maps.
    glm::vec4 texel[kMaxMaps];
    /// xy: near and far of a perspective map, zero for orthographic ones.
    glm::vec4 depthRange[kMaxMaps];
    /// Shadow map of each engine light, -1 for none, four to an ivec4.
    glm::ivec4 slotOfLight[engine::ForwardRenderer::kMaxLights / 4];
    glm::mat4 msmDequantize;
    /// The columns of a mat2: std140 pads each to a vec4.
    glm::vec4 tapInverseCovariance[2];
    /// The technique's own parameters (ShadowTechniqueTraits::shaderParameters).
    glm::vec4 techniqueParameters;
    /// Receiver moved towards the light by this many texel sizes.
    float constantBiasTexels;
    float depthStep;
    float fuzzyScale;
    /// Texel sizes the receiver is pushed along its normal, times the sine of its angle to the light.
    float normalOffset;
    float minimumVariance;
    float bleedingReduction;
    float momentBias;
    float jitterRadius;
    std::int32_t receiverPlaneClamp;
    std::int32_t jitterPairs;
    std::int32_t earlyOutPairs;
    std::int32_t tapCount;
    float tapDisplace;
    /// Depth units the comparison depth is lowered by.
    float depthBias;
};

static_assert(offsetof(ShadowBlock, texel) == 64 * kMaxMaps);
static_assert(offsetof(ShadowBlock, depthRange) == 80 * kMaxMaps);
static_assert(offsetof(ShadowBlock, slotOfLight) == 96 * kMaxMaps);
static_assert(offsetof(ShadowBlock, msmDequantize) ==
              96 * kMaxMaps + 4 * engine::ForwardRenderer::kMaxLights);
static_assert(offsetof(ShadowBlock, tapInverseCovariance) == offsetof(ShadowBlock, msmDequantize) + 64);
static_assert(offsetof(ShadowBlock, techniqueParameters) == offsetof(ShadowBlock, tapInverseCovariance) + 32);
static_assert(offsetof(ShadowBlock, constantBiasTexels) == offsetof(ShadowBlock, techniqueParameters) + 16);
static_assert(offsetof(ShadowBlock, receiverPlaneClamp) == offsetof(ShadowBlock, constantBiasTexels) + 32);
static_assert(offsetof(ShadowBlock, tapDisplace) == offsetof(ShadowBlock, receiverPlaneClamp) + 16);
static_assert(offsetof(ShadowBlock, depthBias) == offsetof(ShadowBlock, tapDisplace) + 4);

} // namespace shadows
