#pragma once

#include "ShadowBlock.h"
#include "ShadowMapArray.h"

#include <shadows/LightFrustum.h>
#include <shadows/ShadowPlan.h>
#include <shadows/VirtualPages.h>

#include <engine/Module.h>
#include <engine/gl/Program.h>

#include <span>
#include <vector>

namespace shadows {

/// @brief One map of the frame: a light's, one of its cascades or cube faces, or a virtual map's level or
/// face.
struct MapSlot {
    int lightIndex = -1;
    LightProjection projection;
    /// Texels per side: the settings' resolution, or a virtual map's.
    int resolution = 0;
};

/// @brief What one frame's allocation works from.
struct AllocationFrame {
    const engine::FrameContext& frame;
    /// The camera the maps are fitted to (the frame's, unless frozen by ShadowModule::setFitView).
    FitView fit;
    /// World bounds of every mesh: receivers for the fit, and casters.
    std::span<const Aabb> boxes;
    /// The entity each of `boxes` belongs to.
    std::span<const engine::EntityId> entities;
    /// Whether `fit` is the frame's own camera, so that its visible samples are the pixels the lighting pass
    /// shades; a frozen fit's maps are drawn whole.
    bool fitIsCamera = true;
};

/// @brief Warnings said once per attached module, however often a settings change replaces its allocation.
struct OnceWarnings {
    bool noSamples = false;
    bool pageBudget = false;
    bool mapBudget = false;
};

/// @brief Where a frame's shadow texels live: which maps each shadow-casting light gets, drawing them, and
/// what the lighting pass samples. Two implementations: FittedShadowMaps (a whole map per light, cascade or
/// cube face, fitted to the view) and VirtualShadowMaps (pages only where visible pixels ask, in a fixed
/// budget, cached). Both describe a light's maps as slots and a LightMapsBlock, and receiver.glsl resolves
/// the layout before a technique's lookup, so no technique knows which one it reads.
/// @brief What the caster pass leaves out (ShadowSettings::casterFaces,
/// ShadowPlan::leavesOutShadowlessPlanes).
struct CasterOmissions {
    /// The faces of closed parts turned away from the light: the depth stored is the same
    /// (engine::hiddenFace).
    engine::HiddenFaces hiddenFaces = engine::HiddenFaces::Draw;
    /// Flat chunks with nothing behind them as the light sees them (engine::chunksCastingNoShadow): the
    /// texels they would fill read as lit instead of as their own surface.
    bool shadowlessPlanes = false;
};

class MapAllocator {
public:
    virtual ~MapAllocator() = default;

    /// @brief Fits the maps of every shadow-casting light of the frame: appends one slot per map to `slots`
    /// (at most kMaxMaps; a light that does not fit is left out, saying so) and describes each light's maps
    /// in `lights`, indexed by engine light.
    virtual void allocate(const AllocationFrame& frame, std::vector<MapSlot>& slots,
                          std::vector<LightMapsBlock>& lights) = 0;
    /// @brief Draws this frame's maps, as the slots of the last allocate describe them, with `program` (the
    /// shadow pass's, in use with its depth state and uniform block set), leaving out what `omissions` says
    /// (drawCasters).
    virtual engine::DrawnMeshes render(const engine::Scene& scene, const engine::gl::Program& program,
                                       std::span<const MapSlot> slots, const CasterOmissions& omissions) = 0;
    /// @brief Whether the maps as last drawn are what `slots` (this frame's allocation) would draw, the
    /// casters being unchanged: the same maps at the same placements, depth ranges and sides, none drawing a
    /// texel the last drawing left out. Then a moving view keeps them. Whole maps only (virtual maps keep
    /// their pages themselves).
    [[nodiscard]] virtual bool holds(std::span<const MapSlot> slots) const {
        static_cast<void>(slots);
        return false;
    }
    /// @brief Blurs the moments drawn this frame with `blur` (shaders/shadows/blur.frag, in use, a fullscreen
    /// triangle bound), sampling through texture unit `unit`.
    virtual void blurMoments(const engine::gl::Program& blur, GLuint unit) = 0;
    /// @brief The maps the lighting pass samples; null while there are none.
    [[nodiscard]] virtual const ShadowMapArray* sampled() const = 0;
    /// @brief The page table the lookups translate through; 0 for whole maps.
    [[nodiscard]] virtual GLuint pageTable() const { return 0; }
    /// @brief Writes what the lookups need of the allocation beyond the slots into `block`.
    virtual void describe(ShadowBlock& block) const { static_cast<void>(block); }
    /// @brief GPU bytes held: the maps, and a virtual pool's page tables and requests.
    [[nodiscard]] virtual std::size_t bytes() const = 0;
    /// @brief Whether the last frame's lights read virtual maps.
    [[nodiscard]] virtual bool servedVirtualMaps() const { return false; }
    /// @brief The virtual maps' page counters in the last frame (zero for whole maps).
    [[nodiscard]] virtual VirtualPageStats pageStats() const { return {}; }
};

/// @brief The light's size as the soft techniques take it, scaled by `lightSizeScale`: a sun's by the tangent
/// of its angular radius (a penumbra's radius per unit of distance behind its blocker; the diameter kept
/// below 90°), a local light's by its radius.
float softLightSize(const engine::LightComponent& light, float lightSizeScale);

/// @brief Appends a slot for a valid `projection` of light `lightIndex` with `resolution` texels per side;
/// its index, or -1 when the projection has nothing to draw or all kMaxMaps slots are taken.
int addSlot(std::vector<MapSlot>& slots, int lightIndex, const LightProjection& projection, int resolution);

/// @brief Records `slot` as face `face` of a cube map (or a spot map's, face 0) in `maps`: faces 0–3 in
/// `slots`, 4 and 5 in `faceSlots`.
void setFaceSlot(LightMapsBlock& maps, int face, int slot);

/// @brief `drawn` when any slot of `maps` holds a map this frame, else None (the lighting pass reads
/// nothing).
std::int32_t drawnKind(const LightMapsBlock& maps, LightMapsKind drawn);

/// @brief Clears what `framebuffer` (one of `maps`' layers, bound, within its viewport and scissor) draws
/// into: the depth to the far plane, a gradient to zero, moments to the plan's far-plane value.
void clearMapTargets(const ShadowMapArray& maps, GLuint framebuffer, const ShadowPlan& plan);

/// @brief The texels of a `side`-texel map its projection's drawnRegion covers, rounded out to whole texels:
/// the first's x and y, then the width and height (the whole map for the region (0, 0, 1, 1)).
glm::ivec4 drawnTexels(const LightProjection& projection, int side);

/// @brief The light `projection` sees from, homogeneous: its eye for a perspective map, the direction
/// towards the light (w = 0) for an orthographic one.
glm::vec4 lightPosition(const LightProjection& projection);

/// @brief Draws the casters of `scene` seen through `projection` with `program` (the shadow pass's, in use),
/// culled to the clip volume of its drawnRegion: casters outside it could not write a texel read. Texels
/// outside the region are the caller's to scissor. Leaves out what `omissions` says.
engine::DrawnMeshes drawCasters(engine::ModuleHost& host, const engine::Scene& scene,
                                const engine::gl::Program& program, const LightProjection& projection,
                                const CasterOmissions& omissions);

/// @brief Adds `drawn`'s counts to `total`'s.
void accumulate(engine::DrawnMeshes& total, const engine::DrawnMeshes& drawn);

} // namespace shadows
