#include <shadowbench/FetchProbe.h>
#include <shadowbench/PeerRun.h>
#include <shadowbench/ShadowBench.h>

#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>
#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettingsJson.h>
#include <shadows/VisibilityMath.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace shadowbench {

namespace {

std::vector<glm::vec4> renderFloat(engine::Engine& engine, const engine::Scene& scene,
                                   engine::EntityId camera, glm::ivec2 size) {
    engine::RenderTarget target(size, engine::ColorFormat::Rgba32F);
    engine.renderFrame(scene, camera, target);
    const std::vector<float> raw = target.readPixelsFloat();
    std::vector<glm::vec4> pixels(raw.size() / 4);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        pixels[i] = {raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], raw[4 * i + 3]};
    }
    return pixels;
}

/// One whole frame's milliseconds: glFinish + steady clock around it, like gs-render.
double timedFrame(engine::Engine& engine, const engine::Scene& scene, engine::EntityId camera,
                  engine::RenderTarget& target) {
    const auto start = std::chrono::steady_clock::now();
    engine.renderFrame(scene, camera, target);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// Whole frames after one warm-up frame, appended to `times`.
void sampleWholeFrames(engine::Engine& engine, const engine::Scene& scene, engine::EntityId camera,
                       engine::RenderTarget& target, int frames, std::vector<double>& times) {
    engine.renderFrame(scene, camera, target);
    glFinish();
    for (int frame = 0; frame < std::max(frames, 1); ++frame) {
        times.push_back(timedFrame(engine, scene, camera, target));
    }
}

/// Whole frames after one warm-up frame.
PassTiming timeFrames(engine::Engine& engine, const engine::Scene& scene, engine::EntityId camera,
                      engine::RenderTarget& target, int frames) {
    std::vector<double> times;
    sampleWholeFrames(engine, scene, camera, target, frames, times);
    return summariseTimes(times);
}

/// The finest of `maps` holding `position` (orthographic: the map's texel; perspective: its texel scale times
/// the distance along its axis), with that texel's world size; nullopt where none holds it.
std::optional<std::pair<std::size_t, float>> finestMap(std::span<const shadows::LightProjection> maps,
                                                       const glm::vec3& position) {
    std::optional<std::pair<std::size_t, float>> finest;
    for (std::size_t k = 0; k < maps.size(); ++k) {
        const shadows::LightProjection& map = maps[k];
        const glm::vec4 s = map.worldToShadow * glm::vec4(position, 1.0f);
        if (!(s.w > 0.0f)) {
            continue;
        }
        const glm::vec3 coord = glm::vec3(s) / s.w;
        if (coord.x >= 0.0f && coord.x <= 1.0f && coord.y >= 0.0f && coord.y <= 1.0f && coord.z <= 1.0f) {
            const float texel = map.texelScale * (map.perspective ? s.w : 1.0f);
            if (!finest || texel < finest->second) {
                finest = std::pair{k, texel};
            }
        }
    }
    return finest;
}

/// The world size of a shadow texel at each receiver pixel, 0 elsewhere (finestMap).
std::vector<float> receiverTexelSizes(const std::vector<glm::vec3>& positions,
                                      const std::vector<Surface>& surfaces,
                                      const std::vector<shadows::LightProjection>& maps) {
    std::vector<float> sizes(positions.size(), 0.0f);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (surfaces[i] == Surface::Receiver) {
            if (const auto finest = finestMap(maps, positions[i])) {
                sizes[i] = finest->second;
            }
        }
    }
    return sizes;
}

/// A timing's median, least and greatest milliseconds, as results.json gives every timed figure.
nlohmann::json timingJson(const PassTiming& timing) {
    return {{"median", timing.median}, {"min", timing.min}, {"max", timing.max}};
}

nlohmann::json probeMapCosts(const std::vector<ProbeMapCost>& costs) {
    if (costs.empty()) {
        return nlohmann::json();
    }
    nlohmann::json out = nlohmann::json::array();
    for (const ProbeMapCost& cost : costs) {
        out.push_back({{"size", cost.map.size},
                       {"format", shadows::toString(cost.map.format)},
                       {"oneCompareReadOverheadMs", cost.oneCompareReadOverheadMs}});
    }
    return out;
}

} // namespace

PassTiming summariseTimes(std::vector<double> samples) {
    if (samples.empty()) {
        return {};
    }
    std::sort(samples.begin(), samples.end());
    const std::size_t n = samples.size();
    // An even count's median is the mean of its middle two: the upper one alone would lean towards the slower
    // frames, the whole of them where two frames are timed.
    const double median = (samples[(n - 1) / 2] + samples[n / 2]) / 2.0;
    return {median, samples.front(), samples.back(), static_cast<int>(n)};
}

// The eye distance times a pixel's angle for a perspective camera, the view height over the image's for an
// orthographic one.
std::vector<float> BenchScene::viewPixelSizes(const engine::Scene& scene, engine::EntityId camera,
                                              const std::vector<glm::vec3>& positions,
                                              const std::vector<std::uint8_t>& covered, glm::ivec2 size) {
    const engine::CameraComponent& lens = *scene.entity(camera).camera;
    const glm::vec3 eye(scene.worldMatrix(camera)[3]);
    const float rows = static_cast<float>(std::max(size.y, 1));
    std::vector<float> sizes(positions.size(), 0.0f);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (covered[i]) {
            sizes[i] = lens.projection == engine::ProjectionType::Perspective
                           ? glm::length(positions[i] - eye) * 2.0f * std::tan(0.5f * lens.verticalFov) / rows
                           : lens.orthographicHeight / rows;
        }
    }
    return sizes;
}

// Facing the light by the smoothed normal lights the pixel; by the facet, the truth's rays leave from it:
// where the two disagree (the terminator of a smoothed mesh) the surface's own facets shadow it, an attached
// shadow whose edge is neither's to place.
Surface BenchScene::surfaceFacing(const RayTracedVisibility& tracer, const engine::FrameLight& light,
                                  const glm::vec3& position, const glm::vec3& normal) {
    // A sun shines along its direction; spot and point lights from their position.
    const glm::vec3 toLight = light.light.type == engine::LightType::Directional
                                  ? -light.direction
                                  : glm::normalize(light.position - position);
    const bool facing =
        glm::dot(normal, toLight) > 0.05f && glm::dot(tracer.facetNormal(position, normal), toLight) > 0.05f;
    return facing ? Surface::Receiver : Surface::FacingAway;
}

