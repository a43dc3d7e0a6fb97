#pragma once

#include <shadows/LightFrustum.h>
#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettings.h>
#include <shadows/TapPattern.h>
#include <shadows/VirtualPages.h>

#include <engine/Module.h>
#include <engine/PassTimer.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/VertexArray.h>

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace shadows {

struct LightMapsBlock;
struct MapInputs;
struct MapSlot;
class MapAllocator;
class PageMarkPrograms;
class ShadowSamplers;
class JitterTexture;
class VisibleSamples;
struct OnceWarnings;

/// @brief Resource and frame counters of the shadow module.
struct ShadowStats {
    /// Shadow maps drawn in the last frame: one per shadow-casting spot or directional light with visible
    /// receivers, one per cascade and one per cube face that has visible receivers.
    int shadowMaps = 0;
    /// GPU memory of the allocated shadow maps (depth plus any gradient target), bytes; with virtual maps,
    /// the page pool, the page tables and the request buffer too.
    std::size_t bytes = 0;
    /// Side of the whole maps drawn in the last frame, texels: ShadowSettings::resolution, or less where a
    /// directional map took the side its view needs (ShadowSettings::fittedTexelPixels); 0 with none drawn or
    /// with virtual maps.
    int mapResolution = 0;
    /// Texels of the whole maps drawn in the last frame that casters were drawn into, summed over the maps:
    /// each map's LightProjection::drawnRegion, the fill the shadow pass spent (0 with virtual maps, whose
    /// `pages` count what was drawn). A map a moving view draws again where it lay also fills a margin beyond
    /// its region, which this leaves out.
    std::size_t casterTexels = 0;
    /// Whether the last frame kept the maps of the frame before, nothing they are drawn from having changed
    /// (ShadowSettings::reuseUnchangedMaps): it drew no map and ran no sample pass.
    bool reusedMaps = false;
    /// Whether the last frame's view moved but kept the whole maps of the frame before: its fit took their
    /// placements, which held its samples, and nothing they are drawn from had changed
    /// (ShadowSettings::reuseUnchangedMaps). It ran the sample pass and drew no map.
    bool keptMaps = false;
    /// Whether the last frame's sample pass (the view's depth, to fit maps or mark pages) took the lighting
    /// pass's depth pre-pass (engine::ModuleHost::viewDepth) instead of drawing the view itself; false when
    /// it ran none.
    bool sharedViewDepth = false;
    /// Whether the last frame's lights read virtual maps (ShadowSettings::mapAllocation).
    bool virtualMaps = false;
    /// The virtual maps' page counters in the last frame (zero without virtual maps).
    VirtualPageStats pages;
    /// What the caster pass drew and left out in the last frame, over every map (zero when it drew none).
    engine::DrawnMeshes casters;
    /// The last frame's pre-pass in its two parts (ShadowModule::setPartTiming), milliseconds: this, the fit
    /// (the view's sample pass and its reduction, or the virtual maps' page marking, and the allocation).
    /// Zero for a frame that kept its maps, negative while part timing is off.
    double fitMilliseconds = -1.0;
    /// The other part, the maps (their clears, the casters, moment filtering); zero and negative as
    /// fitMilliseconds.
    double mapsMilliseconds = -1.0;
};

/// @brief The shadow module: shadow maps for shadow-casting lights and the lighting-pass visibility of the
/// technique in ShadowSettings. Link it and `Engine::addModule`, or load it as module "shadows".
///
/// Settings changes take effect lazily on the next frame (osgShadow style): resources are (re)allocated only
/// for lights that cast shadows and only of the kinds the technique needs; shader variants compile on first
/// draw.
class ShadowModule final : public engine::Module {
public:
    /// @brief A module with the default ShadowSettings (what a module loaded by name starts with).
    ShadowModule();
    /// @brief A module with `settings`. Throws std::invalid_argument listing each bad field.
    explicit ShadowModule(const ShadowSettings& settings);
    ~ShadowModule() override;

    /// @brief "shadows", the name it is attached and loaded under.
    [[nodiscard]] std::string_view name() const override { return "shadows"; }

    /// @brief Validates and applies `settings`. Throws std::invalid_argument listing each bad field.
    void setSettings(const ShadowSettings& settings);
    /// @brief The settings in effect (those last given to setSettings).
    [[nodiscard]] const ShadowSettings& settings() const { return settings_; }
    /// @brief What the passes do for the current settings (resolved by setSettings).
    [[nodiscard]] const ShadowPlan& plan() const { return plan_; }
    /// @brief Shadow maps drawn in the last frame and the memory they hold.
    [[nodiscard]] ShadowStats stats() const;
    /// @brief The projection of the first shadow map of engine light `lightIndex` in the last frame (its
    /// nearest cascade, its first cube face drawn), if it has one.
    [[nodiscard]] std::optional<LightProjection> lightProjection(int lightIndex) const;
    /// @brief The projections of every shadow map of engine light `lightIndex` in the last frame, in slot
    /// order (cascades near to far, cube faces in gsCubeFace's order, those drawn).
    [[nodiscard]] std::vector<LightProjection> lightProjections(int lightIndex) const;
    /// @brief Fits the maps to `view` instead of the frame's camera; nullopt (the default) follows the
    /// camera. A frozen fit shows what a camera's maps cover from elsewhere, and lets a measurement move the
    /// fit while the observer stays still (shimmer, docs/RESULTS.md). A frozen fit's maps are drawn whole,
    /// where the camera's own draw casters only where its visible samples read
    /// (LightProjection::drawnRegion).
    void setFitView(std::optional<FitView> view) { fitView_ = view; }
    /// @brief Times the pre-pass's two parts, the fit and the maps (ShadowStats::fitMilliseconds,
    /// mapsMilliseconds), by `method`; nullopt (the default) times nothing. The parts wait for the GPU
    /// between them, so together they take a little more than the pass does untimed.
    void setPartTiming(std::optional<engine::TimingMethod> method);

    /// @brief Registers the module's GLSL files and reserves its texture units.
    void attach(engine::ModuleHost& host) override;
    /// @brief Releases every GL resource; the module may be attached again.
    void detach() override;
    /// @brief The visibility code for forward.frag's `declarations` and `light_visibility` slots, and the
    /// debug views for `final_color`.
    [[nodiscard]] std::vector<engine::ShaderChunk> shaderChunks() const override;
    /// @brief Applies a settings change: drops the resources it affects and picks the variants.
    void prepareFrame(const engine::FrameContext& frame) override;
    /// @brief Fits a projection for each shadow-casting light to the receivers in view (a directional light's
    /// to the visible samples of a depth pass of the view, by default), allocates its map (again after a
    /// settings change), uploads the shadow uniform block, then draws the shadow maps (and filters moments
    /// for the moment techniques). A frame that changed nothing the maps are drawn from keeps the
    /// last frame's (ShadowSettings::reuseUnchangedMaps).
    void renderPrePasses(const engine::FrameContext& frame) override;
    /// @brief The technique's lighting variant while this frame has a shadow map, else 0.
    [[nodiscard]] engine::ShaderVariantKey variantBits(const engine::DrawContext& draw) const override;
    /// @brief Binds the maps, their samplers and the uniform block; sets `program`'s sampler units and tap
    /// arrays once per program and frame.
    void bindLightingResources(const engine::gl::Program& program, const engine::DrawContext& draw) override;

private:
    void releaseResources();
    /// The allocation of the settings' ShadowSettings::mapAllocation, made after a settings change.
    MapAllocator& allocation();
    /// Fits every shadow-casting light's maps for `frame` seen through `fit`, whose meshes have world bounds
    /// `boxes` (of `entities`), allocates them and uploads the block.
    void fitMaps(const engine::FrameContext& frame, const FitView& fit, const std::vector<Aabb>& boxes,
                 const std::vector<engine::EntityId>& entities);
    /// Draws the maps fitted for `frame` (and blurs and filters their moments where the plan asks).
    void drawMaps(const engine::FrameContext& frame);
    /// Blurs the moments (ShadowPlan::blursMoments).
    void blurMoments();
    /// Writes this frame's GsShadowBlock: the maps' projections, each light's maps and size (of
    /// `frameLights`) and the settings' scalars.
    void uploadBlock(const std::vector<LightMapsBlock>& lights, const FitView& fit,
                     std::span<const engine::FrameLight> frameLights);
    [[nodiscard]] engine::ShaderVariantKey variantKey(const std::vector<std::string_view>& defines) const;
    /// The variant bits of the map layouts (LightMapsKind) `lights` use, which the lighting pass compiles
    /// alone, GS_SHADOW_ONE_MAP where the frame has one map, and GS_SHADOW_ORTHOGRAPHIC where every map is
    /// orthographic.
    [[nodiscard]] engine::ShaderVariantKey layoutKey(const std::vector<LightMapsBlock>& lights) const;

    ShadowSettings settings_;
    ShadowPlan plan_;
    TapPattern pattern_;
    engine::ModuleHost* host_ = nullptr;
    std::unique_ptr<ShadowSamplers> samplers_;
    GLuint mapUnit_ = 0;
    GLuint gradientUnit_ = 0;
    GLuint jitterUnit_ = 0;
    GLuint pageTableUnit_ = 0;
    std::unique_ptr<JitterTexture> jitter_;
    std::unique_ptr<engine::gl::VertexArray> fullscreenVertexArray_;
    std::vector<MapSlot> slots_; // this frame's maps, in the block's slot order
    std::unique_ptr<MapAllocator> allocation_;
    std::unique_ptr<engine::gl::Buffer> shadowBlock_;
    std::optional<FitView> fitView_;
    // The view's depth, which fits directional maps or marks virtual pages, and the page-marking programs
    // live while attached: a settings change makes a new allocation, not these anew.
    std::unique_ptr<VisibleSamples> samples_;
    std::unique_ptr<PageMarkPrograms> pageMarkPrograms_;
    std::unique_ptr<OnceWarnings> warnings_;
    engine::ShaderVariantKey lightingKey_ = 0;
    engine::ShaderVariantKey depthKey_ = 0;
    engine::ShaderVariantKey layoutKey_ = 0;        // this frame's map layouts
    std::map<GLuint, std::uint64_t> uploadedFrame_; // program -> frame whose uniforms it holds
    std::unique_ptr<MapInputs> drawnFrom_;          // what the fitted maps in place were drawn from
    bool reusedMaps_ = false;                       // this frame kept them
    bool keptMaps_ = false;                         // this frame's moved view kept them
    bool sharedViewDepth_ = false;                  // this frame's sample pass took the view depth
    engine::DrawnMeshes casters_;                   // what this frame's caster pass drew
    std::optional<engine::PassTimer> partTimer_;    // times the fit and the maps apart (setPartTiming)
    double fitMilliseconds_ = -1.0;                 // this frame's parts, as ShadowStats gives them
    double mapsMilliseconds_ = -1.0;
    std::uint64_t frameIndex_ = 0;
    bool dirty_ = true;
};

} // namespace shadows
