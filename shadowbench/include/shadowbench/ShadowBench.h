#pragma once

#include <shadowbench/FetchProbe.h>
#include <shadowbench/RayTracedVisibility.h>
#include <shadowbench/ShadowMetrics.h>
#include <shadowbench/SoftShadowMetrics.h>

#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/GlContext.h>
#include <engine/Image.h>
#include <engine/LightAim.h>
#include <engine/PassTimer.h>
#include <engine/RenderTarget.h>
#include <shadows/LightFrustum.h>
#include <shadows/ShadowSettings.h>
#include <shadows/VirtualPages.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace shadows {
class ShadowModule;
} // namespace shadows

namespace shadowbench {

/// @brief One configuration of a sweep: a label and the shadow settings it runs.
struct BenchConfig {
    std::string label;
    shadows::ShadowSettings settings;
};

/// @brief Median and spread of one pass over the timed frames, milliseconds.
struct PassTiming {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
    /// How many timed frames (or rounds' differences) they are of; 0 when nothing was timed.
    int samples = 0;
};

/// @brief The median (of an even count, the mean of the middle two), least and greatest of `samples`, and
/// their count; all zero for none.
[[nodiscard]] PassTiming summariseTimes(std::vector<double> samples);

/// @brief Everything measured for one scene and configuration.
struct BenchResult {
    std::string scene;
    BenchConfig config;
    ShadowMetrics metrics;
    /// Against a soft ground truth (BenchOptions::softSamplesPerAxis): the penumbra's errors.
    std::optional<SoftShadowMetrics> soft;
    PassTiming shadowPass;
    /// The shadow pass's two parts, timed apart in the same frames (shadows::ShadowStats::fitMilliseconds and
    /// mapsMilliseconds): the fit (sample pass, reduction or page marking) and the maps (clears, casters).
    PassTiming fitPart;
    PassTiming mapsPart;
    PassTiming lightingPass;
    /// The cost model (BenchOptions::costModel): the lighting pass minus the unshadowed one, each round's two
    /// timed back to back so that a drift of the machine's speed cancels; median, least and largest over the
    /// rounds. Empty when not measured (an overhead within the noise may be negative).
    std::optional<PassTiming> lightingOverhead;
    /// Whole frames (glFinish + steady clock around Engine::renderFrame), as an application would see them,
    /// each drawing its maps (ShadowSettings::reuseUnchangedMaps off), as every frame of a moving view does.
    /// The passes above are timed the same way.
    PassTiming frame;
    /// The same view's frames with reuseUnchangedMaps on after one that drew them: a still view's, which
    /// keep their maps (virtual maps from the frame after an update that drew no page). Negative medians when
    /// not timed.
    PassTiming stillFrame{-1.0, -1.0, -1.0};
    /// Whether the last of those frames kept its maps (ShadowStats::reusedMaps).
    bool stillFrameKeptMaps = false;
    /// Empty for our techniques; the osgShadow class for rows of the OpenSceneGraph peer (PeerRun).
    std::string peerClass;
    /// Peer rows: receivers the peer left unlit in its unshadowed frame (a silhouette a pixel off); counted
    /// as visibility 1.
    std::size_t peerUnlitReceivers = 0;
    std::size_t shadowBytes = 0;
    /// Side of the whole maps drawn, texels (ShadowStats::mapResolution); 0 for virtual maps and peer rows.
    int mapResolution = 0;
    /// Texels of the whole maps the casters were drawn into in a frame (ShadowStats::casterTexels).
    std::size_t casterTexels = 0;
    /// Shadow maps drawn (cascades and cube faces count one each); 0 for peer rows.
    int shadowMaps = 0;
    /// Virtual maps (ShadowSettings::mapAllocation): the pages of the cold first frame, and those of the
    /// same view drawn again (a static camera: nothing new to draw).
    bool virtualMaps = false;
    shadows::VirtualPageStats coldPages;
    shadows::VirtualPageStats warmPages;
    /// Virtual maps along the walk (BenchOptions::walkFrames): texels drawn per frame after the first, mean
    /// and largest; negative when not measured or not virtual.
    double walkTexelsPerFrame = -1.0;
    double walkTexelsPerFrameMax = -1.0;
    /// The walk's frames after the first, timed as `frame` is (negative medians when not timed or no walk):
    /// what a moving view's frame costs, with whatever the maps keep from the frame before.
    PassTiming walkFrame{-1.0, -1.0, -1.0};
    /// The walk's frames after the first that kept the whole maps of the frame before
    /// (shadows::ShadowStats::keptMaps); negative when there was no walk.
    int walkKeptFrames = -1;
    /// Jittered PCF with early-out: fraction of covered pixels that took the full kernel (penumbra
    /// candidates); negative for every other configuration.
    double fullKernelFraction = -1.0;
    /// Fraction of receiver pixels whose visibility changes by more than 0.5 between consecutive frames while
    /// the view the maps are fitted to moves in sub-texel steps and the observer stays (measureShimmer);
    /// negative when not measured.
    double shimmer = -1.0;
    /// Fraction of receiver pixels, followed from frame to frame by reprojection while the camera itself
    /// moves (measurePathShimmer), whose visibility flips while the truth's does not; negative when not
    /// measured.
    double pathShimmer = -1.0;
    std::filesystem::path shadedImage;
    /// The shaded frame (also written to shadedImage), for side-by-side sheets.
    engine::Image shaded;
};

/// @brief How a soft ground truth was traced, and how far it is from converged.
struct SoftTruth {
    /// Stratified rays per axis (0: the truth is hard).
    int samplesPerAxis = 0;
    /// The light's radius it sampled (RayTracedVisibility::softVisibility).
    float radius = 0.0f;
    /// RMS difference over the receivers between the truth and one traced with twice the rays per axis
    /// (four times the rays); its noise is at most 0.5/sqrt(rays).
    double convergenceRmse = -1.0;
};

/// @brief The reference pass's one comparison read of one probe map (FetchProbe), minus the unshadowed pass.
struct ProbeMapCost {
    ProbeMap map;
    double oneCompareReadOverheadMs = 0.0; ///< the median of the rounds' differences
};

/// @brief What drawing a scene costs without shadows: its size, our draw calls and unshadowed frame time.
struct SceneCost {
    std::string scene;
    std::size_t triangles = 0;
    /// Chunks drawn by the lighting pass, and those culled against the view.
    std::size_t drawCalls = 0;
    std::size_t culledChunks = 0;
    /// GPU bytes of the scene's vertex and index buffers.
    std::size_t meshBytes = 0;
    PassTiming unshadowedFrame;
    /// The OpenSceneGraph peer's unshadowed frame (from its vdsm run), when it ran; negative medians
    /// otherwise.
    PassTiming peerUnshadowedFrame{-1.0, -1.0, -1.0};
    /// Whether that run raised glibc's allocator thresholds as ours does (PeerRun::allocatorTuned).
    std::optional<bool> peerAllocatorTuned;
    /// The cost model (BenchOptions::costModel; negative when not measured): the unshadowed lighting pass,
    /// and the lighting-pass milliseconds one more fetch per fragment adds (FetchProbe), bilinear and
    /// comparison.
    PassTiming unshadowedLighting{-1.0, -1.0, -1.0};
    double filteredFetchMs = -1.0;
    double compareFetchMs = -1.0;
    /// The reference pass with one comparison read and nothing else, minus the unshadowed pass (the median of
    /// the rounds' differences): the least a one-read variant adds on this renderer. Empty when not measured.
    std::optional<double> oneCompareReadOverheadMs;
    /// The same for maps of other sizes and formats, which move other amounts of memory per read
    /// (FetchProbe::kOtherMaps); empty when not measured.
    std::vector<ProbeMapCost> oneCompareReadByMap;
    /// The scene's ground truth, where it is soft.
    SoftTruth softTruth;
};

/// @brief One technique's visibility against ground truth over one view.
struct Accuracy {
    ShadowMetrics metrics;
    /// Against a soft ground truth: the penumbra's errors.
    std::optional<SoftShadowMetrics> soft;
    std::vector<PixelClass> classes;
    std::vector<float> visibility;
    std::vector<float> truth;
    /// World size of a shadow texel at each receiver pixel (0: no map holds it), which a texel band is
    /// measured in.
    std::vector<float> texelSizes;
    /// Lloyd's m at each receiver pixel (texelFootprints); negative where unknown (a peer's image, a pixel
    /// no map holds).
    std::vector<float> footprints;
};

/// @brief The unit of the boundary band (BenchOptions::bandWidth).
enum class BandUnit { Pixels, Texels };

/// @brief "pixels" or "texels".
[[nodiscard]] std::string_view toString(BandUnit unit);

/// @brief Options of a benchmark run.
struct BenchOptions {
    /// Image size in pixels. Default 640x480.
    glm::ivec2 size{640, 480};
    /// Timed frames after one warm-up frame. Default 5.
    int frames = 5;
    /// Rounds of those frames: run(scene, configs) times every configuration in turn in each round, so a
    /// drift of the machine's speed spreads over all of them, and summarises each configuration's frames of
    /// every round. Default 1.
    int rounds = 1;
    /// Whether run() times frames and passes; without, only accuracy is measured (times are -1). Default
    /// true.
    bool timing = true;
    /// Half-width of the boundary band around true shadow edges (not scored for acne and leak), in
    /// `bandUnit`. Default 2 screen pixels: what a viewer sees. Texels (the map's unit; under a low sun one
    /// texel spans tens of pixels, so a texel band hides staircase edges) stay for comparison.
    float bandWidth = 2.0f;
    BandUnit bandUnit = BandUnit::Pixels;
    /// Soft ground truth: stratified samples per axis (0 = hard ground truth). Default 0.
    int softSamplesPerAxis = 0;
    /// Soft ground truth: the light's radius (a sun's angular radius in radians; a spot or point light's
    /// sphere, world units), or nullopt for the light's own size (RayTracedVisibility::ownRadius). Default
    /// nullopt.
    std::optional<float> softRadius;
    /// Frames of the shimmer measurement (measureShimmer); 0 does not measure it. Default 0.
    int shimmerFrames = 0;
    /// Frames of the camera path of the path shimmer measurement (measurePathShimmer); 0 does not measure it.
    /// Default 0.
    int pathFrames = 0;
    /// Frames of the walk (measureWalk): each configuration's frame time while the camera walks, and virtual
    /// maps' pages drawn per frame; 0 does not measure it. Default 0.
    int walkFrames = 0;
    /// Whether measureCost also measures the cost model (SceneCost::filteredFetchMs). Default false.
    bool costModel = false;
    /// Folder for the images (classification, error heat map, shaded). Default "bench".
    std::filesystem::path imageFolder = "bench";
};

/// @brief A scene prepared for measurement: its G-buffer and ray-traced ground truth, computed once.
class BenchScene {
public:
    /// @brief Prepares `scene` seen from `camera` (a copy is kept) at `options.size`. Throws engine::Error
    /// when the scene has no shadow-casting light.
    BenchScene(std::string name, engine::Scene scene, engine::EntityId camera, const BenchOptions& options);
    ~BenchScene();

