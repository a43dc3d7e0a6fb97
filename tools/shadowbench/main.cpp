// gs-shadowbench: sweeps shadow techniques x taps x resolutions x depth formats x scenes, measures each
// against ray-traced ground truth (Embree) and times its passes, and writes CSV, JSON and images.
#include <shadowbench/PeerRun.h>
#include <shadowbench/ShadowBench.h>

#include <cli/ContentFolder.h>
#include <cli/OptionValues.h>

#include <engine/Error.h>
#include <engine/HeadlessContext.h>
#include <engine/Image.h>
#include <shadows/ShadowSettingsJson.h>
#include <shadows/ShadowSettingsSchema.h>
#include <shadows/ShadowTechniqueTraits.h>

#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace {

constexpr const char* kUsage = R"(usage: gs-shadowbench [options]
  --scene NAME|FILE     content scene name or glTF path (repeatable)         [knob]
  --techniques LIST     comma-separated technique names ("default": the module's default), or
                        "all"                                               [all]
  --taps LIST           PCF taps per side (grid) to sweep, e.g. 2,4,6       [4]
  --radius TEXELS       PCF radius in texels                                [1.5]
  --resolutions LIST    shadow map sizes, e.g. 512,1024                     [1024]
  --formats LIST        depth formats: d16,d24,d32f                         [d24]
  --config LABEL:SPEC   an extra configuration, SPEC = key=value,... of the settings JSON fields
                        (e.g. "rpb-d16-floor:technique=receiver-plane,depthFormat=d16,floorReceiverDepth=true")
  --size WxH            image size                                          [640x480]
  --frames N            timed frames per configuration and round            [5]
  --rounds N            rounds of timed frames, every configuration of a scene in turn in each, so a
                        drift of the machine's speed spreads over all of them  [1]
  --accuracy-only       measure accuracy only, no timing (times are -1)
  --cost-model          also measure, per scene, the unshadowed lighting pass and one fetch's cost in it
                        (a reference pass making 1-16 bilinear or comparison reads per fragment), to
                        express each technique's lighting overhead in fetch-equivalents
  --shimmer N           also measure shimmer: the maps' fit moves a third of a texel per frame for N
                        frames while the camera stays; the fraction of receiver pixels whose visibility
                        changes by more than 0.5 between frames (0 for snapped cascades)
  --shimmer-path N      also measure shimmer along a camera path: the camera moves and turns a little
                        over N frames, the maps fitted to each; the fraction of receiver pixels,
                        followed by reprojection, whose visibility flips while the truth's does not
  --walk N              also measure virtual maps while the camera walks forward, level with the ground,
                        1.5 units/s at 30 frames/s, for N frames: texels drawn per frame after the first
  --defaults            each technique once, at its defaults (ignores --taps, --radius, --resolutions,
                        --formats); rows are labelled with the technique's name
  --light-sweep AZ:EL   point each scene's shadow-casting light from every azimuth x elevation (degrees,
                        comma-separated lists, e.g. 30,150:40,15,5,1); rows are "<scene>-az<A>-el<E>";
                        a spot or point light keeps its distance (engine::aimLight)
  --band WIDTH[UNIT]    boundary band half-width around true shadow edges, not scored for acne and
                        leak; UNIT px (screen pixels, what a viewer sees) or texels (shadow-map
                        texels at each receiver)                            [2px]
  --soft N[:RADIUS]     soft ground truth, N x N stratified rays per pixel over the light's own size (a sun's
                        angular diameter, a local light's sphere; glTF extras), or a sun's angular RADIUS in
                        radians, a local light's RADIUS; reports its RMS difference from 2N x 2N rays
  --out DIR             where results.csv, results.json and images go       [bench]: per scene
                        <label>.png (shaded), <label>-classes.png, <label>-error.png, truth.png (the
                        truth's classes) and side-by-side.png
  --content DIR         content folder                                      [installed or source content/]
  --peer DIR            add the OpenSceneGraph peer's runs found in DIR/<scene>/<name>.json and
                        .visibility.pfm (tools/osgpeer; vdsm, sm, lispsm, ssm, then any other name, e.g.
                        pssm3, vdsm-csm2) as rows "osg-<name>")";

constexpr cli::Tool kTool{"gs-shadowbench", kUsage};

[[noreturn]] void usageError(const std::string& message) {
    kTool.fail(message);
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::istringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
        if (!item.empty()) {
            items.push_back(item);
        }
    }
    return items;
}

