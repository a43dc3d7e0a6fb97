#pragma once

#include <engine/ForwardRenderer.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>

namespace shadows {

/// Shadow maps the lighting pass can read at once: lights' maps, cascades and cube faces together
/// (GS_SHADOW_MAX_MAPS in shaders/shadows/block.glsl); each is a layer of the module's map arrays. Enough
/// for every light the renderer takes to be a point light (six faces), or for a virtual sun's 16 clipmap
/// levels beside five point lights.
inline constexpr int kMaxMaps = engine::ForwardRenderer::kMaxLights * 6;
/// Uniform buffer binding of the block; 0 is the engine's FrameBlock.
inline constexpr GLuint kShadowBlockBinding = 1;

/// @brief How a light's maps are laid out (GS_SHADOW_LIGHT_* in block.glsl).
enum class LightMapsKind : std::int32_t {
    None = 0,
    Single = 1,
    Cascades = 2,
    Cube = 3,
    Virtual = 4,
    VirtualFaces = 5
};

/// @brief std140 mirror of GsShadowLightMaps: which maps a light has and how a fragment picks one.
struct alignas(16) LightMapsBlock {
    /// x: LightMapsKind, y: cascade count, clipmap levels or mip levels; Cascades: z the first drawn
    /// cascade's slot (ShadowModule fills it); Virtual: z the first level's slot (the levels' slots follow
    /// it), w its page-table layer; VirtualFaces: z 1 (a spot map, `slots.x`) or 6 (cube faces, as Cube), w
    /// the first face's page-table layer (the faces' follow it, their levels its mip levels).
    glm::ivec4 kind;
    /// Map slot of the single map (x), of each cascade, or of cube faces 0–3; -1: not drawn this frame.
    glm::ivec4 slots;
    /// Map slots of cube faces 4 and 5 (xy).
    glm::ivec4 faceSlots;
    /// Cascades: the view depth each one starts and ends at.
    glm::vec4 splitNear;
    glm::vec4 splitFar;
};
static_assert(sizeof(LightMapsBlock) == 80);

/// @brief std140 mirror of GsShadowBlock in shaders/shadows/block.glsl: every scalar the passes read,
/// written once per frame.
struct alignas(16) ShadowBlock {
    glm::mat4 worldToShadow[kMaxMaps];
    /// x resolution, y 1/resolution, z texel scale, w 1 for perspective maps.
    glm::vec4 texel[kMaxMaps];
    /// xy: near and far of a perspective map, zero for orthographic ones; z: the lit border in texels
    /// (LightProjection::litBorderTexels); w: the light's size (a sun's tan of its angular radius, a local
    /// light's radius).
    glm::vec4 depthRange[kMaxMaps];
    LightMapsBlock lights[engine::ForwardRenderer::kMaxLights];
    /// The fit camera's view depth of a world point is dot(viewDepth, (p, 1)).
    glm::vec4 viewDepth;
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
    /// Fraction of a cascade's depth span blended into the next.
    float cascadeBlend;
    /// The depth bias's arithmetic floor in an orthographic map's depth units (ShadowPlan::depthBiasFloor).
    float depthBiasFloor;
    /// Virtual maps: x pages per side of a clipmap level, y atlas tiles per row, z atlas side in texels.
    alignas(16) glm::ivec4 virtualPages;
    /// Virtual maps: x page side, y tile side, z border in texels, w 1 / atlas side.
    alignas(16) glm::vec4 virtualPage;
    /// The soft techniques' widest penumbra radius in each map, texels, four maps a vector: the plan's reach,
    /// or the wider one the map's fit holds (LightProjection::softReachTexels).
    glm::vec4 softReachTexels[kMaxMaps / 4];
    /// A cascade's or clipmap level's texture coordinates from its light's first cascade's or finest level's,
    /// coord = first * scale + offset (xyz; identity for other maps): the vertex stage projects into the
    /// first only.
    glm::vec4 cascadeScale[kMaxMaps];
    glm::vec4 cascadeOffset[kMaxMaps];
};

static_assert(offsetof(ShadowBlock, texel) == 64 * kMaxMaps);
static_assert(offsetof(ShadowBlock, depthRange) == 80 * kMaxMaps);
static_assert(offsetof(ShadowBlock, lights) == 96 * kMaxMaps);
static_assert(offsetof(ShadowBlock, viewDepth) == 96 * kMaxMaps + 80 * engine::ForwardRenderer::kMaxLights);
static_assert(offsetof(ShadowBlock, msmDequantize) == offsetof(ShadowBlock, viewDepth) + 16);
static_assert(offsetof(ShadowBlock, tapInverseCovariance) == offsetof(ShadowBlock, msmDequantize) + 64);
static_assert(offsetof(ShadowBlock, techniqueParameters) == offsetof(ShadowBlock, tapInverseCovariance) + 32);
static_assert(offsetof(ShadowBlock, constantBiasTexels) == offsetof(ShadowBlock, techniqueParameters) + 16);
static_assert(offsetof(ShadowBlock, receiverPlaneClamp) == offsetof(ShadowBlock, constantBiasTexels) + 32);
static_assert(offsetof(ShadowBlock, tapDisplace) == offsetof(ShadowBlock, receiverPlaneClamp) + 16);
static_assert(offsetof(ShadowBlock, depthBias) == offsetof(ShadowBlock, tapDisplace) + 4);
static_assert(offsetof(ShadowBlock, cascadeBlend) == offsetof(ShadowBlock, depthBias) + 4);
static_assert(offsetof(ShadowBlock, depthBiasFloor) == offsetof(ShadowBlock, cascadeBlend) + 4);
static_assert(offsetof(ShadowBlock, virtualPages) % 16 == 0 &&
              offsetof(ShadowBlock, virtualPages) - offsetof(ShadowBlock, depthBiasFloor) <= 16);
static_assert(offsetof(ShadowBlock, virtualPage) == offsetof(ShadowBlock, virtualPages) + 16);
static_assert(kMaxMaps % 4 == 0 &&
              offsetof(ShadowBlock, softReachTexels) == offsetof(ShadowBlock, virtualPage) + 16);
static_assert(offsetof(ShadowBlock, cascadeScale) == offsetof(ShadowBlock, softReachTexels) + 4 * kMaxMaps);
static_assert(offsetof(ShadowBlock, cascadeOffset) == offsetof(ShadowBlock, cascadeScale) + 16 * kMaxMaps);

} // namespace shadows