    [[nodiscard]] const std::string& name() const { return name_; }
    /// @brief How its ground truth was traced (samplesPerAxis 0: hard).
    [[nodiscard]] const SoftTruth& softTruth() const { return softTruth_; }

private:
    friend class ShadowBench;
    std::string name_;
    engine::Scene scene_;
    engine::EntityId camera_ = engine::kNoEntity;
    engine::FrameLight light_;
    std::vector<glm::vec3> positions_;
    std::vector<glm::vec3> normals_;
    std::vector<Surface> surfaces_;
    std::vector<std::uint8_t> concave_;
    std::vector<float> truth_;
    SoftTruth softTruth_;
    /// World size of one pixel at each covered pixel, across the view ray: a pixel band's reach off the
    /// image.
    std::vector<float> pixelSizes_;
    // Kept for the band: where the light reaches near a shadowed receiver depends on the maps' texel sizes;
    // and for the truth of the path shimmer's moved views (only the camera moves, so the BVH still holds).
    std::unique_ptr<RayTracedVisibility> tracer_;
    // The classes depend on the truth and the maps' texel sizes only: configurations with the same map layout
    // (every technique at its defaults) share one classification.
    mutable std::vector<float> classifiedTexelSizes_;
    mutable std::vector<PixelClass> classes_;