BenchScene::BenchScene(std::string name, engine::Scene scene, engine::EntityId camera,
                       const BenchOptions& options)
    : name_(std::move(name)), scene_(std::move(scene)), camera_(camera) {
    // The G-buffer: where each pixel's surface is and which way it faces, without any module.
    engine::Engine gbuffer;
    gbuffer.renderer().output = engine::OutputMode::WorldPosition;
    const auto positions = renderFloat(gbuffer, scene_, camera_, options.size);
    gbuffer.renderer().output = engine::OutputMode::WorldNormal;
    const auto normals = renderFloat(gbuffer, scene_, camera_, options.size);
    const engine::FrameContext frame =
        gbuffer.renderer().beginFrame(scene_, camera_, engine::FrameTarget{0, options.size}, 0);
    const auto light = std::find_if(frame.lights.begin(), frame.lights.end(),
                                    [](const engine::FrameLight& l) { return l.light.castsShadows; });
    if (light == frame.lights.end()) {
        throw engine::Error("shadowbench: scene '" + name_ + "' has no shadow-casting light");
    }
    light_ = *light;

    std::vector<std::uint8_t> covered(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        positions_.emplace_back(positions[i]);
        normals_.emplace_back(normals[i]);
        covered[i] = positions[i].w > 0.5f;
    }
    concave_ = concaveMask(options.size, positions_, normals_, covered, 0.5f);
    pixelSizes_ = viewPixelSizes(scene_, camera_, positions_, covered, options.size);

    tracer_ = std::make_unique<RayTracedVisibility>(scene_);
    RayTracedVisibility& tracer = *tracer_;
    tracer.setViewer(glm::vec3(scene_.worldMatrix(camera_)[3]));
    surfaces_.resize(positions.size(), Surface::None);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (covered[i]) {
            surfaces_[i] = surfaceFacing(tracer, light_, positions_[i], normals_[i]);
        }
    }
    truth_.resize(positions.size());
    if (options.softSamplesPerAxis > 0) {
        softTruth_.samplesPerAxis = options.softSamplesPerAxis;
        softTruth_.radius = options.softRadius.value_or(RayTracedVisibility::ownRadius(light_));
        tracer.softVisibility(positions_, normals_, covered, light_, softTruth_.radius,
                              softTruth_.samplesPerAxis, truth_);
        // Converged where four times the rays change it little: the RMS difference over the receivers.
        std::vector<float> finer(truth_.size());
        tracer.softVisibility(positions_, normals_, covered, light_, softTruth_.radius,
                              2 * softTruth_.samplesPerAxis, finer);
        double sum = 0.0;
        std::size_t receivers = 0;
        for (std::size_t i = 0; i < truth_.size(); ++i) {
            if (surfaces_[i] == Surface::Receiver) {
                const double difference = static_cast<double>(finer[i]) - truth_[i];
                sum += difference * difference;
                ++receivers;
            }
        }
        softTruth_.convergenceRmse = receivers > 0 ? std::sqrt(sum / static_cast<double>(receivers)) : 0.0;
    } else {
        tracer.hardVisibility(positions_, normals_, covered, light_, truth_);
    }
}

BenchScene::~BenchScene() = default;

ShadowBench::ShadowBench(const engine::GlContext& context, BenchOptions options)
    : ShadowBench(engine::PassTimer::methodFor(context), std::move(options)) {}

ShadowBench::ShadowBench(engine::TimingMethod method, BenchOptions options)
    : options_(std::move(options)), method_(method) {}

std::unique_ptr<BenchScene> ShadowBench::prepare(const std::string& name, const std::filesystem::path& path,
                                                 const std::optional<engine::LightAngles>& light) const {
    content::LoadedScene loaded = content::GltfLoader::load(path);
    const auto camera = loaded.scene.firstCamera();
    if (!camera) {
        throw engine::Error("shadowbench: " + path.string() + " has no camera");
    }
    if (light) {
        std::optional<engine::EntityId> caster;
        loaded.scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
            if (!caster && entity.light && entity.light->castsShadows) {
                caster = id;
            }
        });
        if (!caster) {
            throw engine::Error("shadowbench: " + path.string() + " has no shadow-casting light to point");
        }
        engine::aimLight(loaded.scene, *caster, *light);
    }
    return std::make_unique<BenchScene>(name, std::move(loaded.scene), *camera, options_);
}

struct ShadowBench::ConfigEngine {
    engine::Engine engine;
    shadows::ShadowModule* module = nullptr;
    std::unique_ptr<engine::RenderTarget> target;
};

std::vector<BenchResult> ShadowBench::run(const BenchScene& scene,
                                          std::span<const BenchConfig> configs) const {
    std::vector<BenchResult> results(configs.size());
    if (!options_.timing) { // nothing to alternate: one engine at a time
        for (std::size_t i = 0; i < configs.size(); ++i) {
            finish(scene, configs[i], *start(scene, configs[i], results[i]), results[i]);
        }
        return results;
    }
    std::vector<std::unique_ptr<ConfigEngine>> engines;
    for (std::size_t i = 0; i < configs.size(); ++i) {
        engines.push_back(start(scene, configs[i], results[i]));
    }
    std::vector<FrameSamples> samples(configs.size());
    for (int round = 0; round < std::max(options_.rounds, 1); ++round) {
        for (std::size_t i = 0; i < configs.size(); ++i) {
            sampleFrames(*engines[i], scene, samples[i]);
        }
    }
    for (std::size_t i = 0; i < configs.size(); ++i) {
        results[i].shadowPass = summariseTimes(samples[i].shadow);
        results[i].fitPart = summariseTimes(samples[i].fit);
        results[i].mapsPart = summariseTimes(samples[i].maps);
        results[i].lightingPass = summariseTimes(samples[i].lighting);
        results[i].frame = summariseTimes(samples[i].frame);
        finish(scene, configs[i], *engines[i], results[i]);
        engines[i].reset(); // its maps and meshes are not needed again
    }
    return results;
}

