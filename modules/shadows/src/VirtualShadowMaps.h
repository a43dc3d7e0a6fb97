#pragma once

#include "ShadowMapArray.h"

#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettings.h>
#include <shadows/VirtualPages.h>

#include <engine/Module.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/Program.h>
#include <engine/gl/TextureArray.h>

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace shadows {

/// @brief The virtual shadow maps of directional lights: a clipmap of kClipmapLevels levels per light, each
/// a kVirtualResolution² window of pages around the camera; pages are marked from the view's depth image on
/// the GPU (shaders/shadows/pages.comp), served from one pool of atlas tiles in a fixed budget (PagePool,
/// least recently used first) and drawn only when new or invalidated. Every lookup goes through the light's
/// page table (buildPageTable) to the finest resident page over it.
class VirtualShadowMaps {
public:
    /// @brief Sizes the pool for `settings.virtualBudgetMiB` and the plan's formats. Throws
    /// std::invalid_argument when the budget holds no page.
    VirtualShadowMaps(const ShadowSettings& settings, const ShadowPlan& plan);

    /// @brief One light's pages this frame.
    struct Light {
        int index = 0;
        ClipmapGeometry geometry;
        /// First layer of its page table in pageTable().
        int pageLayer = 0;
    };

    /// @brief Marks, with `mark` (shaders/shadows/pages.comp), the pages the view's depth image `depth` (of
    /// `size`, seen through `fit`) asks for, for
    /// each light in `lights` (directional, shadow-casting), invalidates the pages of casters that moved
    /// (`casters`: each mesh entity's world box), allocates and uploads the page tables. Returns the lights'
    /// clipmaps, in order.
    std::vector<Light> update(const engine::gl::Program& mark, const FitView& fit,
                              std::span<const engine::FrameLight> lights,
                              const std::map<engine::EntityId, Aabb>& casters, std::span<const Aabb> boxes,
                              GLuint depth, glm::ivec2 size);
    /// @brief Draws this frame's new pages with `program` (the shadow pass's, in use), clearing each tile
    /// first; `clearMoments` is the moments' clear value where the plan stores them.
    void render(engine::ModuleHost& host, const engine::Scene& scene, const engine::gl::Program& program,
                const glm::vec4& clearMoments);

    [[nodiscard]] const ShadowMapArray& atlas() const { return *atlas_; }
    [[nodiscard]] GLuint pageTable() const { return pageTable_ ? pageTable_->id() : 0; }
    [[nodiscard]] const VirtualPageStats& stats() const { return stats_; }
    /// @brief GPU bytes: the atlas, the page tables and the request buffer.
    [[nodiscard]] std::size_t bytes() const;
    /// @brief x pages per side of a level, y tiles per atlas row, z atlas side.
    [[nodiscard]] glm::ivec4 pagesUniform() const;
    /// @brief x page side, y tile side, z border, w 1 / atlas side.
    [[nodiscard]] glm::vec4 pageUniform() const;

private:
    struct LightState {
        glm::vec3 direction{0.0f};
        glm::vec2 depth{0.0f};
    };
    /// Reads back the request bits of `light` and turns them into pool keys, coarse to fine, clamped to
    /// its clipmap (sets the geometry's finest level).
    std::vector<PageKey> requestedPages(int light, ClipmapGeometry& geometry, int levelBase);
    void invalidateMovedCasters(const std::vector<Light>& lights,
                                const std::map<engine::EntityId, Aabb>& casters);

    ShadowPlan plan_;
    int pageSize_ = 128;
    int border_ = 2;
    int tile_ = 132;
    float texelPixels_ = 1.0f;
    int tilesPerRow_ = 1;
    int layers_ = 1;
    PagePool pool_;
    std::unique_ptr<ShadowMapArray> atlas_;
    std::optional<engine::gl::TextureArray> pageTable_;
    int pageTableLights_ = 0;
    std::optional<engine::gl::Buffer> requests_;
    std::map<int, LightState> lightStates_;
    std::map<engine::EntityId, Aabb> casters_; // last frame's
    std::vector<Light> lights_;                // this frame's
    std::vector<std::pair<int, PageKey>> toRender_;
    VirtualPageStats stats_;
    std::uint64_t frame_ = 0; // the pool's clock: one tick per update
    /// What each light's uploaded page table was built for.
    struct UploadedTable {
        int light = 0;
        int finestLevel = 0;
        glm::ivec2 finestOrigin{0};
        bool drawnBits = false;
        bool operator==(const UploadedTable&) const = default;
    };
    std::vector<UploadedTable> uploaded_;
};

} // namespace shadows