    /// Receiver where the pixel at `position` faces `light` by its smoothed `normal` and by the facet the
    /// tracer's viewer sees there, FacingAway otherwise: one rule for the scene's view and the path's.
    static Surface surfaceFacing(const RayTracedVisibility& tracer, const engine::FrameLight& light,
                                 const glm::vec3& position, const glm::vec3& normal);
    /// The world size of one pixel at each covered pixel across its view ray from `camera`, 0 elsewhere.
    static std::vector<float> viewPixelSizes(const engine::Scene& scene, engine::EntityId camera,
                                             const std::vector<glm::vec3>& positions,
                                             const std::vector<std::uint8_t>& covered, glm::ivec2 size);
};

/// @brief Runs configurations on prepared scenes: accuracy against ground truth and per-pass timing.
class ShadowBench {
public:
    /// @brief Times with the method that suits `context` (PassTimer::methodFor).
    ShadowBench(const engine::GlContext& context, BenchOptions options);
    ShadowBench(engine::TimingMethod method, BenchOptions options);

    /// @brief Loads `path` (a glTF), renders its G-buffer and ray-traces the ground truth for its first
    /// shadow-casting light, pointed from `light` when given (engine::aimLight: a spot or point light is
    /// placed at its distance along that direction) instead of the file's pose. Throws engine::Error
    /// subclasses naming the file on bad input.
    [[nodiscard]] std::unique_ptr<BenchScene>
    prepare(const std::string& name, const std::filesystem::path& path,
            const std::optional<engine::LightAngles>& light = {}) const;