BenchResult ShadowBench::run(const BenchScene& scene, const BenchConfig& config) const {
    return std::move(run(scene, std::span<const BenchConfig>(&config, 1)).front());
}

std::unique_ptr<ShadowBench::ConfigEngine>
ShadowBench::start(const BenchScene& scene, const BenchConfig& config, BenchResult& result) const {
    result.scene = scene.name();
    result.config = config;
    auto started = std::make_unique<ConfigEngine>();
    // Every timed frame draws its maps, as a moving view's do; the still view's frames are timed apart.
    shadows::ShadowSettings redrawing = config.settings;
    redrawing.reuseUnchangedMaps = false;
    started->module = &static_cast<shadows::ShadowModule&>(
        started->engine.addModule(std::make_unique<shadows::ShadowModule>(redrawing)));
    const shadows::ShadowModule& module = *started->module;

    // Timing: shaded frames, both passes, after a warm-up frame that compiles and uploads.
    started->target = std::make_unique<engine::RenderTarget>(options_.size);
    engine::RenderTarget& shaded = *started->target;
    started->engine.renderFrame(scene.scene_, scene.camera_, shaded);
    result.shadowBytes = module.stats().bytes;
    result.mapResolution = module.stats().mapResolution;
    result.casterTexels = module.stats().casterTexels;
    result.shadowMaps = module.stats().shadowMaps;
    result.virtualMaps = module.stats().virtualMaps;
    if (result.virtualMaps) {
        result.coldPages = module.stats().pages;
        started->engine.renderFrame(scene.scene_, scene.camera_, shaded);
        result.warmPages = module.stats().pages;
    }
    const std::filesystem::path folder = options_.imageFolder / scene.name();
    result.shadedImage = folder / (config.label + ".png");
    result.shaded = shaded.readPixels();
    engine::writePng(result.shadedImage, result.shaded);
    if (!options_.timing) {
        result.frame = result.shadowPass = result.lightingPass = {-1.0, -1.0, -1.0};
    }
    return started;
}

void ShadowBench::finish(const BenchScene& scene, const BenchConfig& config, ConfigEngine& started,
                         BenchResult& result) const {
    engine::Engine& engine = started.engine;
    shadows::ShadowModule& module = *started.module;
    engine::RenderTarget& shaded = *started.target;
    const std::filesystem::path folder = options_.imageFolder / scene.name();
    if (options_.timing) {
        if (options_.costModel) {
            result.lightingOverhead = pairedLightingOverhead(engine, scene, shaded);
        }
        shadows::ShadowSettings keeping = config.settings;
        keeping.reuseUnchangedMaps = true;
        module.setSettings(keeping);
        engine.renderFrame(scene.scene_, scene.camera_, shaded); // draws the maps the still frames keep
        result.stillFrame = timeFrames(engine, scene.scene_, scene.camera_, shaded, options_.frames);
        result.stillFrameKeptMaps = module.stats().reusedMaps;
    }

    const Accuracy accuracy = measure(scene, config.settings);
    result.metrics = accuracy.metrics;
    result.soft = accuracy.soft;
    engine::writePng(folder / (config.label + "-classes.png"),
                     classificationImage(options_.size, accuracy.classes, accuracy.visibility));
    engine::writePng(folder / (config.label + "-error.png"),
                     errorHeatMap(options_.size, accuracy.classes, accuracy.truth, accuracy.visibility));
    if (config.settings.technique == shadows::ShadowTechnique::JitteredPcf &&
        config.settings.earlyOutTestTaps > 0) {
        shadows::ShadowSettings kernelView = config.settings;
        kernelView.debugView = shadows::ShadowDebugView::FullKernel;
        module.setSettings(kernelView);
        std::size_t covered = 0;
        std::size_t full = 0;
        for (const glm::vec4& pixel : renderFloat(engine, scene.scene_, scene.camera_, options_.size)) {
            covered += pixel.w > 0.5f;
            full += pixel.w > 0.5f && pixel.x > 0.5f;
        }
        result.fullKernelFraction = covered ? static_cast<double>(full) / static_cast<double>(covered) : 0.0;
    }
    if (options_.shimmerFrames > 0) {
        result.shimmer = measureShimmer(scene, config.settings);
    }
    if (options_.pathFrames > 0) {
        result.pathShimmer = measurePathShimmer(scene, config.settings);
    }
    if (options_.walkFrames > 0 && (options_.timing || result.virtualMaps)) { // else it would measure nothing
        measureWalk(scene, config.settings, result);
    }
}

void ShadowBench::measureWalk(const BenchScene& scene, const shadows::ShadowSettings& settings,
                              BenchResult& result) const {
    constexpr float kStepPerFrame = 1.5f / 30.0f;
    engine::Scene moving = scene.scene_;
    moving.setParent(scene.camera_, engine::kNoEntity);
    const glm::mat4 start = scene.scene_.worldMatrix(scene.camera_);
    const glm::vec3 scale(glm::length(glm::vec3(start[0])), glm::length(glm::vec3(start[1])),
                          glm::length(glm::vec3(start[2])));
    engine::Transform pose;
    pose.rotation = glm::quat_cast(glm::mat3(glm::vec3(start[0]) / scale.x, glm::vec3(start[1]) / scale.y,
                                             glm::vec3(start[2]) / scale.z));
    pose.scale = scale;
    glm::vec3 forward = -glm::vec3(start[2]);
    forward.y = 0.0f;
    forward = glm::length(forward) > 1e-6f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, -1.0f);
    engine::Engine engine;
    auto& module = static_cast<shadows::ShadowModule&>(
        engine.addModule(std::make_unique<shadows::ShadowModule>(settings)));
    engine::RenderTarget target(options_.size);
    double sum = 0.0;
    double largest = 0.0;
    int kept = 0;
    std::vector<double> times;
    for (int frame = 0; frame <= options_.walkFrames; ++frame) {
        pose.translation = glm::vec3(start[3]) + forward * (kStepPerFrame * static_cast<float>(frame));
        moving.entity(scene.camera_).transform = pose;
        // The first frame, cold (programs compiled, every page drawn), is the walk's start, not timed.
        const double milliseconds = timedFrame(engine, moving, scene.camera_, target);
        if (frame > 0) {
            times.push_back(milliseconds);
            const auto texels = static_cast<double>(module.stats().pages.texelsRendered);
            sum += texels;
            largest = std::max(largest, texels);
            kept += module.stats().keptMaps ? 1 : 0;
        }
    }
    result.walkKeptFrames = kept;
    if (options_.timing && !times.empty()) {
        result.walkFrame = summariseTimes(times);
    }
    if (result.virtualMaps) {
        result.walkTexelsPerFrame = sum / static_cast<double>(options_.walkFrames);
        result.walkTexelsPerFrameMax = largest;
    }
}

