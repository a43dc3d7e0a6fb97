#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/ShadowSettings.h>
#include <shadows/ShadowTechniqueTraits.h>

#include <epoxy/gl.h>
#include <glm/vec4.hpp>

#include <string_view>
#include <vector>

namespace shadows {

/// @brief The GL internal format of a map in `format` (D24 for a value outside the enum).
GLenum glDepthFormat(DepthFormat format);

/// @brief What the passes do for one set of settings: the technique's row resolved against its options,
/// once, in ShadowModule::setSettings; everything else reads it.
struct ShadowPlan {
    /// @brief Resolves valid `settings` (ShadowSettings::validate is empty).
    static ShadowPlan resolve(const ShadowSettings& settings);

    /// @brief Mip levels of the moments of a map of `resolution`²: momentLevels, no more than the size
    /// allows.
    [[nodiscard]] int momentLevelsAt(int resolution) const;
    /// @brief GPU memory of `layers` whole maps of `resolution`² in these formats, bytes: the depth (one
    /// layer where the maps share it), the gradient or the moments (every mip level), and the moments blur's
    /// one temporary layer (ShadowStats::bytes).
    [[nodiscard]] std::size_t mapBytes(int resolution, int layers) const;

    /// The technique's row of the technique table.
    const ShadowTechniqueTraits* traits = nullptr;
    /// How the lighting pass samples the map (the receiver-plane per-tap kernel compares in hardware).
    MapSampler sampler = MapSampler::CompareNearest;
    /// Whether the tap pattern is used (the receiver-plane per-tap kernel uses it too).
    bool usesTapPattern = false;
    /// Whether the lighting pass reads the fragment's depth gradient (ShadowSettings::gradientSource
    /// applies): the technique's trait, but not the average gradient's circular-8 forms, which compute their
    /// own.
    bool readsPointGradient = false;
    /// Lighting-pass defines: GS_SHADOWS, the technique's, its options' and the debug view's.
    std::vector<std::string_view> lightingDefines;
    /// Depth-pass defines: what the pass stores besides depth.
    std::vector<std::string_view> depthDefines;

    /// Depth buffer format of the map.
    GLenum depthFormat = GL_DEPTH_COMPONENT24;
    /// Bytes of one depth texel (memory accounting, ShadowStats::bytes).
    std::size_t depthBytesPerTexel = 4;
    /// The dz/dxy target of stored derivatives (RG32F), when a technique reads them.
    bool storesGradient = false;
    /// Format of the filtered moments target (blurred where asked), 0 when the technique stores none.
    GLenum momentsFormat = 0;
    /// The moments are box-blurred (momentBlurRadius > 0): the blur's temporary layer and passes exist only
    /// then.
    bool blursMoments = false;
    /// Mip levels of the moments target, generated after the shadow pass: 1 (none) unless the technique
    /// filters its moments over a width it picks per pixel (MapSampler::MomentMips).
    int momentLevels = 1;
    /// Bytes of one moments texel.
    std::size_t momentBytesPerTexel = 0;
    /// Whole (fitted) maps of a moment technique share one depth layer: the lookups read only the moments, so
    /// the depth is the shadow pass's z-buffer, cleared before each map's casters are drawn in turn. A
    /// virtual atlas keeps a depth layer per pool layer, as its page budget counts them.
    bool sharesDepthLayer = false;
    /// What empty moments texels hold: the far plane's moments in the stored basis.
    glm::vec4 momentsClear{1.0f};

    /// The technique's own shader parameters (gsShadowTechniqueParameters).
    glm::vec4 shaderParameters{0.0f};

    /// Polygon offset on the casters (slopeScale, slopeUnits).
    bool offsetsCasters = false;
    /// Texel sizes the receiver is pushed along its normal (times the sine of its angle to the light): the
    /// technique's footprint plus normalOffsetTexels; 0 for techniques without a footprint.
    float normalOffsetTexels = 0.0f;
    /// Texel sizes the receiver is moved towards the light: constantBiasTexels plus the technique's relief
    /// lift where the footprint offset is on.
    float constantBiasTexels = 0.0f;
    /// Depth units the comparison depth is lowered by (depthBiasSteps format steps; 0 unless the technique
    /// biasesDepth), but no less than depthBiasFloor.
    float depthBias = 0.0f;
    /// depthBiasSteps arithmetic steps (kArithmeticDepthStep): depth units of an orthographic map; the
    /// lighting pass converts them for a perspective map at the receiver's distance.
    float depthBiasFloor = 0.0f;
    /// How far from the lookup, in texels, the technique reads the map (taps, jitter, blur, bilinear and
    /// central-difference neighbours): cube faces are widened by this much so kernels near a face's edge read
    /// the same face.
    float kernelReachTexels = 0.0f;
    /// The radius the lookup filters the map over, texels (PCF taps, jitter, the moments' blur, and half a
    /// texel for a bilinear lookup): a blur that widens with the texel, so maps sized to the view take texels
    /// 1 + 2 × this times finer (ShadowSettings::fittedTexelPixels).
    float filterRadiusTexels = 0.0f;
    /// The soft techniques' part of kernelReachTexels (their widest penumbra), which a light of no size
    /// does not need.
    float softReachTexels = 0.0f;
    /// The caster pass leaves out flat casters with nothing behind them as the light sees them
    /// (engine::chunksCastingNoShadow), with casterFaces auto: a ground under the model, walls around a
    /// light. Only where every read of the map is a comparison, which such a texel can only turn to shadow
    /// falsely, and not for the naive reproductions, whose acne on those planes is what they show. Filtered
    /// depth, moments and gradient fits read the depth values themselves: there the plane stays.
    bool leavesOutShadowlessPlanes = false;
    /// The stratified jitter texture of jittered PCF is bound.
    bool needsJitterTexture = false;
};

/// @brief The side whole maps take within a memory budget: `resolution`, halved while `layers` maps of `plan`
/// take more than `budgetBytes` (ShadowPlan::mapBytes), down to kSmallestMapSide, where it stops however
/// many bytes they take.
[[nodiscard]] int budgetedResolution(const ShadowPlan& plan, int resolution, int layers,
                                     std::size_t budgetBytes);

} // namespace shadows