    /// @brief Measures every configuration on one scene and writes their images, in their order. Their
    /// engines are set up first and timed in BenchOptions::rounds alternated rounds; then each is measured
    /// alone.
    std::vector<BenchResult> run(const BenchScene& scene, std::span<const BenchConfig> configs) const;
    /// @brief run() of one configuration.
    BenchResult run(const BenchScene& scene, const BenchConfig& config) const;

    /// @brief Accuracy of `settings` against the scene's ground truth (no timing, nothing written).
    [[nodiscard]] Accuracy measure(const BenchScene& scene, const shadows::ShadowSettings& settings) const;

    /// @brief Accuracy of a visibility image made elsewhere (rows top to bottom, the scene's size), with the
    /// boundary band measured in `texelSizes` (Accuracy::texelSizes).
    [[nodiscard]] Accuracy measureVisibility(const BenchScene& scene, std::vector<float> visibility,
                                             std::vector<float> texelSizes) const;

    /// @brief Shimmer of `settings` on `scene`: the maps are fitted to a view that starts at the camera and
    /// moves a third of the light's first map texel per frame (options().shimmerFrames frames, along a fixed
    /// oblique direction), while the image is drawn from the still camera; the fraction of receiver pixels
    /// whose visibility changes by more than 0.5 from one frame to the next, over all frame pairs. Snapped
    /// (stable) fits give 0: their maps do not change.
    [[nodiscard]] double measureShimmer(const BenchScene& scene,
                                        const shadows::ShadowSettings& settings) const;

    /// @brief Shimmer of `settings` while the camera moves: from the scene's camera it moves 4 % of the
    /// distance to the surface at the image's centre along its right + forward direction and turns 3° right
    /// about the world's up axis, in options().pathFrames equal steps, the maps fitted to each frame's view.
    /// Each frame's receivers are reprojected into the previous frame and compared with the nearest pixel
    /// there when it is a receiver within 1.5 pixel sizes of the same point (otherwise it was hidden or off
    /// the image); the fraction of those whose visibility changes by more than 0.5 while the hard ray-traced
    /// truth's does not, over all frame pairs. The nearest pixel lies up to 0.7 pixels off the point, so
    /// the truth flips where the pair straddles a true shadow edge, and those pairs do not count.
    /// Maps that do not move still score above 0 where a rendered edge lies off the true one, so that the
    /// pair straddles it alone: the coarser the map, the more (on the knob over 8 frames 2.1e-4 with 2048²,
    /// 8e-4 with 256²).
    [[nodiscard]] double measurePathShimmer(const BenchScene& scene,
                                            const shadows::ShadowSettings& settings) const;
    /// @brief The camera walks: it moves along its view direction, level with the ground (world y up), at 1.5
    /// units a second at 30 frames a second (a walker's 1.5 m/s where a unit is a metre), for
    /// BenchOptions::walkFrames frames; fills the result's walk frame times (when timing) and, for virtual
    /// maps, the texels drawn per frame after the first.
    void measureWalk(const BenchScene& scene, const shadows::ShadowSettings& settings,
                     BenchResult& result) const;

    /// @brief The scene drawn without shadows: counts and whole-frame times, and the cost model where
    /// BenchOptions::costModel asks for it.
    [[nodiscard]] SceneCost measureCost(const BenchScene& scene) const;

    /// @brief A row for an OpenSceneGraph peer run: its accuracy against this scene's truth and its frame
    /// times; images written like ours. `texelSizes` should be ours at the same map size (the band's unit).
    BenchResult peerResult(const BenchScene& scene, const struct PeerRun& run,
                           std::vector<float> texelSizes) const;

