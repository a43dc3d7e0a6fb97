// gs-scenetest: a shadow-quality check of one scene for a user's own CI. Renders headless, measures the
// technique's visibility against the ray-traced truth (and optionally the shaded frame against a golden
// image), writes a short report and the error images, and exits 1 naming every bound that is exceeded.
#include <cli/ContentFolder.h>
#include <cli/OptionValues.h>
#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/HeadlessContext.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <shadowbench/ShadowBench.h>
#include <shadows/ShadowModule.h>
#include <shadows/ShadowSettingsJson.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr const char* kUsage = R"(usage: gs-scenetest SCENE [options]
  SCENE                     a .gltf/.glb file, or a content or corpus scene name
  --technique NAME          shadow technique (gs-render --list-techniques)   [the module's default]
  --settings FILE           shadow settings JSON (docs/SHADOWS.md); --technique overrides its technique
  --max-acne PERCENT        lit receivers rendered in shadow                     [0.05]
  --max-leak PERCENT        shadowed receivers rendered lit                      [0.05]
  --max-darkening PERCENT   mean visibility lost over lit receivers              [0.5]
  --max-edge-mean PIXELS    mean distance from each true shadow-edge pixel to the nearest rendered one,
                            and back (each way)                                  [0.5]
  --max-edge-p95 PIXELS     95th percentile of those distances (each way)        [2]
                            (edges are checked where the truth has at least 100 edge pixels; acne and leak
                            are counted outside a band of 2 screen pixels around true edges)
  --golden PNG              compare the shaded frame with this image (same size)
  --max-diff D              per-channel difference a pixel may have, 0..255      [2]
  --max-failing-fraction F  fraction of pixels allowed beyond --max-diff, 0..1   [0.001]
  --size WxH                image size                                           [640x480]
  --out DIR                 report.txt, classes.png, error.png, shaded.png (and diff.png) [scenetest]
  --content DIR             content folder for scene names                       [installed or source content/]
exit status: 0 every bound holds; 1 a bound is exceeded (each is named) or the scene cannot be rendered;
2 bad options)";

struct Options {
    std::string scene;
    std::filesystem::path contentFolder = cli::defaultContentFolder();
    shadows::ShadowSettings settings;
    std::optional<std::string> technique;
    double maxAcne = 0.05;
    double maxLeak = 0.05;
    double maxDarkening = 0.5;
    double maxEdgeMean = 0.5;
    double maxEdgeP95 = 2.0;
    std::optional<std::filesystem::path> golden;
    int maxDiff = 2;
    double maxFailingFraction = 0.001;
    glm::ivec2 size{640, 480};
    std::filesystem::path out = "scenetest";
};

constexpr cli::Tool kTool{"gs-scenetest", kUsage};

/// Edge distances are checked only over at least this many true edge pixels: with a handful, one missing
/// rendered edge weighs in at the image diagonal.
constexpr std::size_t kMinimumEdgePixels = 100;

[[noreturn]] void usageError(const std::string& message) {
    kTool.fail(message);
}