PassTiming ShadowBench::pairedLightingOverhead(engine::Engine& shadowed, const BenchScene& scene,
                                               engine::RenderTarget& target) const {
    engine::Engine unshadowed;
    unshadowed.renderFrame(scene.scene_, scene.camera_, target); // compiles and uploads
    // Each round's fastest frames: the machine's noise only ever adds time.
    std::vector<double> differences;
    for (int round = 0; round < kCostModelRounds; ++round) {
        const double base = passTimes(unshadowed, scene, target).lighting.min;
        differences.push_back(passTimes(shadowed, scene, target).lighting.min - base);
    }
    return summariseTimes(differences);
}

ShadowBench::PassTimes ShadowBench::passTimes(engine::Engine& engine, const BenchScene& scene,
                                              engine::RenderTarget& target) const {
    FrameSamples samples;
    samplePasses(engine, nullptr, scene, target, samples);
    return {summariseTimes(samples.shadow), summariseTimes(samples.lighting)};
}

void ShadowBench::samplePasses(engine::Engine& engine, shadows::ShadowModule* module, const BenchScene& scene,
                               engine::RenderTarget& target, FrameSamples& samples) const {
    engine.setPassTiming(method_);
    if (module) {
        module->setPartTiming(method_);
    }
    for (int frame = 0; frame < std::max(options_.frames, 1); ++frame) {
        const engine::FrameStats stats = engine.renderFrame(scene.scene_, scene.camera_, target);
        samples.shadow.push_back(stats.prePassMilliseconds);
        samples.lighting.push_back(stats.lightingMilliseconds);
        if (module) {
            const shadows::ShadowStats parts = module->stats();
            samples.fit.push_back(parts.fitMilliseconds);
            samples.maps.push_back(parts.mapsMilliseconds);
        }
    }
    engine.setPassTiming(std::nullopt);
    if (module) {
        module->setPartTiming(std::nullopt);
    }
}

void ShadowBench::sampleFrames(ConfigEngine& started, const BenchScene& scene, FrameSamples& samples) const {
    // A warm-up frame: the configuration timed before this one left the caches holding its own data.
    started.engine.renderFrame(scene.scene_, scene.camera_, *started.target);
    samplePasses(started.engine, started.module, scene, *started.target, samples);
    sampleWholeFrames(started.engine, scene.scene_, scene.camera_, *started.target, options_.frames,
                      samples.frame);
}

Accuracy ShadowBench::measure(const BenchScene& scene, const shadows::ShadowSettings& settings) const {
    engine::Engine engine;
    shadows::ShadowSettings visibilityOnly = settings;
    visibilityOnly.debugView = shadows::ShadowDebugView::Visibility;
    auto& module = static_cast<shadows::ShadowModule&>(
        engine.addModule(std::make_unique<shadows::ShadowModule>(visibilityOnly)));
    const auto pixels = renderFloat(engine, scene.scene_, scene.camera_, options_.size);
    std::vector<float> visibility(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        visibility[i] = pixels[i].x;
    }
    // A texel band is measured in the texels of the finest map holding each receiver (a light's cascades and
    // cube faces differ).
    const std::vector<shadows::LightProjection> maps = module.lightProjections(scene.light_.index);
    Accuracy accuracy = measureVisibility(scene, std::move(visibility),
                                          receiverTexelSizes(scene.positions_, scene.surfaces_, maps));
    const auto slotImage = [&] {
        engine::Engine slotEngine;
        shadows::ShadowSettings slotView = settings;
        slotView.debugView = shadows::ShadowDebugView::Slot;
        slotEngine.addModule(std::make_unique<shadows::ShadowModule>(slotView));
        return renderFloat(slotEngine, scene.scene_, scene.camera_, options_.size);
    };
    if (settings.mapAllocation == shadows::MapAllocation::Virtual) {
        // Each pixel's clipmap level is the finest resident page's over it: read which one it used.
        const auto read = slotImage();
        std::vector<float> slots(read.size());
        std::vector<float> pageEdges(read.size());
        std::vector<float> levels(read.size());
        for (std::size_t i = 0; i < read.size(); ++i) {
            slots[i] = read[i].x;
            pageEdges[i] = read[i].y;
            levels[i] = read[i].z;
        }
        accuracy.metrics.seams = seamErrors(
            accuracy.classes, accuracy.truth, accuracy.visibility, pageEdges,
            static_cast<float>(shadows::virtualPageBorderTexels(shadows::ShadowPlan::resolve(settings))));
        accuracy.footprints = texelFootprints(options_.size, scene.positions_, scene.surfaces_, maps,
                                              shadows::kVirtualResolution, slots, levels);
        if (accuracy.soft) {
            seamWidthJumps(options_.size, slots, *accuracy.soft); // clipmap levels' seams
        }
    } else {
        accuracy.footprints = texelFootprints(options_.size, scene.positions_, scene.surfaces_, maps,
                                              module.stats().mapResolution);
        if (accuracy.soft && maps.size() > 1) {
            // Cascades' (and cube faces') seams: where a penumbra crosses from one map to the next.
            const auto read = slotImage();
            std::vector<float> slots(read.size());
            for (std::size_t i = 0; i < read.size(); ++i) {
                slots[i] = read[i].x;
            }
            seamWidthJumps(options_.size, slots, *accuracy.soft);
        }
    }
    accuracy.metrics.density = texelDensity(accuracy.classes, accuracy.truth, accuracy.footprints);
    return accuracy;
}

