#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/ShadowPlan.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <set>
#include <span>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace shadows {

/// @brief Side of each clipmap level of a directional light's virtual map, in texels (UE5's 16k²).
inline constexpr int kVirtualResolution = 16384;
/// @brief Absolute levels the page requests can name: level k has texels 2^k world units wide, k from
/// kVirtualLevelBase(scene) to that plus kRequestLevels − 1.
inline constexpr int kRequestLevels = 64;
/// @brief Levels of one light's clipmap that the lighting pass reads (consecutive absolute levels; each a
/// slot of the shadow block).
inline constexpr int kClipmapLevels = 16;

/// @brief Page-table layers all lights together may use: one per map slot of the lighting pass (a clipmap
/// level, a spot map, a cube face), kMaxMaps of ShadowBlock.h.
inline constexpr int kPageTableLayers = 48;

/// @brief Page counters of the virtual maps in the last frame.
struct VirtualPageStats {
    /// Pages the visible pixels asked for (after clamping to each light's clipmap).
    int requested = 0;
    /// Pages drawn this frame (new, evicted before, or invalidated).
    int rendered = 0;
    /// Requested pages that were resident and valid already.
    int cached = 0;
    /// Pages fewer the requests hold after moving to coarser levels so that the frame's pages fit the pool
    /// (coarsenToFit).
    int coarsened = 0;
    /// Requests the pool could not hold even so: lookups there find no texels and are lit (warned).
    int refused = 0;
    /// Pages resident in the pool.
    int resident = 0;
    /// Pages the pool holds at most (its budget over one tile's bytes).
    int poolPages = 0;
    /// Pages dropped this frame because a caster moved over them or the light changed.
    int invalidated = 0;
    /// Texels drawn this frame (rendered pages with their borders).
    std::size_t texelsRendered = 0;
};

/// @brief Texels of neighbouring pages each atlas tile also holds: the kernel's reach and the receiver's
/// offsets, so that no lookup reads across a page's edge.
int virtualPageBorderTexels(const ShadowPlan& plan);
/// @brief GPU bytes of one atlas tile of a `pageSize`² page with its border (depth plus the technique's
/// stored values).
std::size_t virtualTileBytes(const ShadowPlan& plan, int pageSize);

/// @brief GPU bytes the virtual maps hold beside the pool for `pageSize`² pages: the page requests (a bit per
/// page of kRequestLevels levels) and `tableLayers` page-table layers, each a mip chain of 32-bit entries
/// from pagesPerSide² down to one.
std::size_t virtualOverheadBytes(int pageSize, int tableLayers);

/// @brief One page of a light's virtual map. A directional light's clipmap: absolute level (texels 2^level
/// world units wide) and absolute page coordinates on that level's grid, which is anchored at the light-space
/// origin (so a page keeps its key, and its cached texels, however the window of pages around the camera
/// moves). A spot light's map or a point light's face: the mip level and the page on it.
struct PageKey {
    /// Engine light index.
    int light = 0;
    /// Clipmap: absolute level, texels 2^level world units wide. Perspective map: mip level, 0 finest.
    int level = 0;
    /// Absolute page coordinates on the level's grid.
    glm::ivec2 page{0};
    /// Cube face of a point light (cubeFaceAxis's order); 0 for directional and spot lights.
    int face = 0;
    /// @brief Field-wise equality.
    bool operator==(const PageKey&) const = default;
};

/// @brief Hash of a PageKey, for the pool's map of resident pages.
struct PageKeyHash {
    /// @brief Mixes the key's four integers.
    std::size_t operator()(const PageKey& key) const;
};

/// @brief The geometry of a directional light's clipmap: each level a kVirtualResolution² window of pages
/// (pageSize² texels each) around the camera, its origin snapped to whole pages so the texel grid stays
/// fixed in world space (the window of level k+1 is twice the radius of level k's).
struct ClipmapGeometry {
    /// World → light space (lightView(direction)): x, y across the light, z towards it.
    glm::mat4 lightView{1.0f};
    /// The camera's light-space x, y (the windows' centre).
    glm::vec2 camera{0.0f};
    /// Light-space z range of every caster and receiver, snapped outward (depthRangeFor).
    glm::vec2 depth{0.0f, 1.0f};
    /// Side of a page, texels (ShadowSettings::virtualPageSize).
    int pageSize = 128;
    /// Finest absolute level of the clipmap's kClipmapLevels.
    int finestLevel = 0;