Options parse(int argc, char** argv) {
    Options options;
    for (cli::ArgumentList arguments(argc, argv, kTool); arguments.next();) {
        const std::string arg = arguments.current();
        const auto value = [&] { return arguments.value(); };
        if (arg == "--technique") {
            options.technique = value();
        } else if (arg == "--settings") {
            const std::string path = value();
            std::ifstream file(path);
            if (!file) {
                usageError("--settings: cannot read '" + path + "'");
            }
            std::stringstream text;
            text << file.rdbuf();
            options.settings = shadows::settingsFromJson(text.str(), path);
        } else if (arg == "--max-acne") {
            options.maxAcne = cli::numberIn(arg, value(), 0.0f, 100.0f);
        } else if (arg == "--max-leak") {
            options.maxLeak = cli::numberIn(arg, value(), 0.0f, 100.0f);
        } else if (arg == "--max-darkening") {
            options.maxDarkening = cli::numberIn(arg, value(), 0.0f, 100.0f);
        } else if (arg == "--max-edge-mean") {
            options.maxEdgeMean = cli::numberIn(arg, value(), 0.0f, 10000.0f);
        } else if (arg == "--max-edge-p95") {
            options.maxEdgeP95 = cli::numberIn(arg, value(), 0.0f, 10000.0f);
        } else if (arg == "--golden") {
            options.golden = value();
        } else if (arg == "--max-diff") {
            options.maxDiff = cli::integerIn(arg, value(), 0, 255);
        } else if (arg == "--max-failing-fraction") {
            options.maxFailingFraction = cli::numberIn(arg, value(), 0.0f, 1.0f);
        } else if (arg == "--size") {
            options.size = cli::sizeIn(arg, value(), 16, 4096);
        } else if (arg == "--out") {
            options.out = value();
        } else if (arg == "--content") {
            options.contentFolder = value();
        } else if (arg.starts_with("--") || !options.scene.empty()) {
            usageError("unknown option '" + arg + "'");
        } else {
            options.scene = arg;
        }
    }
    if (options.scene.empty()) {
        usageError("no scene given");
    }
    if (options.technique) {
        const auto technique = shadows::techniqueFromString(*options.technique);
        if (!technique) {
            usageError("--technique: unknown technique '" + *options.technique +
                       "' (gs-render --list-techniques)");
        }
        options.settings.technique = *technique;
    }
    return options;
}

/// The shaded frame of `path` with `settings`, as gs-render draws it.
engine::Image shadedFrame(const std::filesystem::path& path, const shadows::ShadowSettings& settings,
                          glm::ivec2 size) {
    const content::LoadedScene loaded = content::GltfLoader::load(path);
    engine::Engine engine;
    engine.addModule(std::make_unique<shadows::ShadowModule>(settings));
    engine::RenderTarget target(size);
    engine.renderFrame(loaded.scene, *loaded.scene.firstCamera(), target);
    return target.readPixels();
}

