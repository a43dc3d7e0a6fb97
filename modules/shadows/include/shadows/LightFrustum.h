#pragma once

#include <engine/Bounds.h>

#include <glm/glm.hpp>

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace shadows {

/// @brief World-space axis-aligned box (the engine's).
using Aabb = engine::Aabb;

struct LightRect; // shadows/SampleDistribution.h

/// @brief The view and projection a shadow map is rendered with.
struct LightProjection {
    /// World → light view space.
    glm::mat4 view{1.0f};
    /// Light view → clip space (orthographic for directional lights, perspective for spots).
    glm::mat4 projection{1.0f};
    /// World → shadow texture space: xy in [0,1] over the map, z the stored depth in [0,1] (after divide by
    /// w).
    glm::mat4 worldToShadow{1.0f};
    /// Whether `projection` is perspective (a spot light's).
    bool perspective = false;
    /// Orthographic: world size of one texel. Perspective: 2·tan(fov/2)/resolution (times distance = texel
    /// size).
    float texelScale = 0.0f;
    /// Perspective: the near and far plane distances; zero for orthographic maps (gsLinearDepth).
    glm::vec2 depthRange{0.0f};
    /// A fitted directional map: the width, in whole texels, of its outer band where no receiver can be
    /// shadowed (the margin beyond where shadows can fall). Lookups there are lit without reading the map, so
    /// no kernel, fit or central difference straddles the map's edge. Zero for cascades, spot maps and cube
    /// faces, whose edges shadows may reach.
    float litBorderTexels = 0.0f;
    /// The widest penumbra radius, in texels, the margin of a map fitted with a SoftMargin holds beyond the
    /// technique's own reach (ShadowPlan::softReachTexels, which every map keeps); zero for other maps.
    float softReachTexels = 0.0f;
    /// Where the visible receivers' lookups read, in texture coordinates (min x, min y, max x, max y): for a
    /// map fitted to the samples, their box widened by the lookups' reach, within the map. Casters are drawn
    /// there alone (scissored, and culled to it), so a square map wider than the view's samples along one
    /// axis, or enlarged by the snapped extent, spends no fill beyond them. The whole map, (0, 0, 1, 1), for
    /// every other map.
    glm::vec4 drawnRegion{0.0f, 0.0f, 1.0f, 1.0f};
    /// A directional map fitted to the samples: the light-space square it covers, its centre (x, y) and side
    /// (z), which a later fit at the same side may keep (fitToSamples); zero for every other map.
    glm::vec3 square{0.0f};
    /// False when nothing visible can receive a shadow from this light (no map needs drawing).
    bool valid = false;
};

/// @brief Fits an orthographic shadow frustum for a directional light shining along `direction`.
///
/// Receivers are the parts of the boxes inside the camera frustum (`cameraViewProjection`); the map covers
/// where they can be shadowed: each receiver's light-space extent (clipped to the camera frustum's) where
/// some box that reaches nearer the light overlaps it (a flat box does not shadow itself). Its depth range
/// spans the parts of every box over the map, towards the light too, so casters outside the view still cast
/// and a large ground tilted in light space adds only its part under the map. Invalid when no visible
/// receiver can be shadowed. With `snapToTexels`, the extent is quantised to 1/8-octave steps and the origin
/// to whole texels, so a moving camera does not make shadow edges shimmer.
LightProjection fitDirectionalLight(const glm::vec3& direction, const glm::mat4& cameraViewProjection,
                                    std::span<const Aabb> boxes, int resolution, bool snapToTexels);

/// @brief Fits a perspective shadow frustum for a spot light at `position` shining along `direction` with
/// cone half-angle `outerConeAngle` (radians); near and far planes bound the boxes in front of the light (and
/// `range` when it is positive).
LightProjection fitSpotLight(const glm::vec3& position, const glm::vec3& direction, float outerConeAngle,
                             float range, std::span<const Aabb> boxes, int resolution);

/// @brief The camera shadow maps are fitted to: world → view, and view → clip.
struct FitView {
    /// World → view space (the inverse of the camera's world matrix).
    glm::mat4 view{1.0f};
    /// View → clip space.
    glm::mat4 projection{1.0f};

    /// @brief Field-wise (exact) equality.
    bool operator==(const FitView&) const = default;
};

/// @brief Most cascades a directional light can have (ShadowSettings::cascadeCount).
inline constexpr int kMaxCascades = 4;
/// @brief The smallest side a whole map takes when it is sized down (to the view, to a memory budget, to what
/// the driver allocates): its margins and a kernel's reach still leave most of it to the view.
inline constexpr int kSmallestMapSide = 64;

/// @brief The practical split scheme (Zhang, Sun, Xu, Lun, "Parallel-Split Shadow Maps for Large-scale
/// Virtual Environments", VRCIA 2006, section 3.2): split i of `count` at w·n·(f/n)^(i/count) + (1−w)·(n +
/// (f−n)·i/count), a blend of the logarithmic scheme (texel size proportional to depth, ideal for perspective
/// aliasing) and the uniform one. Returns count + 1 ascending view depths, the first exactly `near`, the last
/// exactly `far`.
std::vector<float> cascadeSplits(float near, float far, int count, float weight);

/// @brief The view depths the fit's camera sees receivers at: the range of the boxes that intersect its view
/// volume, clamped to its near and far planes and widened to 1/8-octave steps (so cascades keep their splits
/// while the camera moves). nullopt when no box is in view.
std::optional<glm::vec2> visibleDepthRange(const FitView& view, std::span<const Aabb> boxes);

/// @brief Cascades for visible receivers spanning view depths `depthRange`: one map below 1000:1, then one
/// more per decade (2 below 10⁴:1, 3 below 10⁵:1, else kMaxCascades). Models on a ground plane (up to some
/// hundreds to one) meet the accuracy floor with one map fitted to the receivers, at a third of the shadow
/// pass that cascades cost; a landscape seen from the ground does not (docs/RESULTS.md, "Every light").
int automaticCascadeCount(glm::vec2 depthRange);

/// @brief Whether a box that intersects the view volume of `view` reaches view depths between `near` and
/// `far`: a cascade over that slice would have a visible receiver.
bool hasReceiversBetween(const FitView& view, std::span<const Aabb> boxes, float near, float far);

/// @brief A sphere in view space.
struct Sphere {
    /// Centre, view space.
    glm::vec3 centre{0.0f};
    /// Radius, world units.
    float radius = 0.0f;
};

/// @brief The smallest sphere centred on the frustum's axis that holds the slice of the view frustum between
/// view depths `sliceNear` and `sliceFar`. It depends on the projection and the slice only, so a cascade
/// fitted to it keeps its size, to the bit, however the camera moves or turns (Valient, "Stable Rendering of
/// Cascaded Shadow Maps", ShaderX6, 2008).
Sphere frustumSliceSphere(const glm::mat4& projection, float sliceNear, float sliceFar);

/// @brief Fits the orthographic map of one cascade of a directional light shining along `direction`: a square
/// around the bounding sphere of the slice [sliceNear, sliceFar] of `view`, its origin snapped to whole
/// texels when `snapToTexels` (the texel grid then stays fixed in world space: no shimmer), and its depth
/// range extended towards the light over the part of every box over the square (not all of a large ground),
/// so casters outside the view still cast. Invalid when the slice is empty.
LightProjection fitCascade(const glm::vec3& direction, const FitView& view, float sliceNear, float sliceFar,
                           std::span<const Aabb> boxes, int resolution, bool snapToTexels);

/// @brief The margin a soft technique's penumbrae need around a directional map's samples: at least `texels`,
/// and as wide as the penumbra a blocker at the map's nearest caster casts on its deepest sample, `perDepth`
/// world units of radius per unit of depth between them (a sun's tan of its angular radius; 0: `texels`
/// alone). The widening stops at an eighth of the map's side, so the margin takes at most a quarter of its
/// texels.
struct SoftMargin {
    /// The narrowest soft margin, texels (ShadowPlan::softReachTexels; 0 for a light of no size).
    float texels = 0.0f;
    /// Penumbra radius per unit of depth behind its blocker, world units (0: `texels` alone).
    float perDepth = 0.0f;
};

/// @brief Fits the orthographic map of a directional light shining along `direction` to the visible samples
/// it must hold: their light-space box `samples` (x, y in the frame of lightView(direction); z towards the
/// light), widened by `marginTexels` texels (the lookups' kernel reach), the soft margin `soft` (the map's
/// softReachTexels: what it holds beyond soft.texels) and a texel of snapping slack. With
/// `snapToTexels` its extent is quantised to 1/8-octave steps and its origin to whole texels, and its depth
/// range to steps of an eighth of an octave of its span, so a moving camera changes it rarely (SDSM's known
/// weakness is flashing as the fit follows the samples). Depth: from the deepest sample to the nearest caster
/// over the map (the part of every box over it, towards the light), so casters outside the view still cast.
/// Beyond the samples' box, less two texels for the receiver's own offsets, is the lit border. The casters
/// are drawn within the margin and those two texels of `visible` (drawnRegion): every visible sample of the
/// slice, of which `samples` are those a caster can shadow, so that each one's lookup reads what it did in a
/// map drawn whole; `samples` where null. The square of the first of `kept` (earlier fits) of the same side
/// that holds the samples with the margins a new square would give them is kept, on the same texel grid, so
/// a camera moving within it leaves the map as it was drawn. Invalid when `samples` is empty or not finite.
LightProjection fitToSamples(const glm::vec3& direction, const LightRect& samples,
                             std::span<const Aabb> boxes, int resolution, float marginTexels,
                             bool snapToTexels, SoftMargin soft = {}, const LightRect* visible = nullptr,
                             std::span<const LightProjection> kept = {});

/// @brief Where a directional light shining along `direction` can shadow a receiver in the view of
/// `cameraViewProjection`, as a light-space (lightView) xy box (z = 0): the part of each box the view can see
/// under some other box (or a box that is not flat) reaching nearer the light. Boxes bound every surface and
/// caster, so this is a superset of where visible shadows fall; empty when none can.
Aabb shadowableRegion(const glm::vec3& direction, const glm::mat4& cameraViewProjection,
                      std::span<const Aabb> boxes);

/// @brief The rotation directional maps of a light shining along `direction` are drawn in: world → light
/// space, the light looking down -z.
glm::mat4 lightView(const glm::vec3& direction);

/// @brief Clip space to the clip space of the texture rectangle from `low`, `size` wide (a map's [0,1]
/// coordinates): the rectangle's edges go to -w and w, so what lies over it, and only that, lies in the new
/// clip volume, perspective maps included. A virtual page's projection, and the cull volume of a drawnRegion.
glm::dmat4 textureRectClip(glm::dvec2 low, glm::dvec2 size);

/// @brief Faces of a point light's cube map.
inline constexpr int kCubeFaces = 6;

/// @brief The axis face `face` looks along: +X, −X, +Y, −Y, +Z, −Z (gsCubeFace's order).
glm::vec3 cubeFaceAxis(int face);

/// @brief Field of view of a cube face that holds `marginTexels` texels beyond the 90° face on each side at
/// `resolution`: tan(fov/2) = R / (R − 2m). Kernels that reach up to the margin past a face's edge then read
/// the same face's own map instead of clamping at its border.
float cubeFaceFieldOfView(int resolution, float marginTexels);

/// @brief Fits the perspective map of face `face` of a point light at `position` (see cubeFaceFieldOfView);
/// near and far bound the boxes the face's frustum sees (and `range` when positive). Invalid when no box that
/// intersects the camera's view volume (`cameraViewProjection`) lies in the face's frustum: the face has no
/// visible receiver.
LightProjection fitPointLightFace(const glm::vec3& position, int face, float range,
                                  const glm::mat4& cameraViewProjection, std::span<const Aabb> boxes,
                                  int resolution, float marginTexels);

} // namespace shadows