struct Options {
    std::vector<std::string> scenes;
    std::vector<shadows::ShadowTechnique> techniques = shadows::allTechniques();
    std::vector<int> taps{4};
    float radius = 1.5f;
    std::vector<int> resolutions{1024};
    std::vector<shadows::DepthFormat> formats{shadows::DepthFormat::D24};
    std::vector<shadowbench::BenchConfig> extra;
    std::filesystem::path contentFolder = cli::defaultContentFolder();
    std::optional<std::filesystem::path> peerFolder;
    /// Empty: each scene's own light only.
    std::vector<engine::LightAngles> lights;
    bool defaults = false;
    shadowbench::BenchOptions bench;
};

std::vector<engine::LightAngles> lightSweep(const std::string& spec) {
    const auto colon = spec.find(':');
    if (colon == std::string::npos) {
        usageError("--light-sweep: '" + spec + "' is not AZIMUTHS:ELEVATIONS");
    }
    std::vector<engine::LightAngles> lights;
    for (const std::string& azimuth : splitList(spec.substr(0, colon))) {
        for (const std::string& elevation : splitList(spec.substr(colon + 1))) {
            lights.push_back({cli::numberIn("--light-sweep azimuth", azimuth, -360.0f, 360.0f),
                              cli::numberIn("--light-sweep elevation", elevation, 0.1f, 90.0f)});
        }
    }
    if (lights.empty()) {
        usageError("--light-sweep: '" + spec + "' names no direction");
    }
    return lights;
}

Options parse(int argc, char** argv) {
    Options options;
    options.bench.imageFolder = "bench";
    for (cli::ArgumentList arguments(argc, argv, kTool); arguments.next();) {
        const std::string arg = arguments.current();
        const auto value = [&] { return arguments.value(); };
        if (arg == "--scene") {
            options.scenes.push_back(value());
        } else if (arg == "--techniques") {
            const std::string list = value();
            if (list != "all") {
                options.techniques.clear();
                for (const std::string& name : splitList(list)) {
                    const auto technique = name == "default" ? shadows::ShadowSettings{}.technique
                                                             : shadows::techniqueFromString(name);
                    if (!technique) {
                        usageError("--techniques: unknown technique '" + name + "'");
                    }
                    options.techniques.push_back(*technique);
                }
            }
        } else if (arg == "--taps") {
            options.taps.clear();
            for (const std::string& item : splitList(value())) {
                const shadows::IntLimits grid = shadows::integerLimits("pcfTaps"); // the default layout's
                options.taps.push_back(cli::integerIn("--taps", item, grid.min, grid.max));
            }
        } else if (arg == "--radius") {
            options.radius = cli::numberIn("--radius", value(), 0.25f, 16.0f);
        } else if (arg == "--resolutions") {
            options.resolutions.clear();
            for (const std::string& item : splitList(value())) {
                const shadows::IntLimits sizes = shadows::integerLimits("resolution");
                options.resolutions.push_back(cli::integerIn("--resolutions", item, sizes.min, sizes.max));
            }
        } else if (arg == "--formats") {
            options.formats.clear();
            for (const std::string& item : splitList(value())) {
                const auto format = shadows::depthFormatFromString(item);
                if (!format) {
                    usageError("--formats: unknown depth format '" + item + "' (" +
                               shadows::nameList<shadows::DepthFormat>() + ")");
                }
                options.formats.push_back(*format);
            }
        } else if (arg == "--config") {
            const std::string spec = value();
            const auto colon = spec.find(':');
            if (colon == std::string::npos || colon == 0) {
                usageError("--config: '" + spec + "' is not LABEL:key=value,...");
            }
            try {
                options.extra.push_back(
                    {spec.substr(0, colon),
                     shadowbench::settingsFromAssignments(spec.substr(colon + 1), "--config " + spec)});
            } catch (const engine::Error& error) {
                usageError(error.what());
            }
        } else if (arg == "--size") {
            options.bench.size = cli::sizeIn("--size", value(), 16, 4096);
        } else if (arg == "--frames") {
            options.bench.frames = cli::integerIn("--frames", value(), 1, 1000);
        } else if (arg == "--rounds") {
            options.bench.rounds = cli::integerIn("--rounds", value(), 1, 100);
        } else if (arg == "--shimmer") {
            options.bench.shimmerFrames = cli::integerIn("--shimmer", value(), 1, 1000);
        } else if (arg == "--walk") {
            options.bench.walkFrames = cli::integerIn("--walk", value(), 1, 1000);
        } else if (arg == "--shimmer-path") {
            options.bench.pathFrames = cli::integerIn("--shimmer-path", value(), 1, 1000);
        } else if (arg == "--defaults") {
            options.defaults = true;
        } else if (arg == "--accuracy-only") {
            options.bench.timing = false;
        } else if (arg == "--cost-model") {
            options.bench.costModel = true;
        } else if (arg == "--light-sweep") {
            options.lights = lightSweep(value());
        } else if (arg == "--band") {
            std::string band = value();
            options.bench.bandUnit = shadowbench::BandUnit::Pixels;
            if (band.ends_with("texels")) {
                options.bench.bandUnit = shadowbench::BandUnit::Texels;
                band.resize(band.size() - 6);
            } else if (band.ends_with("px")) {
                band.resize(band.size() - 2);
            }
            options.bench.bandWidth = cli::numberIn("--band", band, 0.0f, 64.0f);
        } else if (arg == "--soft") {
            const std::string text = value();
            const auto colon = text.find(':');
            options.bench.softSamplesPerAxis = cli::integerIn("--soft", text.substr(0, colon), 1, 32);
            if (colon != std::string::npos) {
                options.bench.softRadius = cli::numberIn("--soft", text.substr(colon + 1), 0.0f, 100.0f);
            }
        } else if (arg == "--out") {
            options.bench.imageFolder = value();
        } else if (arg == "--content") {
            options.contentFolder = value();
        } else if (arg == "--peer") {
            options.peerFolder = value();
        } else {
            usageError("unknown option '" + arg + "'");
        }
    }
    if (options.scenes.empty()) {
        options.scenes.push_back("knob");
    }
    if (options.bench.costModel && !options.bench.timing) {
        usageError("--cost-model times the lighting pass: it cannot go with --accuracy-only");
    }
    return options;
}