Accuracy ShadowBench::measureVisibility(const BenchScene& scene, std::vector<float> visibility,
                                        std::vector<float> texelSizes) const {
    if (visibility.size() != scene.truth_.size()) {
        throw engine::Error("shadowbench: a visibility image of " + std::to_string(visibility.size()) +
                            " pixels for scene '" + scene.name() + "' of " +
                            std::to_string(scene.truth_.size()));
    }
    Accuracy accuracy;
    accuracy.truth = scene.truth_;
    accuracy.visibility = std::move(visibility);
    accuracy.texelSizes = std::move(texelSizes);
    LightPlane plane;
    plane.positions = scene.positions_;
    plane.texelSizes = accuracy.texelSizes;
    plane.directional = scene.light_.light.type == engine::LightType::Directional;
    plane.direction = scene.light_.direction;
    plane.position = scene.light_.position;
    // A pixel band does not depend on the maps: one classification per scene.
    const bool texelBand = options_.bandUnit == BandUnit::Texels;
    if (scene.classes_.empty() || (texelBand && scene.classifiedTexelSizes_ != accuracy.texelSizes)) {
        std::vector<float> reach(scene.truth_.size(), 0.0f);
        std::vector<std::uint8_t> lit(scene.truth_.size(), 0);
        for (std::size_t i = 0; i < reach.size(); ++i) {
            if (scene.surfaces_[i] == Surface::Receiver) {
                reach[i] = options_.bandWidth * (texelBand ? accuracy.texelSizes[i] : scene.pixelSizes_[i]);
                lit[i] = static_cast<std::uint8_t>(scene.truth_[i] >= 0.5f);
            }
        }
        std::vector<std::uint8_t> edgeWithinBand(reach.size());
        scene.tracer_->edgeWithin(scene.positions_, scene.normals_, reach, lit, scene.light_, edgeWithinBand);
        plane.edgeWithinBand = edgeWithinBand;
        scene.classes_ =
            texelBand ? classify(options_.size, scene.truth_, scene.surfaces_, plane, options_.bandWidth)
                      : classifyByScreenBand(options_.size, scene.truth_, scene.surfaces_, options_.bandWidth,
                                             edgeWithinBand);
        scene.classifiedTexelSizes_ = accuracy.texelSizes;
    }
    accuracy.classes = scene.classes_;
    accuracy.metrics = computeMetrics(accuracy.classes, scene.truth_, accuracy.visibility, scene.concave_);
    accuracy.metrics.edges =
        edgePlacement(options_.size, accuracy.classes, scene.truth_, accuracy.visibility);
    if (scene.softTruth_.samplesPerAxis > 0) {
        accuracy.soft = softShadowMetrics(options_.size, accuracy.classes, scene.truth_, accuracy.visibility);
    }
    return accuracy;
}

SceneCost ShadowBench::measureCost(const BenchScene& scene) const {
    SceneCost cost;
    cost.scene = scene.name();
    cost.softTruth = scene.softTruth();
    engine::Engine engine;
    engine::RenderTarget target(options_.size);
    const engine::FrameStats stats = engine.renderFrame(scene.scene_, scene.camera_, target);
    cost.drawCalls = stats.drawCalls;
    cost.culledChunks = stats.culledChunks;
    cost.meshBytes = engine.renderer().meshBytes();
    scene.scene_.forEach([&](engine::EntityId, const engine::Entity& entity) {
        cost.triangles += entity.mesh && entity.mesh->mesh ? entity.mesh->mesh->triangleCount() : 0;
    });
    cost.unshadowedFrame = options_.timing
                               ? timeFrames(engine, scene.scene_, scene.camera_, target, options_.frames)
                               : PassTiming{-1.0, -1.0, -1.0};
    if (options_.timing && options_.costModel) {
        measureFetchCost(scene, cost);
    }
    return cost;
}

