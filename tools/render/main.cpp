// gs-render: renders a scene headless (EGL surfaceless) to PNG and writes a short JSON report.
#include <content/GltfLoader.h>

#include <cli/ContentFolder.h>
#include <cli/OptionValues.h>
#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/HeadlessContext.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>

#include <shadows/ShadowModule.h>
#include <shadows/ShadowSettingsSchema.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <sys/resource.h>

namespace {

struct Options {
    std::string scene = "knob";
    std::filesystem::path contentFolder = cli::defaultContentFolder();
    int subdivisionLevel = -1;
    std::filesystem::path outFolder = "out";
    glm::ivec2 size{1024, 768};
    int frames = 5;
    std::vector<std::string> modules;
    std::optional<shadows::ShadowSettings> shadows;
    std::uint32_t chunkTriangles = engine::ChunkLimits{}.maxTriangles;
    bool culling = true;
    bool depthPrePass = false;
    bool ownSampleDepth = false;
    bool drawHiddenFaces = false;
    bool drawShadowlessPlanes = false;
    bool linearOutput = false;
    bool tuneAllocator = true;
};

constexpr const char* kUsage = R"(usage: gs-render [options]
  --scene NAME     content scene (content/scenes/NAME.gltf), corpus scene (corpus/NAME.glb) or a .gltf/.glb path [knob]
  --content DIR    content folder holding scenes/ and cages/      [installed or source content/]
  --level N        subdivision level for every subdivided mesh, 0..6 [each scene's own]
  --out DIR        folder for <scene>.png and report.json         [out]
  --size WxH       image size in pixels, 1..16384 each            [1024x768]
  --frames N       frames to time after one warm-up frame, 1..1000 [5]
  --module NAME    load engine module NAME (repeatable)
  --chunk-triangles N  triangles per draw chunk, 1..16777216   [4096]
  --no-culling     draw chunks outside the view volume too
  --depth-prepass  lay down depth first, then shade with an EQUAL depth test
  --own-sample-depth  the shadow module's sample pass draws the view's depth itself (by default it takes
                   the lighting pass's depth pre-pass, which the lighting pass then shades against)
  --draw-hidden-faces  draw the faces closed meshes hide from the camera too (left out by default)
  --draw-shadowless-planes  draw flat casters that shadow nothing into the maps too (left out by default
                   where the technique only compares depths)
  --redraw-maps    draw the shadow maps every frame, as a moving view does (else a still view keeps them)
  --linear-output  store the linear colour without the sRGB encode, as fixed-function OpenGL does (darker)
  --allocator A    tuned (mallopt on CPU rasterisers) or default  [tuned]
  --list-techniques  print every shadow technique's name, one a line, and exit
  --help           this text
shadow settings (with --technique none they are checked and ignored):)";

/// `text` wrapped to lines of at most `width` characters that start `indent` characters in.
std::string wrapped(const std::string& text, std::size_t width, std::size_t indent) {
    std::string out;
    std::size_t lineLength = indent;
    std::istringstream words(text);
    for (std::string word; words >> word;) {
        if (lineLength > indent && lineLength + 1 + word.size() > width) {
            out += "\n" + std::string(indent, ' ');
            lineLength = indent;
        } else if (lineLength > indent) {
            out += ' ';
            ++lineLength;
        }
        out += word;
        lineLength += word.size();
    }
    return out;
}

/// The usage text: the tool's own options, then the shadow settings that have an option in the schema.
const std::string& usage() {
    static const std::string text = [] {
        std::string out = kUsage;
        const shadows::ShadowSettings defaults;
        for (const shadows::SettingRow& row : shadows::settingsSchema()) {
            if (row.option.empty()) {
                continue;
            }
            std::string head = "  " + std::string(row.option) +
                               (std::holds_alternative<shadows::IntSetting>(row.field) ? " N" : " NAME");
            head.resize(std::max<std::size_t>(head.size() + 1, 19), ' ');
            std::string accepts = row.rangeText() + (row.name == "technique" ? ", none" : "");
            out +=
                "\n" + head +
                wrapped(row.labelWithUnit() + ": " + accepts + " [" + row.valueText(defaults) + "]", 110, 19);
        }
        return out;
    }();
    return text;
}

const cli::Tool& tool() {
    static const std::string text = usage();
    static const cli::Tool gsRender{"gs-render", text};
    return gsRender;
}

[[noreturn]] void usageError(const std::string& message) {
    tool().fail(message);
}

/// Sets the schema field `row` from its command-line text (integers and choices are the only kinds with an
/// option).
void setShadowOption(shadows::ShadowSettings& settings, const shadows::SettingRow& row,
                     const std::string& text) {
    const std::string option(row.option);
    if (const auto* integer = std::get_if<shadows::IntSetting>(&row.field)) {
        const shadows::IntLimits limits = *integer->limits(settings);
        settings.*integer->member = cli::integerIn(option, text, limits.min, limits.max);
        return;
    }
    const auto& choice = std::get<shadows::EnumSetting>(row.field);
    const auto name = std::find(choice.names.begin(), choice.names.end(), text);
    if (name == choice.names.end()) {
        throw std::invalid_argument(option + ": unknown value '" + text + "' (" + choice.nameList() + ")");
    }
    choice.set(settings, static_cast<int>(name - choice.names.begin()));
}

const shadows::SettingRow* shadowOption(std::string_view option) {
    for (const shadows::SettingRow& row : shadows::settingsSchema()) {
        if (!row.option.empty() && row.option == option) {
            return &row;
        }
    }
    return nullptr;
}

Options parse(int argc, char** argv) {
    Options options;
    shadows::ShadowSettings settings;
    bool shadowsOn = true;
    for (cli::ArgumentList arguments(argc, argv, tool()); arguments.next();) {
        const std::string arg = arguments.current();
        const auto value = [&] { return arguments.value(); };
        if (arg == "--list-techniques") {
            for (const shadows::ShadowTechnique technique : shadows::allTechniques()) {
                std::cout << shadows::toString(technique) << "\n";
            }
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
        } else if (const shadows::SettingRow* row = shadowOption(arg)) {
            const std::string text = value();
            shadowsOn = row->name != "technique" ? shadowsOn : text != "none";
            if (row->name != "technique" || shadowsOn) {
                setShadowOption(settings, *row, text);
            }
        } else if (arg == "--chunk-triangles") {
            options.chunkTriangles =
                static_cast<std::uint32_t>(cli::integerIn("--chunk-triangles", value(), 1, 1 << 24));
        } else if (arg == "--no-culling") {
            options.culling = false;
        } else if (arg == "--depth-prepass") {
            options.depthPrePass = true;
        } else if (arg == "--own-sample-depth") {
            options.ownSampleDepth = true;
        } else if (arg == "--draw-hidden-faces") {
            options.drawHiddenFaces = true;
        } else if (arg == "--draw-shadowless-planes") {
            options.drawShadowlessPlanes = true;
        } else if (arg == "--linear-output") {
            options.linearOutput = true;
        } else if (arg == "--redraw-maps") {
            settings.reuseUnchangedMaps = false;
        } else if (arg == "--allocator") {
            const std::string name = value();
            if (name != "tuned" && name != "default") {
                usageError("--allocator: '" + name + "' is not tuned or default");
            }
            options.tuneAllocator = name == "tuned";
        } else {
            usageError("unknown option '" + arg + "'");
        }
    }
    if (shadowsOn) {
        options.shadows = settings;
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
    const Options options = tool().parse(parse, argc, argv);
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
        engine.renderer().shareViewDepth = !options.ownSampleDepth;
        engine.renderer().lightingHiddenFaces =
            options.drawHiddenFaces ? engine::HiddenFaces::Draw : engine::HiddenFaces::Skip;
        engine.renderer().leaveOutShadowlessChunks = !options.drawShadowlessPlanes;
        engine.renderer().encodeSrgb = !options.linearOutput;
        const shadows::ShadowModule* shadowModule = nullptr;
        if (options.shadows) {
            shadowModule = &static_cast<const shadows::ShadowModule&>(
                engine.addModule(std::make_unique<shadows::ShadowModule>(*options.shadows)));
        }
        for (const std::string& name : options.modules) {
            engine.loadModule(name);
        }
        engine::RenderTarget target(options.size);

        engine::FrameStats stats =
            engine.renderFrame(scene, *camera, target); // warm-up: uploads and compiles
        glFinish();
        std::vector<double> milliseconds;
        int framesReusingMaps = 0;
        const long faultsBefore = minorPageFaults();
        for (int frame = 0; frame < options.frames; ++frame) {
            const auto start = std::chrono::steady_clock::now();
            stats = engine.renderFrame(scene, *camera, target);
            glFinish();
            milliseconds.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            framesReusingMaps += shadowModule && shadowModule->stats().reusedMaps;
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
               << "  \"ownSampleDepth\": " << (options.ownSampleDepth ? "true" : "false") << ",\n"
               << "  \"sharedViewDepth\": " << (stats.sharedViewDepth ? "true" : "false") << ",\n"
               << "  \"drawHiddenFaces\": " << (options.drawHiddenFaces ? "true" : "false") << ",\n"
               << "  \"drawShadowlessPlanes\": " << (options.drawShadowlessPlanes ? "true" : "false") << ",\n"
               << "  \"allocatorTuned\": " << (context.allocatorTuned() ? "true" : "false") << ",\n"
               << "  \"programsCompiled\": " << engine.programs().compileCount() << ",\n"
               << "  \"shadowTechnique\": \""
               << (options.shadows ? shadows::toString(options.shadows->technique) : "none") << "\",\n"
               << "  \"shadowMaps\": " << (shadowModule ? shadowModule->stats().shadowMaps : 0) << ",\n"
               << "  \"shadowBytes\": " << (shadowModule ? shadowModule->stats().bytes : 0) << ",\n"
               << "  \"shadowMapResolution\": " << (shadowModule ? shadowModule->stats().mapResolution : 0)
               << ",\n"
               << "  \"shadowCasterTexels\": " << (shadowModule ? shadowModule->stats().casterTexels : 0)
               << ",\n"
               << "  \"shadowCasterTriangles\": "
               << (shadowModule ? shadowModule->stats().casters.triangles : 0) << ",\n"
               << "  \"shadowlessChunks\": "
               << (shadowModule ? shadowModule->stats().casters.shadowlessChunks : 0) << ",\n"
               << "  \"framesReusingShadowMaps\": " << framesReusingMaps << ",\n";
        if (shadowModule && shadowModule->stats().virtualMaps) {
            // The last timed frame's pages: a static view draws none once the first frame has.
            const shadows::VirtualPageStats pages = shadowModule->stats().pages;
            report << "  \"virtualPages\": {\"requested\": " << pages.requested
                   << ", \"rendered\": " << pages.rendered << ", \"cached\": " << pages.cached
                   << ", \"coarsened\": " << pages.coarsened << ", \"refused\": " << pages.refused
                   << ", \"resident\": " << pages.resident << ", \"poolPages\": " << pages.poolPages
                   << "},\n";
        }
        report << "  \"modules\": [";
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