    /// Pages along each side of a level's window.
    [[nodiscard]] int pagesPerSide() const { return kVirtualResolution / pageSize; }
    /// World size of one texel of absolute level `level`.
    [[nodiscard]] static double texelSize(int level);
    /// First page (absolute, both axes) of level `level`'s window.
    [[nodiscard]] glm::ivec2 windowOrigin(int level) const;
    /// The projection of level `level`'s whole window (its worldToShadow maps the window to [0,1]², z the
    /// stored depth), as the lighting pass reads the level.
    [[nodiscard]] LightProjection levelProjection(int level) const;
    /// The view and projection page `page` of level `level` is drawn with: the page and `borderTexels` of
    /// its neighbours' texels on every side, on the level's own texel grid.
    [[nodiscard]] LightProjection pageProjection(int level, glm::ivec2 page, int borderTexels) const;
    /// The light-space x, y rectangle (min, max) that page `page` of `level` and its border cover.
    [[nodiscard]] glm::vec4 pageRect(int level, glm::ivec2 page, int borderTexels) const;

private:
    LightProjection projectionOver(glm::dvec2 low, glm::dvec2 high, int level) const;
};

/// @brief The virtual map of a spot light or of one face of a point light: one perspective projection of
/// kVirtualResolution² texels with mip levels, level m of texels 2^m level-0 texels wide in
/// (pagesPerSide() >> m)² pages. Every page is a crop of the same frustum, so all levels store the same depth
/// and a page keeps its texels while the light and its depth range stay.
struct PerspectiveGeometry {
    /// The whole map's projection (level 0 at kVirtualResolution²), its depth range snapped outward
    /// (virtualPerspective).
    LightProjection face;
    /// Side of a page, texels (ShadowSettings::virtualPageSize).
    int pageSize = 128;

    /// Pages along each side of level 0.
    [[nodiscard]] int pagesPerSide() const { return kVirtualResolution / pageSize; }
    /// Mip levels, down to one page: log2(pagesPerSide()) + 1.
    [[nodiscard]] int levels() const;
    /// The shadow texture rectangle (min x, min y, max x, max y) of page `page` of level `level` and
    /// `borderTexels` of that level's texels on every side.
    [[nodiscard]] glm::vec4 pageRect(int level, glm::ivec2 page, int borderTexels) const;
    /// The projection page `page` of level `level` is drawn with: the face's frustum cropped to pageRect.
    [[nodiscard]] LightProjection pageProjection(int level, glm::ivec2 page, int borderTexels) const;
};

/// @brief A perspective virtual map with light view `view`, square field of view `fov` and near and far
/// `depthRange` (a fitted map's), the range widened to quarter octaves (near down, far up), so a caster
/// moving inside the light's reach rarely changes it (a change redraws every page of the map). Invalid when
/// the range is not positive and finite.
LightProjection virtualPerspective(const glm::mat4& view, float fov, glm::vec2 depthRange);

/// @brief The light-space z range a light's pages are drawn with: that of `boxes` in `lightView`, widened to
/// a grid of an eighth of its span rounded up to a power of two, so a caster moving inside the scene's
/// bounds rarely changes it (a change redraws every page of the light).
glm::vec2 depthRangeFor(const glm::mat4& lightView, std::span<const Aabb> boxes);

/// @brief The absolute level whose grid has texels no wider than the world size `texelSize`, floor(log2),
/// clamped to [base, base + kRequestLevels − 1]; NaN or non-positive sizes give `base`'s finest.
int levelForTexelSize(double texelSize, int base);

/// @brief The finest request level a scene spanning `sceneExtent` world units may need: 24 octaves below it
/// (texels of a 16 millionth of the scene), so the request levels reach 40 octaves above it.
int requestLevelBase(float sceneExtent);

/// @brief Entry of a page table texel (R32UI): 0 when no page of this or a coarser level is resident; else
/// bit 31, the clipmap level index (0 finest) of the page that covers it in bits 24–29, its atlas tile in
/// bits 0–23.
std::uint32_t pageTableEntry(int levelIndex, int tile);
inline constexpr std::uint32_t kPageResidentBit = 0x80000000u;
/// Set by the module in entries whose page was drawn this frame (the pages debug view).
inline constexpr std::uint32_t kPageDrawnBit = 0x40000000u;
inline constexpr std::uint32_t kPageTileMask = 0x00ffffffu;

/// @brief One light's page requests in a frame: (level, face, page y, page x), so the finest level comes
/// first. A clipmap's levels are absolute, a perspective map's its mip levels; face is 0 but for cube faces.
using PageRequests = std::set<std::tuple<int, int, int, int>>;

class PagePool;

/// @brief What coarsenToFit knows of one light.
struct CoarseningLight {
    /// Engine light index (its pages' PageKey::light).
    int light = 0;
    /// The coarsest level its lookups read.
    int coarsestLevel = 0;
    /// A clipmap's camera, in pages of absolute level 0; NaN for a perspective map.
    glm::dvec2 centre{std::numeric_limits<double>::quiet_NaN()};
    /// The pool whose resident pages are drawn already (none: nothing is).
    const PagePool* pool = nullptr;
};

