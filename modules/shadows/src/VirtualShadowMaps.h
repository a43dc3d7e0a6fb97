#pragma once

#include "MapAllocator.h"
#include "PageMarkPrograms.h"

#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettings.h>
#include <shadows/VirtualPages.h>

#include <engine/Module.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Program.h>
#include <engine/gl/TextureArray.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <tuple>
#include <vector>

namespace shadows {

class VisibleSamples;

/// @brief The virtual shadow maps: a clipmap of kClipmapLevels levels per directional light, each a
/// kVirtualResolution² window of pages around the camera; one perspective map with mip levels per spot light
/// and per face of a point light (PerspectiveGeometry). Pages are marked from the view's depth image on
/// the GPU (shaders/shadows/pages.comp), served from one pool of atlas tiles in a fixed budget (PagePool,
/// least recently used first) and drawn only when new or invalidated. Every lookup goes through the light's
/// page table (buildPageTable) to the finest resident page over it.
class VirtualShadowMaps final : public MapAllocator {
public:
    /// @brief A pool in `settings.virtualBudgetMiB` for the plan's formats, allocated with the first frame's
    /// lights (their page tables share the budget); pages are marked with `marks` from the view's depth drawn
    /// by `samples`, and an overflowing budget is said once in `warnings`. Throws std::invalid_argument when
    /// the budget holds no page beside the page requests.
    VirtualShadowMaps(engine::ModuleHost& host, const ShadowSettings& settings, const ShadowPlan& plan,
                      VisibleSamples& samples, PageMarkPrograms& marks, OnceWarnings& warnings);
    ~VirtualShadowMaps() override;

    /// @brief Serves the frame's shadow-casting lights from virtual maps: draws the view's depth, marks and
    /// allocates the pages it asks for (update), and adds each light's clipmap levels or faces as slots. A
    /// light whose page tables or slots do not fit beside the others casts no shadow, saying so.
    void allocate(const AllocationFrame& frame, std::vector<MapSlot>& slots,
                  std::vector<LightMapsBlock>& lights) override;
    /// @brief Draws this frame's new pages (the slots are the levels they crop), clearing each tile first.
    engine::DrawnMeshes render(const engine::Scene& scene, const engine::gl::Program& program,
                               std::span<const MapSlot> slots, const CasterOmissions& omissions) override;
    /// @brief Blurs the moments of this frame's new pages, each within its tile, through a tile-sized
    /// temporary: the border holds the blur's reach (ShadowPlan::kernelReachTexels), so page edges blur as a
    /// whole map's interior would.
    void blurMoments(const engine::gl::Program& blur, GLuint unit) override;
    [[nodiscard]] const ShadowMapArray* sampled() const override { return atlas_.get(); }
    [[nodiscard]] GLuint pageTable() const override { return pageTable_ ? pageTable_->id() : 0; }
    /// @brief The page and atlas geometry (ShadowBlock::virtualPages, virtualPage).
    void describe(ShadowBlock& block) const override;
    /// @brief GPU bytes: the atlas, the page tables and the request buffer (within the budget).
    [[nodiscard]] std::size_t bytes() const override;
    [[nodiscard]] bool servedVirtualMaps() const override { return served_; }
    [[nodiscard]] VirtualPageStats pageStats() const override { return stats_; }

    /// @brief One light's pages this frame.
    struct Light {
        int index = 0;
        /// 0: a directional light's clipmap (`geometry`); 1: a spot light's map, 6: a point light's faces
        /// (`faces`).
        int faceCount = 0;
        ClipmapGeometry geometry;
        /// Spot: [0]; point: cubeFaceAxis's order. A face whose projection is not valid has no visible
        /// receiver this frame.
        std::array<PerspectiveGeometry, kCubeFaces> faces{};
        /// First layer of its page table in pageTable(): a layer per clipmap level (mip level 0 of each), or
        /// a layer per face holding its levels as mip levels.
        int pageLayer = 0;
        /// Spot and point lights: where they shine from, the spot's axis and the cosine of its outer cone
        /// (-2 for a point light), the range (0 unlimited): pixels they do not reach ask for no pages.
        glm::vec3 position{0.0f};
        glm::vec3 direction{0.0f, 0.0f, -1.0f};
        float coneCosine = -2.0f;
        float range = 0.0f;
        /// Levels a lookup can read: kClipmapLevels, or the perspective maps' mip levels.
        [[nodiscard]] int levels() const { return faceCount == 0 ? kClipmapLevels : faces[0].levels(); }
        /// Layers of the page table.
        [[nodiscard]] int layers() const { return pageTableLayers(faceCount); }
        /// The faces of a light of `type`: 0 (a clipmap), 1 (spot) or kCubeFaces (point).
        [[nodiscard]] static int facesOf(engine::LightType type) {
            return type == engine::LightType::Directional ? 0
                   : type == engine::LightType::Spot      ? 1
                                                          : kCubeFaces;
        }
        /// Page-table layers of a light with `faceCount` faces: a layer per clipmap level, or per face.
        [[nodiscard]] static int pageTableLayers(int faceCount) {
            return faceCount == 0 ? kClipmapLevels : faceCount;
        }
    };

private:
    /// Marks (shaders/shadows/pages.comp) the pages the view's depth image `depth` (of `size`, seen through
    /// `fit`) asks for, for each light in `lights` (shadow-casting), invalidates the pages of casters that
    /// moved (`casters`: each mesh entity's world box), allocates and uploads the page tables. Returns the
    /// lights' clipmaps, in order.
    std::vector<Light> update(const FitView& fit, std::span<const engine::FrameLight> lights,
                              const std::map<engine::EntityId, Aabb>& casters, std::span<const Aabb> boxes,
                              GLuint depth, glm::ivec2 size);

