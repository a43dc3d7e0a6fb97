#include <shadowbench/ShadowBench.h>

#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>
#include <shadows/ShadowSettingsJson.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
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

PassTiming summarise(std::vector<double> samples) {
    std::sort(samples.begin(), samples.end());
    return {samples[samples.size() / 2], samples.front(), samples.back()};
}

double median(std::vector<float> values) {
    if (values.empty()) {
        return 0.0;
    }
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2),
                     values.end());
    return values[values.size() / 2];
}

} // namespace

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
    receivers_.resize(positions.size());
    std::vector<float> pixelSizes;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3 toLight = light_.light.type == engine::LightType::Directional
                                      ? -light_.direction
                                      : glm::normalize(light_.position - positions_[i]);
        receivers_[i] = covered[i] && glm::dot(normals_[i], toLight) > 0.05f;
        if (covered[i] && (i + 1) % static_cast<std::size_t>(options.size.x) != 0 && covered[i + 1]) {
            pixelSizes.push_back(glm::length(positions_[i + 1] - positions_[i]));
        }
    }
    pixelWorldSize_ = static_cast<float>(median(pixelSizes));
    concave_ = concaveMask(options.size, positions_, normals_, covered, 0.5f);

    const RayTracedVisibility tracer(scene_);
    truth_.resize(positions.size());
    if (options.softSamplesPerAxis > 0) {
        tracer.softVisibility(positions_, normals_, covered, light_, options.softRadius,
                              options.softSamplesPerAxis, truth_);
    } else {
        tracer.hardVisibility(positions_, normals_, covered, light_, truth_);
    }
}

BenchScene::~BenchScene() = default;

ShadowBench::ShadowBench(const engine::GlContext& context, BenchOptions options)
    : ShadowBench(engine::PassTimer::methodFor(context), std::move(options)) {}

ShadowBench::ShadowBench(engine::TimingMethod method, BenchOptions options)
    : options_(std::move(options)), method_(method) {}

std::unique_ptr<BenchScene> ShadowBench::prepare(const std::string& name,
                                                 const std::filesystem::path& path) const {
    content::LoadedScene loaded = content::GltfLoader::load(path);
    const auto camera = loaded.scene.firstCamera();
    if (!camera) {
        throw engine::Error("shadowbench: " + path.string() + " has no camera");
    }
    return std::make_unique<BenchScene>(name, std::move(loaded.scene), *camera, options_);
}

BenchResult ShadowBench::run(const BenchScene& scene, const BenchConfig& config) const {
    BenchResult result;
    result.scene = scene.name();
    result.config = config;
    engine::Engine engine;
    auto& module = static_cast<shadows::ShadowModule&>(
        engine.addModule(std::make_unique<shadows::ShadowModule>(config.settings)));

    // Timing: shaded frames, both passes, after a warm-up frame that compiles and uploads.
    engine::RenderTarget shaded(options_.size);
    engine.renderFrame(scene.scene_, scene.camera_, shaded);
    engine.setPassTiming(method_);
    std::vector<double> shadowTimes;
    std::vector<double> lightingTimes;
    for (int frame = 0; frame < std::max(options_.frames, 1); ++frame) {
        const engine::FrameStats stats = engine.renderFrame(scene.scene_, scene.camera_, shaded);
        shadowTimes.push_back(stats.prePassMilliseconds);
        lightingTimes.push_back(stats.lightingMilliseconds);
    }
    engine.setPassTiming(std::nullopt);
    result.shadowPass = summarise(shadowTimes);
    result.lightingPass = summarise(lightingTimes);
    result.shadowBytes = module.stats().bytes;
    std::filesystem::path folder = options_.imageFolder / scene.name();
    result.shadedImage = folder / (config.label + ".png");
    result.shaded = shaded.readPixels();
    engine::writePng(result.shadedImage, result.shaded);

    const Accuracy accuracy = measure(scene, config.settings);
    result.metrics = accuracy.metrics;
    result.bandPixels = accuracy.bandPixels;
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
    return result;
}