std::string percent(double fraction) {
    std::ostringstream text;
    text.precision(3);
    text << 100.0 * fraction << " %";
    return text.str();
}

} // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parse(argc, argv);
    } catch (const std::exception& error) {
        usageError(error.what());
    }
    try {
        const std::filesystem::path path = cli::scenePath(options.scene, options.contentFolder);
        engine::HeadlessContext context;
        shadowbench::BenchOptions benchOptions;
        benchOptions.size = options.size;
        benchOptions.imageFolder = options.out;
        const shadowbench::ShadowBench bench(context, benchOptions);
        const auto scene = bench.prepare(path.stem().string(), path);
        const shadowbench::Accuracy accuracy = bench.measure(*scene, options.settings);
        engine::writePng(
            options.out / "classes.png",
            shadowbench::classificationImage(options.size, accuracy.classes, accuracy.visibility));
        engine::writePng(
            options.out / "error.png",
            shadowbench::errorHeatMap(options.size, accuracy.classes, accuracy.truth, accuracy.visibility));
        const engine::Image shaded = shadedFrame(path, options.settings, options.size);
        engine::writePng(options.out / "shaded.png", shaded);

        std::ostringstream report;
        std::vector<std::string> violated;
        report << "gs-scenetest: " << path.string() << ", technique "
               << shadows::toString(options.settings.technique) << ", " << options.size.x << "x"
               << options.size.y << ", " << context.renderer() << "\n";
        const shadowbench::ShadowMetrics& m = accuracy.metrics;
        const auto bound = [&](const std::string& name, double fraction, double maxPercent) {
            const bool ok = 100.0 * fraction <= maxPercent;
            report << "  " << name << " " << percent(fraction) << " (bound " << maxPercent << " %) "
                   << (ok ? "ok" : "EXCEEDED") << "\n";
            if (!ok) {
                violated.push_back(name + " " + percent(fraction) + " > " + percent(maxPercent / 100.0));
            }
        };
        bound("acne", m.acneRate, options.maxAcne);
        bound("leak", m.leakRate, options.maxLeak);
        bound("darkening", m.darkening, options.maxDarkening);
        const auto edgeBound = [&](const std::string& name, double pixels, double maxPixels) {
            const bool ok = pixels <= maxPixels;
            report << "  " << name << " " << pixels << " px (bound " << maxPixels << " px) "
                   << (ok ? "ok" : "EXCEEDED") << "\n";
            if (!ok) {
                violated.push_back(name + " " + std::to_string(pixels) + " px > " +
                                   std::to_string(maxPixels) + " px");
            }
        };
        if (m.edges.trueToRendered.count >= kMinimumEdgePixels) {
            edgeBound("edge true->rendered mean", m.edges.trueToRendered.mean, options.maxEdgeMean);
            edgeBound("edge true->rendered p95", m.edges.trueToRendered.percentile95, options.maxEdgeP95);
            edgeBound("edge rendered->true mean", m.edges.renderedToTrue.mean, options.maxEdgeMean);
            edgeBound("edge rendered->true p95", m.edges.renderedToTrue.percentile95, options.maxEdgeP95);
        } else {
            report << "  edges not checked: " << m.edges.trueToRendered.count
                   << " true edge pixels (fewer than " << kMinimumEdgePixels << ")\n";
        }
        if (m.density.pixels > 0) {
            report << "  texel density: " << percent(m.density.atMostOnePixel)
                   << " of lit receivers at m <= 1 (one texel per pixel or finer), median "
                   << m.density.median << " px, p99 " << m.density.percentile99 << " px\n";
        }
        if (options.golden) {
            const engine::Image golden = engine::readPng(*options.golden);
            if (golden.size != shaded.size) {
                throw engine::Error(options.golden->string() + ": golden image is " +
                                    std::to_string(golden.size.x) + "x" + std::to_string(golden.size.y) +
                                    ", the frame " + std::to_string(shaded.size.x) + "x" +
                                    std::to_string(shaded.size.y));
            }
            engine::Image diff = shaded;
            std::size_t failing = 0;
            for (std::size_t i = 0; i < shaded.pixels.size(); i += 4) {
                int largest = 0;
                for (std::size_t c = 0; c < 3; ++c) {
                    largest = std::max(largest, std::abs(shaded.pixels[i + c] - golden.pixels[i + c]));
                }
                const bool fails = largest > options.maxDiff;
                failing += fails;
                diff.pixels[i] = fails ? 255 : 0;
                diff.pixels[i + 1] = diff.pixels[i + 2] =
                    static_cast<std::uint8_t>(std::min(255, 4 * largest));
                diff.pixels[i + 3] = 255;
            }
            engine::writePng(options.out / "diff.png", diff);
            const double fraction =
                static_cast<double>(failing) / static_cast<double>(shaded.pixels.size() / 4);
            const bool ok = fraction <= options.maxFailingFraction;
            report << "  golden " << percent(fraction) << " of pixels differ by more than " << options.maxDiff
                   << " (bound " << percent(options.maxFailingFraction) << ") " << (ok ? "ok" : "EXCEEDED")
                   << "\n";
            if (!ok) {
                violated.push_back("golden " + percent(fraction) + " of pixels > " +
                                   percent(options.maxFailingFraction));
            }
        }
        if (violated.empty()) {
            report << "PASSED\n";
        } else {
            report << "FAILED:";
            for (const std::string& v : violated) {
                report << " " << v << ";";
            }
            report << "\n";
        }
        engine::writeTextFile(options.out / "report.txt", report.str());
        std::cout << report.str();
        return violated.empty() ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "gs-scenetest: " << error.what() << "\n";
        return 1;
    }
}