/// The sweep: every technique at every resolution and format; pattern techniques once per tap count.
std::vector<shadowbench::BenchConfig> configurations(const Options& options) {
    std::vector<shadowbench::BenchConfig> configs;
    if (options.defaults) {
        for (const shadows::ShadowTechnique technique : options.techniques) {
            shadowbench::BenchConfig config;
            config.settings.technique = technique;
            config.label = std::string(shadows::toString(technique));
            configs.push_back(config);
        }
        configs.insert(configs.end(), options.extra.begin(), options.extra.end());
        return configs;
    }
    for (const shadows::ShadowTechnique technique : options.techniques) {
        const bool patterned = shadows::techniqueTable()[static_cast<std::size_t>(technique)].usesTapPattern;
        const std::vector<int> taps = patterned ? options.taps : std::vector<int>{options.taps.front()};
        for (const int resolution : options.resolutions) {
            for (const shadows::DepthFormat format : options.formats) {
                for (const int tapCount : taps) {
                    shadowbench::BenchConfig config;
                    config.settings.technique = technique;
                    config.settings.resolution = resolution;
                    config.settings.depthFormat = format;
                    config.settings.pcfTaps = tapCount;
                    config.settings.pcfRadius = options.radius;
                    config.label =
                        std::string(shadows::toString(technique)) +
                        (patterned ? "-" + std::to_string(tapCount) + "x" + std::to_string(tapCount) : "") +
                        "-" + std::to_string(resolution) + "-" + std::string(shadows::toString(format));
                    configs.push_back(config);
                }
            }
        }
    }
    configs.insert(configs.end(), options.extra.begin(), options.extra.end());
    return configs;
}

/// Shaded images of a scene side by side, four to a row, in sweep order.
engine::Image sideBySide(const std::vector<engine::Image>& images) {
    const glm::ivec2 cell = images.front().size;
    const int columns = std::min<int>(4, static_cast<int>(images.size()));
    const int rows = (static_cast<int>(images.size()) + columns - 1) / columns;
    engine::Image sheet;
    sheet.size = {cell.x * columns, cell.y * rows};
    sheet.pixels.assign(static_cast<std::size_t>(sheet.size.x) * static_cast<std::size_t>(sheet.size.y) * 4,
                        0);
    for (std::size_t n = 0; n < images.size(); ++n) {
        const int ox = static_cast<int>(n) % columns * cell.x;
        const int oy = static_cast<int>(n) / columns * cell.y;
        for (int y = 0; y < cell.y; ++y) {
            const auto* from =
                images[n].pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(cell.x) * 4;
            auto* to = sheet.pixels.data() +
                       (static_cast<std::size_t>(oy + y) * static_cast<std::size_t>(sheet.size.x) +
                        static_cast<std::size_t>(ox)) *
                           4;
            std::copy(from, from + static_cast<std::size_t>(cell.x) * 4, to);
        }
    }
    return sheet;
}