void ShadowBench::measureFetchCost(const BenchScene& scene, SceneCost& cost) const {
    engine::RenderTarget target(options_.size);
    // The probe reads where the default technique's first map would: the same texels per pixel.
    glm::mat4 worldToMap(1.0f);
    {
        engine::Engine engine;
        auto& module =
            static_cast<shadows::ShadowModule&>(engine.addModule(std::make_unique<shadows::ShadowModule>()));
        engine.renderFrame(scene.scene_, scene.camera_, target);
        if (const auto projection = module.lightProjection(scene.light_.index)) {
            worldToMap = projection->worldToShadow;
        }
    }
    // Each configuration's fastest frame, as the techniques' overheads take them (pairedLightingOverhead).
    const auto lightingPass = [&](engine::Engine& engine) {
        // Warm-up: a probe count's first draw compiles its program.
        engine.renderFrame(scene.scene_, scene.camera_, target);
        return passTimes(engine, scene, target).lighting;
    };
    engine::Engine unshadowed;
    engine::Engine filtered;
    engine::Engine compare;
    auto& filteredProbe = static_cast<FetchProbe&>(
        filtered.addModule(std::make_unique<FetchProbe>(FetchKind::Filtered, 1, worldToMap)));
    auto& compareProbe = static_cast<FetchProbe&>(
        compare.addModule(std::make_unique<FetchProbe>(FetchKind::Compare, 1, worldToMap)));
    std::vector<std::unique_ptr<engine::Engine>> otherMaps;
    for (const ProbeMap& map : FetchProbe::kOtherMaps) {
        otherMaps.push_back(std::make_unique<engine::Engine>());
        otherMaps.back()->addModule(std::make_unique<FetchProbe>(FetchKind::Compare, 1, worldToMap, map));
    }
    // Rounds alternate every configuration, so a drift of the machine's speed spreads over all of them; each
    // count's figure is its median over the rounds.
    std::vector<double> base;
    std::map<int, std::vector<double>> filteredTimes;
    std::map<int, std::vector<double>> compareTimes;
    std::vector<std::vector<double>> otherMapOverheads(otherMaps.size());
    for (int round = 0; round < kCostModelRounds; ++round) {
        base.push_back(lightingPass(unshadowed).min);
        for (const int fetches : FetchProbe::kCounts) {
            filteredProbe.setFetches(fetches);
            filteredTimes[fetches].push_back(lightingPass(filtered).min);
            compareProbe.setFetches(fetches);
            compareTimes[fetches].push_back(lightingPass(compare).min);
        }
        for (std::size_t m = 0; m < otherMaps.size(); ++m) {
            otherMapOverheads[m].push_back(lightingPass(*otherMaps[m]).min - base.back());
        }
    }
    cost.unshadowedLighting = summariseTimes(base);
    std::vector<double> oneReadOverheads;
    for (std::size_t round = 0; round < base.size(); ++round) {
        oneReadOverheads.push_back(compareTimes[1][round] - base[round]);
    }
    cost.oneCompareReadOverheadMs = summariseTimes(oneReadOverheads).median;
    for (std::size_t m = 0; m < otherMaps.size(); ++m) {
        cost.oneCompareReadByMap.push_back(
            {FetchProbe::kOtherMaps[m], summariseTimes(otherMapOverheads[m]).median});
    }
    // Least squares over the counts: the slope is one fetch's cost, the intercept the probe's fixed code.
    const auto slope = [](const std::map<int, std::vector<double>>& times) {
        double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
        for (const auto& [fetches, samples] : times) {
            const double x = fetches;
            const double y = summariseTimes(samples).median;
            n += 1.0;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        const double denominator = n * sxx - sx * sx;
        return denominator > 0.0 ? (n * sxy - sx * sy) / denominator : -1.0;
    };
    cost.filteredFetchMs = slope(filteredTimes);
    cost.compareFetchMs = slope(compareTimes);
}

BenchResult ShadowBench::peerResult(const BenchScene& scene, const PeerRun& run,
                                    std::vector<float> texelSizes) const {
    BenchResult result;
    result.scene = scene.name();
    result.config.label = "osg-" + run.technique;
    result.config.settings.resolution = run.mapSize;
    result.peerClass = run.osgClass;
    result.frame = run.shadowed;
    result.shadowPass = {-1.0, -1.0, -1.0}; // the peer times whole frames only
    result.lightingPass = {-1.0, -1.0, -1.0};
    std::vector<float> visibility = run.visibility;
    for (std::size_t i = 0; i < visibility.size(); ++i) {
        if (visibility[i] < 0.0f) {
            result.peerUnlitReceivers += scene.surfaces_[i] == Surface::Receiver;
            visibility[i] = 1.0f;
        }
    }
    const Accuracy accuracy = measureVisibility(scene, std::move(visibility), std::move(texelSizes));
    result.metrics = accuracy.metrics;
    result.soft = accuracy.soft;
    const std::filesystem::path folder = options_.imageFolder / scene.name();
    engine::writePng(folder / (result.config.label + "-classes.png"),
                     classificationImage(options_.size, accuracy.classes, accuracy.visibility));
    engine::writePng(folder / (result.config.label + "-error.png"),
                     errorHeatMap(options_.size, accuracy.classes, accuracy.truth, accuracy.visibility));
    return result;
}

int mapReadsPerLookup(const shadows::ShadowSettings& settings) {
    const shadows::ShadowPlan plan = shadows::ShadowPlan::resolve(settings);
    int reads = 1;
    if (plan.traits->jittered) {
        reads = settings.jitterTaps;
    } else if (plan.sampler == shadows::MapSampler::MomentMips) {
        reads = shadows::kMomentSoftFetches;
    } else if (plan.traits->softReachTexels) {
        reads = shadows::kPcssSearchTaps + shadows::kPcssFilterTaps;
    } else if (plan.usesTapPattern) {
        reads = static_cast<int>(settings.tapPattern().offsets.size());
    }
    if (plan.readsPointGradient) {
        reads += settings.gradientSource == shadows::GradientSource::StoredDerivatives    ? 1
                 : settings.gradientSource == shadows::GradientSource::CentralDifferences ? 4
                                                                                          : 0;
    }
    return reads;
}

std::string_view toString(BandUnit unit) {
    return unit == BandUnit::Pixels ? "pixels" : "texels";
}

std::vector<float> texelFootprints(glm::ivec2 size, std::span<const glm::vec3> positions,
                                   std::span<const Surface> surfaces,
                                   std::span<const shadows::LightProjection> maps, int resolution,
                                   std::span<const float> slots, std::span<const float> levels) {
    std::vector<float> footprints(positions.size(), -1.0f);
    const auto index = [&](int x, int y) {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
    };
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = index(x, y);
            if (surfaces[i] != Surface::Receiver) {
                continue;
            }
            std::size_t map = 0;
            if (slots.empty()) {
                const auto finest = finestMap(maps, positions[i]);
                if (!finest) {
                    continue;
                }
                map = finest->first;
            } else {
                const float slot = slots[i];
                if (!(slot >= 0.0f && slot < static_cast<float>(maps.size()))) {
                    continue;
                }
                map = static_cast<std::size_t>(slot);
            }
            const glm::mat4& toShadow = maps[map].worldToShadow;
            float texels = static_cast<float>(resolution);
            if (!levels.empty() && maps[map].perspective && levels[i] > 0.0f && levels[i] < 32.0f) {
                texels = std::ldexp(texels, -static_cast<int>(levels[i]));
            }
            const auto texelAt = [&](std::size_t j) -> std::optional<glm::vec2> {
                const glm::vec4 s = toShadow * glm::vec4(positions[j], 1.0f);
                if (surfaces[j] == Surface::None || !(s.w > 0.0f)) {
                    return std::nullopt;
                }
                return glm::vec2(s) / s.w * texels;
            };
            const glm::vec2 centre = *texelAt(i);
            // The one-sided difference towards the nearer neighbour in texels: the other may lie across a
            // silhouette, on another surface.
            const auto derivative = [&](glm::ivec2 step) -> std::optional<glm::vec2> {
                std::optional<glm::vec2> best;
                for (const int sign : {1, -1}) {
                    const glm::ivec2 n = glm::ivec2(x, y) + sign * step;
                    if (n.x < 0 || n.y < 0 || n.x >= size.x || n.y >= size.y) {
                        continue;
                    }
                    if (const auto t = texelAt(index(n.x, n.y))) {
                        const glm::vec2 d = static_cast<float>(sign) * (*t - centre);
                        if (!best || glm::length(d) < glm::length(*best)) {
                            best = d;
                        }
                    }
                }
                return best;
            };
            const auto dx = derivative({1, 0});
            const auto dy = derivative({0, 1});
            if (dx && dy) {
                footprints[i] = shadows::glsl::gsTexelFootprintPixels(*dx, *dy);
            }
        }
    }
    return footprints;
}