    [[nodiscard]] engine::TimingMethod timingMethod() const { return method_; }
    [[nodiscard]] const BenchOptions& options() const { return options_; }

private:
    struct PassTimes {
        PassTiming shadow;
        PassTiming lighting;
    };
    /// Milliseconds of each timed frame, over every round.
    struct FrameSamples {
        std::vector<double> shadow;
        std::vector<double> fit; // the shadow pass's parts, where a shadow module times them
        std::vector<double> maps;
        std::vector<double> lighting;
        std::vector<double> frame;
    };
    /// A configuration's engine with its shadow module and the target it draws, kept while a scene's
    /// configurations are timed in turn.
    struct ConfigEngine;
    /// The engine of `config` on `scene`, after a warm-up frame; fills the result's map statistics and shaded
    /// image and writes it.
    std::unique_ptr<ConfigEngine> start(const BenchScene& scene, const BenchConfig& config,
                                        BenchResult& result) const;
    /// What run() measures of a started configuration after its timed rounds: the still frame, the lighting
    /// overhead, accuracy and the optional measurements.
    void finish(const BenchScene& scene, const BenchConfig& config, ConfigEngine& started,
                BenchResult& result) const;
    /// BenchOptions::frames frames of pass times, appended; with `module`, its shadow pass's parts too.
    void samplePasses(engine::Engine& engine, shadows::ShadowModule* module, const BenchScene& scene,
                      engine::RenderTarget& target, FrameSamples& samples) const;
    /// A warm-up frame, BenchOptions::frames frames of pass times, then as many whole frames after another
    /// warm-up frame, appended.
    void sampleFrames(ConfigEngine& started, const BenchScene& scene, FrameSamples& samples) const;
    /// The pre-pass and lighting-pass times of BenchOptions::frames frames of `engine` on `scene`.
    PassTimes passTimes(engine::Engine& engine, const BenchScene& scene, engine::RenderTarget& target) const;
    /// BenchResult::lightingOverhead: `shadowed`'s lighting pass against a new unshadowed engine's,
    /// alternated.
    PassTiming pairedLightingOverhead(engine::Engine& shadowed, const BenchScene& scene,
                                      engine::RenderTarget& target) const;
    /// Rounds of the cost model's alternated timings.
    static constexpr int kCostModelRounds = 5;
    /// The cost model's figures of SceneCost: the unshadowed lighting pass and one fetch's cost.
    void measureFetchCost(const BenchScene& scene, SceneCost& cost) const;

    BenchOptions options_;
    engine::TimingMethod method_;
};

/// @brief Lloyd et al.'s m at each receiver pixel (`surfaces`): the largest extent in pixels of one texel of
/// the finest of `maps` (each `resolution`² texels) holding it, from the texel coordinates' differences to
/// its neighbours on the same surface (the nearer one in texels along each axis, as a derivative that does
/// not cross a silhouette); -1 where no map holds it or it has no such neighbour on an axis. Given `slots`
/// (the map each pixel read, ShadowDebugView::Slot; -1 none), each pixel's own map instead of the finest: a
/// virtual map's level is the finest resident page's, which only the lighting pass knows. With `levels` too
/// (the slot view's blue), a perspective map's pixel reads mip level `levels[i]`, of resolution / 2^level
/// texels a side.
std::vector<float> texelFootprints(glm::ivec2 size, std::span<const glm::vec3> positions,
                                   std::span<const Surface> surfaces,
                                   std::span<const shadows::LightProjection> maps, int resolution,
                                   std::span<const float> slots = {}, std::span<const float> levels = {});

/// @brief Texture reads of the shadow maps per lookup with `settings`: the kernel's taps (jittered: every
/// tap, and a soft technique's search and filter taps: the most an early out leaves), plus the reads of the
/// point gradient (stored: 1; central differences: 4).
[[nodiscard]] int mapReadsPerLookup(const shadows::ShadowSettings& settings);

/// @brief Settings from a `key=value,key=value` list of ShadowSettings JSON fields (values: true/false,
/// numbers, or names), starting from defaults. Throws shadows::SettingsError naming the field.
shadows::ShadowSettings settingsFromAssignments(const std::string& assignments, const std::string& source);

/// @brief Results as CSV, one row per configuration and scene, with a header line.
std::string resultsCsv(const std::vector<BenchResult>& results);
/// @brief Results as JSON, with the renderer, the timing method and each scene's cost.
std::string resultsJson(const std::vector<BenchResult>& results, const std::vector<SceneCost>& costs,
                        const std::string& renderer, const std::string& glVersion,
                        engine::TimingMethod method, const BenchOptions& options);

} // namespace shadowbench