/// The virtual maps' pages of a result for the progress line: drawn cold, and per frame of the walk, as
/// multiples of the lit receiver pixels; empty without virtual maps.
std::string pagesText(const shadowbench::BenchResult& result) {
    if (!result.virtualMaps) {
        return {};
    }
    const double lit = static_cast<double>(std::max<std::size_t>(result.metrics.density.pixels, 1));
    std::ostringstream text;
    text << std::setprecision(3) << "pages " << result.coldPages.rendered << " cold ("
         << static_cast<double>(result.coldPages.texelsRendered) / lit << "x lit px), "
         << result.warmPages.rendered << " warm, " << result.coldPages.coarsened << " coarsened, ";
    if (result.walkTexelsPerFrame >= 0.0) {
        text << "walk " << result.walkTexelsPerFrame / lit << "x lit px/frame (max "
             << result.walkTexelsPerFrameMax / lit << "), ";
    }
    return text.str();
}

/// A result's penumbra errors against a soft truth for the progress line; empty against a hard one.
std::string softText(const shadowbench::BenchResult& result) {
    if (!result.soft) {
        return {};
    }
    const shadowbench::SoftShadowMetrics& soft = *result.soft;
    std::ostringstream text;
    text << std::setprecision(3) << "penumbra RMSE " << soft.penumbraRmse << " over " << soft.penumbraPixels
         << " px, false lit " << soft.falseLit << ", false shadow " << soft.falseShadow << ", width error "
         << soft.widthErrorMedian << "/" << soft.widthErrorP95 << " px (median/p95 of " << soft.widthSamples
         << ", widths x" << soft.widthRatioMedian << ")";
    if (soft.seamPairs > 0) {
        text << ", seam jump " << soft.seamJumpMedian << "/" << soft.seamJumpMax << " px (median/max of "
             << soft.seamPairs << ")";
    }
    text << ", ";
    return text.str();
}

} // namespace