shadows::ShadowSettings settingsFromAssignments(const std::string& assignments, const std::string& source) {
    nlohmann::json document = nlohmann::json::object();
    std::istringstream list(assignments);
    for (std::string item; std::getline(list, item, ',');) {
        const auto equals = item.find('=');
        if (equals == std::string::npos || equals == 0) {
            throw shadows::SettingsError(source + ": '" + item + "' is not key=value");
        }
        const std::string key = item.substr(0, equals);
        const std::string value = item.substr(equals + 1);
        if (value == "true" || value == "false") {
            document[key] = value == "true";
            continue;
        }
        std::size_t used = 0;
        try {
            const double number = std::stod(value, &used);
            if (used == value.size()) {
                const bool integral = value.find_first_of(".eE") == std::string::npos;
                document[key] =
                    integral ? nlohmann::json(static_cast<long long>(number)) : nlohmann::json(number);
                continue;
            }
        } catch (const std::exception&) {
        }
        document[key] = value;
    }
    return shadows::settingsFromJson(document.dump(), source);
}

std::string resultsCsv(const std::vector<BenchResult>& results) {
    std::ostringstream csv;
    csv << "scene,label,technique,layout,taps,radius,resolution,format,acne_rate,leak_rate,darkening,"
           "concave_darkening,mae,rmse,receivers,lit,shadowed,band,concave,shadow_ms_median,"
           "shadow_ms_min,shadow_ms_max,lighting_ms_median,lighting_ms_min,lighting_ms_max,shadow_bytes,"
           "full_kernel_fraction,frame_ms_median,peer,edge_true_to_rendered_mean,edge_true_to_rendered_p95,"
           "edge_rendered_to_true_mean,edge_rendered_to_true_p95,true_edge_pixels,rendered_edge_pixels,"
           "shimmer,density_pixels,density_m_at_most_1,density_m_p50,density_m_p99,path_shimmer\n";
    for (const BenchResult& r : results) {
        const shadows::ShadowSettings& s = r.config.settings;
        const ShadowMetrics& m = r.metrics;
        csv << r.scene << ',' << r.config.label << ',' << shadows::toString(s.technique) << ','
            << shadows::toString(s.pcfLayout) << ',' << s.pcfTaps << ',' << s.pcfRadius << ',' << s.resolution
            << ',' << shadows::toString(s.depthFormat) << ',' << m.acneRate << ',' << m.leakRate << ','
            << m.darkening << ',' << m.concaveDarkening << ',' << m.meanAbsoluteError << ','
            << m.rootMeanSquareError << ',' << m.receivers << ',' << m.lit << ',' << m.shadowed << ','
            << m.band << ',' << m.concave << ',' << r.shadowPass.median << ',' << r.shadowPass.min << ','
            << r.shadowPass.max << ',' << r.lightingPass.median << ',' << r.lightingPass.min << ','
            << r.lightingPass.max << ',' << r.shadowBytes << ',' << r.fullKernelFraction << ','
            << r.frame.median << ',' << r.peerClass << ',' << m.edges.trueToRendered.mean << ','
            << m.edges.trueToRendered.percentile95 << ',' << m.edges.renderedToTrue.mean << ','
            << m.edges.renderedToTrue.percentile95 << ',' << m.edges.trueToRendered.count << ','
            << m.edges.renderedToTrue.count << ',' << r.shimmer << ',' << m.density.pixels << ','
            << m.density.atMostOnePixel << ',' << m.density.median << ',' << m.density.percentile99 << ','
            << r.pathShimmer << '\n';
    }
    return csv.str();
}