    /// What each light's pages were drawn with: a change redraws them.
    struct LightState {
        int faceCount = -1;
        glm::vec3 direction{0.0f};
        glm::vec2 depth{0.0f};
        /// The last valid projection of each face (a face with no visible receiver keeps its pages, which
        /// casters moving meanwhile still invalidate).
        std::array<std::optional<PerspectiveGeometry>, kCubeFaces> faces{};
    };
    /// Fits `light`'s clipmap or faces and drops its pages when what they were drawn with changed.
    Light fitLight(const engine::FrameLight& light, const FitView& fit, std::span<const Aabb> boxes);
    /// Runs the page marking for `light` and reads back its request bits as pages; a clipmap's are clamped to
    /// its kClipmapLevels (which sets the geometry's finest level).
    PageRequests markPages(Light& light, const FitView& fit, int levelBase, glm::ivec2 size);
    void uploadPageTables();
    /// Sizes the pool to `wanted` tiles, at most what the budget leaves beside `tableLayers` page-table
    /// layers and the requests (at least one page, warned). Beside the same layers it grows, the resident
    /// pages copied to the new atlas; else it starts empty.
    void allocatePool(int tableLayers, std::size_t wanted);
    /// How the atlas is laid out beside `tableLayers` page-table layers: square layers of a fixed size, as
    /// many as the budget holds beside the tables, the requests and the blur's tile (at least one tile).
    struct PoolLayout {
        int tilesPerRow = 1;
        std::size_t tilesPerLayer = 1;
        /// Layers at most.
        std::size_t layers = 1;
        /// Whether the budget holds even one tile beside the rest.
        bool fitsBudget = true;
        [[nodiscard]] std::size_t tiles() const { return tilesPerLayer * layers; }
    };
    [[nodiscard]] PoolLayout poolLayout(int tableLayers) const;
    /// GPU bytes of the blur's temporary tile (none unless the plan blurs moments).
    [[nodiscard]] std::size_t blurTileBytes() const;
    void invalidateMovedCasters(const std::vector<Light>& lights,
                                const std::map<engine::EntityId, Aabb>& casters);

    engine::ModuleHost& host_;
    VisibleSamples& samples_;
    PageMarkPrograms& marks_;
    OnceWarnings& warnings_;
    int budgetMiB_ = 0;
    bool served_ = false; // the last frame had a shadow-casting light
    ShadowPlan plan_;
    int pageSize_ = 128;
    int border_ = 2;
    int tile_ = 132;
    float texelPixels_ = 1.0f;
    int tilesPerRow_ = 1;
    int layers_ = 1;
    std::size_t budget_ = 0;
    int poolTableLayers_ = -1; // the page-table layers the pool was sized beside
    PagePool pool_;
    std::unique_ptr<ShadowMapArray> atlas_;
    /// The moment blur's horizontal pass of one tile (ShadowPlan::blursMoments only).
    std::optional<engine::gl::TextureArray> blurTile_;
    std::optional<engine::gl::Framebuffer> blurTileFramebuffer_;
    std::optional<engine::gl::TextureArray> pageTable_;
    int pageTableLayers_ = 0;
    std::optional<engine::gl::Buffer> requests_;
    std::map<int, LightState> lightStates_;
    std::map<engine::EntityId, Aabb> casters_; // last frame's
    std::vector<Light> lights_;                // this frame's
    std::vector<std::pair<int, PageKey>> toRender_;
    VirtualPageStats stats_;
    std::uint64_t frame_ = 0; // the pool's clock: one tick per update
    GLuint samplesDepth_ = 0; // the view's depth image the pages are marked from
    /// What each light's uploaded page table was built for.
    struct UploadedTable {
        int light = 0;
        int faceCount = 0;
        int finestLevel = 0;
        glm::ivec2 finestOrigin{0};
        bool drawnBits = false;
        bool operator==(const UploadedTable&) const = default;
    };
    std::vector<UploadedTable> uploaded_;
    int levelsPerTable_ = 1; // mip levels of the page table: the perspective maps' levels
};

} // namespace shadows