int main(int argc, char** argv) {
    const Options options = kTool.parse(parse, argc, argv);
    try {
        engine::HeadlessContext context;
        const shadowbench::ShadowBench bench(context, options.bench);
        const std::vector<shadowbench::BenchConfig> configs = configurations(options);
        // Each scene under its own light, or under every light of the sweep.
        std::vector<std::pair<std::string, std::optional<engine::LightAngles>>> views;
        for (const std::string& sceneName : options.scenes) {
            if (options.lights.empty()) {
                views.emplace_back(sceneName, std::nullopt);
            }
            for (const engine::LightAngles& light : options.lights) {
                views.emplace_back(sceneName, light);
            }
        }
        const std::size_t total = configs.size() * views.size();
        std::vector<shadowbench::BenchResult> results;
        std::vector<shadowbench::SceneCost> costs;
        std::cout << "gs-shadowbench: " << total << " runs on " << context.renderer() << ", timing by "
                  << (options.bench.timing ? engine::PassTimer::describe(bench.timingMethod()) : "nothing")
                  << "\n";
        for (const auto& [sceneName, light] : views) {
            const std::filesystem::path path = cli::scenePath(sceneName, options.contentFolder);
            const std::string name = path.stem().string() + (light ? "-" + light->label() : std::string());
            const auto scene = bench.prepare(name, path, light);
            if (!configs.empty()) {
                // The truth's own classes (lit, shadowed, and the edge band at the first configuration's map
                // size), beside each configuration's classes on gs-contactsheet's truth sheet.
                const shadowbench::Accuracy reference = bench.measure(*scene, configs.front().settings);
                engine::writePng(
                    options.bench.imageFolder / scene->name() / "truth.png",
                    shadowbench::classificationImage(options.bench.size, reference.classes, reference.truth));
            }
            std::vector<engine::Image> shaded;
            const auto started = std::chrono::steady_clock::now();
            std::vector<shadowbench::BenchResult> runs = bench.run(*scene, configs);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            for (shadowbench::BenchResult& result : runs) {
                shaded.push_back(std::move(result.shaded));
                results.push_back(std::move(result));
                const shadowbench::ShadowMetrics& m = results.back().metrics;
                std::cout << "[" << results.size() << "/" << total << "] " << scene->name() << " "
                          << results.back().config.label << ": acne " << std::setprecision(3) << m.acneRate
                          << ", leak " << m.leakRate << ", darkening " << m.darkening << ", edges "
                          << m.edges.trueToRendered.mean << "/" << m.edges.renderedToTrue.mean << " px (p95 "
                          << m.edges.trueToRendered.percentile95 << "/" << m.edges.renderedToTrue.percentile95
                          << "), m<=1 " << m.density.atMostOnePixel << " (p99 " << m.density.percentile99
                          << " px, p99.9 " << m.density.percentile999 << "), "
                          << (results.back().mapResolution > 0
                                  ? "map " + std::to_string(results.back().mapResolution) + "², "
                                  : std::string())
                          << pagesText(results.back()) << softText(results.back())
                          << (results.back().shimmer >= 0.0
                                  ? "shimmer " + std::to_string(results.back().shimmer) + ", "
                                  : std::string())
                          << (results.back().pathShimmer >= 0.0
                                  ? "path shimmer " + std::to_string(results.back().pathShimmer) + ", "
                                  : std::string())
                          << "shadow " << results.back().shadowPass.median << " ms, lighting "
                          << results.back().lightingPass.median << " ms, frame "
                          << results.back().frame.median << " ms (still " << results.back().stillFrame.median
                          << " ms)\n";
            }
            std::cout << scene->name() << ": " << runs.size() << " configurations in " << std::fixed
                      << std::setprecision(1) << seconds << std::defaultfloat << " s\n"
                      << std::flush;
            shadowbench::SceneCost cost = bench.measureCost(*scene);
            if (options.peerFolder) {
                // The band's unit, our texel at each receiver at the peer's map size, measured once per size
                // rather than once per run.
                std::map<int, std::vector<float>> texelSizesAtMapSize;
                for (const std::string& technique :
                     shadowbench::peerRunNames(*options.peerFolder, scene->name())) {
                    const auto run = shadowbench::loadPeerRun(*options.peerFolder, scene->name(), technique,
                                                              options.bench.size);
                    if (!run) {
                        std::cout << scene->name() << " osg-" << technique << ": no peer run in "
                                  << options.peerFolder->string() << "\n";
                        continue;
                    }
                    auto texels = texelSizesAtMapSize.find(run->mapSize);
                    if (texels == texelSizesAtMapSize.end()) {
                        shadows::ShadowSettings ours;
                        ours.resolution = run->mapSize;
                        texels =
                            texelSizesAtMapSize.emplace(run->mapSize, bench.measure(*scene, ours).texelSizes)
                                .first;
                    }
                    results.push_back(bench.peerResult(*scene, *run, texels->second));
                    if (technique == "vdsm") {
                        cost.peerUnshadowedFrame = run->unshadowed;
                        cost.peerAllocatorTuned = run->allocatorTuned;
                    }
                    const shadowbench::ShadowMetrics& m = results.back().metrics;
                    std::cout << scene->name() << " osg-" << technique << " (" << run->osgClass << ", "
                              << run->shadowMaps << (run->shadowMaps == 1 ? " map" : " maps") << "): acne "
                              << std::setprecision(3) << m.acneRate << ", leak " << m.leakRate << ", MAE "
                              << m.meanAbsoluteError << ", frame " << run->shadowed.median << " ms"
                              << ", " << results.back().peerUnlitReceivers << " receivers unlit in its frame"
                              << "\n";
                }
            }
            std::cout << std::fixed << std::setprecision(2) << scene->name() << ": " << cost.triangles
                      << " triangles, " << cost.drawCalls << " draws, unshadowed frame "
                      << cost.unshadowedFrame.median << " ms";
            if (cost.filteredFetchMs >= 0.0) {
                std::cout << ", lighting pass " << cost.unshadowedLighting.median << " ms, one fetch "
                          << cost.filteredFetchMs << " ms bilinear, " << cost.compareFetchMs << " ms compare";
            }
            if (const shadowbench::SoftTruth& soft = cost.softTruth; soft.samplesPerAxis > 0) {
                std::cout << std::defaultfloat << "; soft truth " << soft.samplesPerAxis << "x"
                          << soft.samplesPerAxis << " rays over radius " << soft.radius << ", RMS "
                          << soft.convergenceRmse << " from " << 2 * soft.samplesPerAxis << "x"
                          << 2 * soft.samplesPerAxis;
            }
            std::cout << std::defaultfloat << "\n";
            costs.push_back(cost);
            engine::writePng(options.bench.imageFolder / scene->name() / "side-by-side.png",
                             sideBySide(shaded));
        }
        engine::writeTextFile(options.bench.imageFolder / "results.csv", shadowbench::resultsCsv(results));
        engine::writeTextFile(options.bench.imageFolder / "results.json",
                              shadowbench::resultsJson(results, costs, context.renderer(), context.version(),
                                                       bench.timingMethod(), options.bench));
        std::cout << "wrote " << (options.bench.imageFolder / "results.csv").string()
                  << " and results.json\n";
        return 0;
    } catch (const engine::Error& error) {
        std::cerr << "gs-shadowbench: " << error.what() << "\n";
        return 1;
    }
}
