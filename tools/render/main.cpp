// gs-render: renders a scene headless (EGL surfaceless) to PNG and writes a short JSON report.
#include <content/GltfLoader.h>

#include <cli/OptionValues.h>
#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/HeadlessContext.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>

#include <shadows/ShadowModule.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace {

struct Options {
    std::string scene = "knob";
    std::filesystem::path contentFolder = GS_CONTENT_DIR;
    int subdivisionLevel = -1;
    std::filesystem::path outFolder = "out";
    glm::ivec2 size{1024, 768};
    int frames = 5;
    std::vector<std::string> modules;
    std::optional<shadows::ShadowSettings> shadows;
    std::uint32_t chunkTriangles = engine::ChunkLimits{}.maxTriangles;
    bool culling = true;
    bool depthPrePass = false;
    bool tuneAllocator = true;
};

constexpr const char* kUsage = R"(usage: gs-render [options]
  --scene NAME     content scene (content/scenes/NAME.gltf) or a .gltf/.glb path [knob]
  --content DIR    content folder holding scenes/ and cages/      [the repository's content/]
  --level N        subdivision level for every subdivided mesh, 0..6 [each scene's own]
  --out DIR        folder for <scene>.png and report.json         [out]
  --size WxH       image size in pixels, 1..16384 each            [1024x768]
  --frames N       frames to time after one warm-up frame, 1..1000 [5]
  --module NAME    load engine module NAME (repeatable)
  --technique NAME shadows with this technique (hard, slope-scaled, hw-pcf, pcf, gsm, pcf-gsm-naive,
                   pcf-gsm-point, pcf-gsm-average, pcf-gsm-quadratic, receiver-plane, normal-offset, none)
                                                                  [pcf-gsm-average]
  --shadow-size N  shadow map resolution, 64..16384               [2048]
  --depth-format F d16, d24 or d32f                               [d24]
  --debug-view V   none, texels, gradient, bias, visibility, shadow-map [none]
  --chunk-triangles N  triangles per draw chunk, 1..16777216   [4096]
  --no-culling     draw chunks outside the view volume too
  --depth-prepass  lay down depth first, then shade with an EQUAL depth test
  --allocator A    tuned (mallopt on CPU rasterisers) or default  [tuned]
  --help           this text)";

[[noreturn]] void usageError(const std::string& message) {
    std::cerr << "gs-render: " << message << "\n" << kUsage << "\n";
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options options;
    options.shadows = shadows::ShadowSettings{};
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                usageError(arg + " needs a value");
            }
            return argv[++i];
        };
        if (arg == "--help") {
            std::cout << kUsage << "\n";
            std::exit(0);
        } else if (arg == "--scene") {
            options.scene = value();
        } else if (arg == "--content") {
            options.contentFolder = value();
        } else if (arg == "--level") {
            options.subdivisionLevel = cli::integerIn("--level", value(), 0, 6);
        } else if (arg == "--out") {
            options.outFolder = value();
        } else if (arg == "--size") {
            options.size = cli::sizeIn("--size", value(), 1, 16384);
        } else if (arg == "--frames") {
            options.frames = cli::integerIn("--frames", value(), 1, 1000);
        } else if (arg == "--module") {
            options.modules.push_back(value());
        } else if (arg == "--technique") {
            const std::string name = value();
            if (name == "none") {
                options.shadows.reset();
            } else if (const auto technique = shadows::techniqueFromString(name);
                       technique && options.shadows) {
                options.shadows->technique = *technique;
            } else if (!technique) {
                usageError("--technique: unknown technique '" + name + "'");
            }
        } else if (arg == "--chunk-triangles") {
            options.chunkTriangles =
                static_cast<std::uint32_t>(cli::integerIn("--chunk-triangles", value(), 1, 1 << 24));
        } else if (arg == "--no-culling") {
            options.culling = false;
        } else if (arg == "--depth-prepass") {
            options.depthPrePass = true;
        } else if (arg == "--allocator") {
            const std::string name = value();
            if (name != "tuned" && name != "default") {
                usageError("--allocator: '" + name + "' is not tuned or default");
            }
            options.tuneAllocator = name == "tuned";
        } else if (arg == "--shadow-size" && options.shadows) {
            options.shadows->resolution = cli::integerIn("--shadow-size", value(), 64, 16384);
        } else if (arg == "--depth-format" && options.shadows) {
            const std::string name = value();
            const auto format = shadows::depthFormatFromString(name);
            if (!format) {
                usageError("--depth-format: unknown format '" + name + "' (d16, d24, d32f)");
            }
            options.shadows->depthFormat = *format;
        } else if (arg == "--debug-view" && options.shadows) {
            const std::string name = value();
            const auto view = shadows::debugViewFromString(name);
            if (!view) {
                usageError("--debug-view: unknown view '" + name + "'");
            }
            options.shadows->debugView = *view;
        } else {
            usageError("unknown option '" + arg + "'");
        }
    }
    return options;
}