/// @brief Coarsens `requests` (one set per light, described by `lights`) until they hold at most `capacity`
/// pages. The light asking for the most pages gives way first, one group of its finest level's pages that
/// share a parent at a time, among the groups that free a page: a clipmap's farthest from its camera first,
/// so its finest region shrinks around the camera; a perspective map's those freeing the most per page they
/// coarsen first (the parent asked for already, then four children, three, two). So the pool ends as full as
/// the requests allow. Groups whose pages are all resident in the pool go last (a clipmap's unless √2 times
/// farther than the others), so a walking camera keeps its drawn pages. Where no group of a level frees a
/// page (lone children of parents nobody asked for), the level moves up whole. Stops when every light is at
/// its coarsest level. Returns how many pages fewer the requests hold.
int coarsenToFit(std::vector<PageRequests>& requests, std::span<const CoarseningLight> lights,
                 std::size_t capacity);

/// @brief The physical pages: a fixed number of atlas tiles shared by every light, each holding one
/// PageKey's texels, reused least recently used first. Pure bookkeeping; no GL.
class PagePool {
public:
    /// @brief A pool of `tiles` free tiles (none when `tiles` is not positive).
    explicit PagePool(int tiles);

    /// @brief What one frame's requests led to.
    struct FrameResult {
        /// Tiles to draw this frame (newly given to a key, or invalidated), with their key.
        std::vector<std::pair<int, PageKey>> render;
        /// Requests already resident and valid (no drawing).
        int cached = 0;
        /// Requests that got no tile: the budget is full of pages this frame also asked for.
        int refused = 0;
    };

    /// @brief Serves `requests` for frame `frame` (> every earlier frame), in the given order: a resident key
    /// is touched; a new one takes a free tile or evicts the least recently used tile not requested this
    /// frame; when none is left it is refused. Order requests coarse to fine so that over budget the coarse
    /// levels stay, and the fine ones fall back to them.
    FrameResult request(std::span<const PageKey> requests, std::uint64_t frame);
    /// @brief Adds free tiles up to `tiles` in all (nothing when it holds as many already); resident pages
    /// keep their tiles.
    void grow(int tiles);
    /// @brief Drops every resident page of `light` (its direction or depth range changed).
    int invalidateLight(int light);
    /// @brief Drops the pages of `light` for which `stale(key)` holds; returns how many.
    template <typename Stale>
    int invalidateWhere(int light, Stale&& stale) {
        int dropped = 0;
        for (int tile = 0; tile < static_cast<int>(tiles_.size()); ++tile) {
            const Tile& record = tiles_[static_cast<std::size_t>(tile)];
            if (record.used && record.key.light == light && stale(record.key)) {
                release(tile);
                ++dropped;
            }
        }
        return dropped;
    }
    /// @brief Drops the pages of `light` whose light-space rectangle (with `borderTexels` of their level's
    /// texels) overlaps `rect` (min x, min y, max x, max y) in `geometry`: a caster there moved.
    int invalidate(int light, const ClipmapGeometry& geometry, glm::vec4 rect, int borderTexels);

    /// @brief The tile holding `key`, -1 when it is not resident.
    [[nodiscard]] int tileOf(const PageKey& key) const;
    /// @brief Tiles in the pool.
    [[nodiscard]] int tiles() const { return static_cast<int>(tiles_.size()); }
    /// @brief Tiles holding a page.
    [[nodiscard]] int resident() const { return static_cast<int>(residents_.size()); }
    /// @brief Calls `visit(key, tile)` for every resident page.
    template <typename Visit>
    void forEachResident(Visit&& visit) const {
        for (const auto& [key, tile] : residents_) {
            visit(key, tile);
        }
    }

private:
    struct Tile {
        PageKey key;
        std::uint64_t lastUsed = 0;
        bool used = false;
    };
    void release(int tile);

    std::vector<Tile> tiles_;
    std::vector<int> free_;
    std::unordered_map<PageKey, int, PageKeyHash> residents_;
};

/// @brief The page table of one light's clipmap: kClipmapLevels layers of pagesPerSide² entries
/// (pageTableEntry), finest level first. A page that is not resident points at the finest resident page of a
/// coarser level that covers it, so a lookup reads one entry and lands on the finest texels anyone rendered
/// there.
std::vector<std::uint32_t> buildPageTable(const PagePool& pool, int light, const ClipmapGeometry& geometry);

/// @brief The page table of face `face` of `light`'s perspective map, a mip chain: level m's
/// (pagesPerSide >> m)² entries after the finer levels', finest first, each page without texels pointing at
/// its finest resident ancestor (as buildPageTable).
std::vector<std::uint32_t> buildPageTable(const PagePool& pool, int light, int face,
                                          const PerspectiveGeometry& geometry);

} // namespace shadows