std::string resultsJson(const std::vector<BenchResult>& results, const std::vector<SceneCost>& costs,
                        const std::string& renderer, const std::string& glVersion,
                        engine::TimingMethod method, const BenchOptions& options) {
    nlohmann::json document;
    document["renderer"] = renderer;
    document["glVersion"] = glVersion;
    document["timingMethod"] = std::string(engine::PassTimer::describe(method));
    document["width"] = options.size.x;
    document["height"] = options.size.y;
    document["frames"] = options.frames;
    document["rounds"] = options.rounds;
    document["band"] = {{"width", options.bandWidth}, {"unit", std::string(toString(options.bandUnit))}};
    document["shimmerFrames"] = options.shimmerFrames;
    document["pathFrames"] = options.pathFrames;
    document["walkFrames"] = options.walkFrames;
    document["groundTruth"] = options.softSamplesPerAxis > 0 ? "soft" : "hard";
    document["defaultTechnique"] = std::string(shadows::toString(shadows::ShadowSettings{}.technique));
    nlohmann::json list = nlohmann::json::array();
    for (const BenchResult& r : results) {
        const ShadowMetrics& m = r.metrics;
        list.push_back(
            {{"scene", r.scene},
             {"label", r.config.label},
             {"settings", nlohmann::json::parse(shadows::settingsToJson(r.config.settings))},
             {"acneRate", m.acneRate},
             {"leakRate", m.leakRate},
             {"darkening", m.darkening},
             {"concaveDarkening", m.concaveDarkening},
             {"mae", m.meanAbsoluteError},
             {"rmse", m.rootMeanSquareError},
             {"soft", !r.soft ? nlohmann::json()
                              : nlohmann::json({{"penumbraPixels", r.soft->penumbraPixels},
                                                {"penumbraRmse", r.soft->penumbraRmse},
                                                {"penumbraMae", r.soft->penumbraMae},
                                                {"umbraPixels", r.soft->umbraPixels},
                                                {"falseLit", r.soft->falseLit},
                                                {"litPixels", r.soft->litPixels},
                                                {"falseShadow", r.soft->falseShadow},
                                                {"widthSamples", r.soft->widthSamples},
                                                {"widthMissing", r.soft->widthMissing},
                                                {"widthErrorMedian", r.soft->widthErrorMedian},
                                                {"widthErrorP95", r.soft->widthErrorP95},
                                                {"widthRatioMedian", r.soft->widthRatioMedian},
                                                {"seamPairs", r.soft->seamPairs},
                                                {"seamJumpMedian", r.soft->seamJumpMedian},
                                                {"seamJumpMax", r.soft->seamJumpMax}})},
             {"pixels",
              {{"receivers", m.receivers},
               {"lit", m.lit},
               {"shadowed", m.shadowed},
               {"band", m.band},
               {"concave", m.concave},
               {"acne", m.acne},
               {"leak", m.leak}}},
             {"edges",
              {{"trueToRendered",
                {{"pixels", m.edges.trueToRendered.count},
                 {"mean", m.edges.trueToRendered.mean},
                 {"p95", m.edges.trueToRendered.percentile95}}},
               {"renderedToTrue",
                {{"pixels", m.edges.renderedToTrue.count},
                 {"mean", m.edges.renderedToTrue.mean},
                 {"p95", m.edges.renderedToTrue.percentile95}}}}},
             {"density", m.density.pixels == 0 ? nlohmann::json()
                                               : nlohmann::json({{"pixels", m.density.pixels},
                                                                 {"atMostOnePixel", m.density.atMostOnePixel},
                                                                 {"median", m.density.median},
                                                                 {"p99", m.density.percentile99},
                                                                 {"p999", m.density.percentile999}})},
             {"seams", m.seams.pixels + m.seams.interiorPixels == 0
                           ? nlohmann::json()
                           : nlohmann::json({{"pixels", m.seams.pixels},
                                             {"errorRate", m.seams.errorRate},
                                             {"interiorPixels", m.seams.interiorPixels},
                                             {"interiorErrorRate", m.seams.interiorErrorRate}})},
             {"pages", !r.virtualMaps ? nlohmann::json()
                                      : nlohmann::json({{"coldRequested", r.coldPages.requested},
                                                        {"coldRendered", r.coldPages.rendered},
                                                        {"coldTexels", r.coldPages.texelsRendered},
                                                        {"coarsened", r.coldPages.coarsened},
                                                        {"refused", r.coldPages.refused},
                                                        {"poolPages", r.coldPages.poolPages},
                                                        {"warmRendered", r.warmPages.rendered},
                                                        {"walkTexelsPerFrame", r.walkTexelsPerFrame},
                                                        {"walkTexelsPerFrameMax", r.walkTexelsPerFrameMax}})},
             {"shadowPassMs", timingJson(r.shadowPass)},
             {"shadowFitMs", timingJson(r.fitPart)},
             {"shadowMapsMs", timingJson(r.mapsPart)},
             {"lightingPassMs", timingJson(r.lightingPass)},
             {"lightingOverheadMs", r.lightingOverhead ? timingJson(*r.lightingOverhead) : nlohmann::json()},
             {"frameMs",
              {{"median", r.frame.median},
               {"min", r.frame.min},
               {"max", r.frame.max},
               {"samples", r.frame.samples}}},
             {"stillFrameMs", timingJson(r.stillFrame)},
             {"stillFrameKeptMaps", r.stillFrameKeptMaps},
             {"walkFrameMs", r.walkFrame.median < 0.0 ? nlohmann::json() : timingJson(r.walkFrame)},
             {"walkKeptFrames", r.walkKeptFrames < 0 ? nlohmann::json() : nlohmann::json(r.walkKeptFrames)},
             {"peer", r.peerClass.empty() ? nlohmann::json() : nlohmann::json(r.peerClass)},
             {"naive", r.peerClass.empty() && shadows::traitsOf(r.config.settings.technique).naive},
             {"peerUnlitReceivers", r.peerUnlitReceivers},
             {"shadowBytes", r.shadowBytes},
             {"mapResolution", r.mapResolution},
             {"casterTexels", r.casterTexels},
             {"mapReads", mapReadsPerLookup(r.config.settings)},
             {"fullKernelFraction", r.fullKernelFraction},
             {"shimmer", r.shimmer},
             {"pathShimmer", r.pathShimmer},
             {"shadowMaps", r.shadowMaps},
             {"image", r.shadedImage.string()}});
    }
    document["results"] = list;
    nlohmann::json sceneCosts = nlohmann::json::array();
    for (const SceneCost& c : costs) {
        sceneCosts.push_back(
            {{"scene", c.scene},
             {"triangles", c.triangles},
             {"drawCalls", c.drawCalls},
             {"culledChunks", c.culledChunks},
             {"meshBytes", c.meshBytes},
             {"unshadowedFrameMs", timingJson(c.unshadowedFrame)},
             {"unshadowedLightingMs",
              c.unshadowedLighting.median < 0.0 ? nlohmann::json() : timingJson(c.unshadowedLighting)},
             {"filteredFetchMs",
              c.filteredFetchMs < 0.0 ? nlohmann::json() : nlohmann::json(c.filteredFetchMs)},
             {"compareFetchMs", c.compareFetchMs < 0.0 ? nlohmann::json() : nlohmann::json(c.compareFetchMs)},
             {"oneCompareReadOverheadMs",
              c.oneCompareReadOverheadMs ? nlohmann::json(*c.oneCompareReadOverheadMs) : nlohmann::json()},
             {"oneCompareReadByMap", probeMapCosts(c.oneCompareReadByMap)},
             {"softTruth", c.softTruth.samplesPerAxis == 0
                               ? nlohmann::json()
                               : nlohmann::json({{"samplesPerAxis", c.softTruth.samplesPerAxis},
                                                 {"radius", c.softTruth.radius},
                                                 {"convergenceRmse", c.softTruth.convergenceRmse}})},
             {"peerUnshadowedFrameMs",
              c.peerUnshadowedFrame.median < 0.0 ? nlohmann::json() : timingJson(c.peerUnshadowedFrame)},
             {"peerAllocatorTuned",
              c.peerAllocatorTuned ? nlohmann::json(*c.peerAllocatorTuned) : nlohmann::json()}});
    }
    document["scenes"] = sceneCosts;
    return document.dump(2) + "\n";
}

} // namespace shadowbench