/// Minor page faults of the process so far: memory the allocator handed back and touches again.
long minorPageFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

std::string jsonEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        if (static_cast<unsigned char>(c) >= 0x20) {
            out += c;
        }
    }
    return out;
}

} // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parse(argc, argv);
    } catch (const std::invalid_argument& error) {
        usageError(error.what());
    }
    try {
        const std::filesystem::path path = cli::scenePath(options.scene, options.contentFolder);
        content::SceneLoadOptions loadOptions;
        loadOptions.subdivisionLevel = options.subdivisionLevel;
        const content::LoadedScene loaded = content::GltfLoader::load(path, loadOptions);
        for (const std::string& warning : loaded.warnings) {
            std::cerr << "gs-render: warning: " << warning << "\n";
        }
        const engine::Scene& scene = loaded.scene;
        const auto camera = scene.firstCamera();
        if (!camera) {
            std::cerr << "gs-render: " << path.string() << ": the scene has no camera\n";
            return 1;
        }
        engine::ContextOptions contextOptions;
        contextOptions.tuneAllocatorForSoftwareRenderer = options.tuneAllocator;
        engine::HeadlessContext context(contextOptions);
        engine::Engine engine;
        engine.renderer().chunkLimits.maxTriangles = options.chunkTriangles;
        engine.renderer().culling = options.culling;
        engine.renderer().depthPrePass = options.depthPrePass;
        if (options.shadows) {
            engine.addModule(std::make_unique<shadows::ShadowModule>(*options.shadows));
        }
        for (const std::string& name : options.modules) {
            engine.loadModule(name);
        }
        engine::RenderTarget target(options.size);

        engine::FrameStats stats =
            engine.renderFrame(scene, *camera, target); // warm-up: uploads and compiles
        glFinish();
        std::vector<double> milliseconds;
        const long faultsBefore = minorPageFaults();
        for (int frame = 0; frame < options.frames; ++frame) {
            const auto start = std::chrono::steady_clock::now();
            stats = engine.renderFrame(scene, *camera, target);
            glFinish();
            milliseconds.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        const double faultsPerFrame =
            static_cast<double>(minorPageFaults() - faultsBefore) / static_cast<double>(options.frames);
        std::sort(milliseconds.begin(), milliseconds.end());
        const double median = milliseconds[milliseconds.size() / 2];

        const std::filesystem::path image = options.outFolder / (path.stem().string() + ".png");
        engine::writePng(image, target.readPixels());

        std::ostringstream report;
        report << "{\n"
               << "  \"scene\": \"" << jsonEscape(path.string()) << "\",\n"
               << "  \"image\": \"" << jsonEscape(image.string()) << "\",\n"
               << "  \"width\": " << options.size.x << ",\n"
               << "  \"height\": " << options.size.y << ",\n"
               << "  \"renderer\": \"" << jsonEscape(context.renderer()) << "\",\n"
               << "  \"glVersion\": \"" << jsonEscape(context.version()) << "\",\n"
               << "  \"timingMethod\": \"glFinish + std::chrono::steady_clock per frame (CPU wall time)\",\n"
               << "  \"frames\": " << options.frames << ",\n"
               << "  \"frameMillisecondsMedian\": " << median << ",\n"
               << "  \"frameMillisecondsMin\": " << milliseconds.front() << ",\n"
               << "  \"frameMillisecondsMax\": " << milliseconds.back() << ",\n"
               << "  \"drawCalls\": " << stats.drawCalls << ",\n"
               << "  \"triangles\": " << stats.triangles << ",\n"
               << "  \"culledChunks\": " << stats.culledChunks << ",\n"
               << "  \"pageFaultsPerFrame\": " << faultsPerFrame << ",\n"
               << "  \"chunkTriangles\": " << options.chunkTriangles << ",\n"
               << "  \"culling\": " << (options.culling ? "true" : "false") << ",\n"
               << "  \"depthPrePass\": " << (options.depthPrePass ? "true" : "false") << ",\n"
               << "  \"allocatorTuned\": " << (context.allocatorTuned() ? "true" : "false") << ",\n"
               << "  \"programsCompiled\": " << engine.programs().compileCount() << ",\n"
               << "  \"shadowTechnique\": \""
               << (options.shadows ? shadows::toString(options.shadows->technique) : "none") << "\",\n"
               << "  \"modules\": [";
        for (std::size_t i = 0; i < options.modules.size(); ++i) {
            report << (i ? ", " : "") << '"' << jsonEscape(options.modules[i]) << '"';
        }
        report << "]\n}\n";
        engine::writeTextFile(options.outFolder / "report.json", report.str());
        std::cout << "wrote " << image.string() << " and " << (options.outFolder / "report.json").string()
                  << " (" << context.renderer() << ", median frame " << median
                  << " ms by glFinish + steady clock)\n";
        return 0;
    } catch (const engine::Error& error) {
        std::cerr << "gs-render: " << error.what() << "\n";
        return 1;
    }
}