Accuracy ShadowBench::measure(const BenchScene& scene, const shadows::ShadowSettings& settings) const {
    engine::Engine engine;
    shadows::ShadowSettings visibilityOnly = settings;
    visibilityOnly.debugView = shadows::ShadowDebugView::Visibility;
    auto& module = static_cast<shadows::ShadowModule&>(
        engine.addModule(std::make_unique<shadows::ShadowModule>(visibilityOnly)));
    const auto pixels = renderFloat(engine, scene.scene_, scene.camera_, options_.size);
    Accuracy accuracy;
    accuracy.truth = scene.truth_;
    accuracy.visibility.resize(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        accuracy.visibility[i] = pixels[i].x;
    }
    // The band is a number of shadow texels; convert to pixels with the median texel and pixel footprints.
    float texelWorld = 0.0f;
    if (const auto projection = module.lightProjection(scene.light_.index)) {
        texelWorld = projection->texelScale;
        if (projection->perspective) {
            std::vector<float> distances;
            for (std::size_t i = 0; i < scene.positions_.size(); ++i) {
                if (scene.receivers_[i]) {
                    distances.push_back(
                        glm::dot(scene.positions_[i] - scene.light_.position, scene.light_.direction));
                }
            }
            texelWorld *= static_cast<float>(median(distances));
        }
    }
    accuracy.bandPixels = scene.pixelWorldSize_ > 0.0f
                              ? std::clamp(static_cast<int>(std::ceil(options_.bandTexels * texelWorld /
                                                                      scene.pixelWorldSize_)),
                                           1, 32)
                              : 1;
    accuracy.classes = classify(options_.size, scene.truth_, scene.receivers_, accuracy.bandPixels);
    accuracy.metrics = computeMetrics(accuracy.classes, scene.truth_, accuracy.visibility, scene.concave_);
    return accuracy;
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
           "concave_darkening,mae,rmse,receivers,lit,shadowed,band,concave,band_pixels,shadow_ms_median,"
           "shadow_ms_min,shadow_ms_max,lighting_ms_median,lighting_ms_min,lighting_ms_max,shadow_bytes,"
           "full_kernel_fraction\n";
    for (const BenchResult& r : results) {
        const shadows::ShadowSettings& s = r.config.settings;
        const ShadowMetrics& m = r.metrics;
        csv << r.scene << ',' << r.config.label << ',' << shadows::toString(s.technique) << ','
            << shadows::toString(s.pcfLayout) << ',' << s.pcfTaps << ',' << s.pcfRadius << ',' << s.resolution
            << ',' << shadows::toString(s.depthFormat) << ',' << m.acneRate << ',' << m.leakRate << ','
            << m.darkening << ',' << m.concaveDarkening << ',' << m.meanAbsoluteError << ','
            << m.rootMeanSquareError << ',' << m.receivers << ',' << m.lit << ',' << m.shadowed << ','
            << m.band << ',' << m.concave << ',' << r.bandPixels << ',' << r.shadowPass.median << ','
            << r.shadowPass.min << ',' << r.shadowPass.max << ',' << r.lightingPass.median << ','
            << r.lightingPass.min << ',' << r.lightingPass.max << ',' << r.shadowBytes << ','
            << r.fullKernelFraction << '\n';
    }
    return csv.str();
}

std::string resultsJson(const std::vector<BenchResult>& results, const std::string& renderer,
                        const std::string& glVersion, engine::TimingMethod method,
                        const BenchOptions& options) {
    nlohmann::json document;
    document["renderer"] = renderer;
    document["glVersion"] = glVersion;
    document["timingMethod"] = std::string(engine::PassTimer::describe(method));
    document["width"] = options.size.x;
    document["height"] = options.size.y;
    document["frames"] = options.frames;
    document["bandTexels"] = options.bandTexels;
    document["groundTruth"] = options.softSamplesPerAxis > 0 ? "soft" : "hard";
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
             {"pixels",
              {{"receivers", m.receivers},
               {"lit", m.lit},
               {"shadowed", m.shadowed},
               {"band", m.band},
               {"concave", m.concave},
               {"acne", m.acne},
               {"leak", m.leak}}},
             {"bandPixels", r.bandPixels},
             {"shadowPassMs",
              {{"median", r.shadowPass.median}, {"min", r.shadowPass.min}, {"max", r.shadowPass.max}}},
             {"lightingPassMs",
              {{"median", r.lightingPass.median}, {"min", r.lightingPass.min}, {"max", r.lightingPass.max}}},
             {"shadowBytes", r.shadowBytes},
             {"fullKernelFraction", r.fullKernelFraction},
             {"image", r.shadedImage.string()}});
    }
    document["results"] = list;
    return document.dump(2) + "\n";
}

} // namespace shadowbench
