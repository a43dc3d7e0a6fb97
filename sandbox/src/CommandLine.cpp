#include "CommandLine.h"

#include <cli/OptionValues.h>

#include "ParameterTable.h"
#include "SandboxError.h"

#include <shadows/ShadowSettingsSchema.h>

#include <string>

namespace sandbox {

namespace {

constexpr std::string_view kUsage = R"(usage: gs-sandbox [options]
Explore shadow techniques side by side: a window with controls, or --headless to render a PNG through EGL.

  --headless        render without a window (EGL) and write --out
  --scene NAME      content scene (content/scenes/NAME.gltf) or a .gltf/.glb path     [knob]
  --level N         subdivision level of every subdivided mesh, -1..6 (-1: the file's) [-1]
  --technique NAME  technique of side A; without --compare the whole view is A        [pcf-gsm-point]
  --compare NAME    technique of side B, right of the divider (split screen)         [pcf-gsm-average]
  --shadow-size N   shadow map resolution of both sides, %RESOLUTION%
  --settings FILE   sandbox settings JSON (docs/SANDBOX.md); the options above override it
  --size WxH        window or image size, 1..16384 each                              [1280x720]
  --frames N        headless: frames to render, the last is written [1];
                    windowed: close after N frames [run until closed]
  --out FILE        headless: PNG to write                                           [sandbox.png]
  --ground-truth F  headless: measure side A against ray-traced truth, write the acne/leak overlay to F
  --screenshot FILE windowed: PNG for F12/the button, written after the last --frames frame too
                                                                                      [sandbox-screenshot.png]
  --no-ui           windowed: start with the panels hidden (F1 shows them)
  --help            this text

Techniques: )";

/// The shared option parsers report through std::invalid_argument; the sandbox's errors are SandboxErrors.
int parseInt(const std::string& option, const std::string& text, int low, int high) {
    try {
        return cli::integerIn(option, text, low, high);
    } catch (const std::invalid_argument& error) {
        throw SandboxError(error.what());
    }
}

shadows::ShadowTechnique parseTechnique(const std::string& option, const std::string& name) {
    const auto technique = shadows::techniqueFromString(name);
    if (!technique) {
        throw SandboxError(option + ": unknown technique '" + name + "' (" +
                           shadows::nameList<shadows::ShadowTechnique>() + ")");
    }
    return *technique;
}

} // namespace

std::string_view CommandLine::usage() {
    static const std::string text = [] {
        std::string usage = std::string(kUsage) + shadows::nameList<shadows::ShadowTechnique>() + ".";
        const shadows::IntLimits limits = shadows::integerLimits("resolution");
        std::string range = std::to_string(limits.min) + ".." + std::to_string(limits.max);
        range.resize(28, ' '); // the defaults column
        const std::string placeholder = "%RESOLUTION%";
        usage.replace(usage.find(placeholder), placeholder.size(),
                      range + "[" + std::to_string(shadows::ShadowSettings{}.resolution) + "]");
        return usage;
    }();
    return text;
}

CommandLine CommandLine::parse(std::span<const std::string_view> arguments, const SceneCatalog& catalog) {
    CommandLine line;
    std::optional<std::string> scene;
    std::optional<int> level;
    std::optional<shadows::ShadowTechnique> techniqueA;
    std::optional<shadows::ShadowTechnique> techniqueB;
    std::optional<int> shadowSize;
    std::optional<std::string> windowOnly;
    std::optional<std::string> headlessOnly;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string option(arguments[i]);
        auto value = [&]() -> std::string {
            if (i + 1 >= arguments.size()) {
                throw SandboxError(option + " needs a value");
            }
            return std::string(arguments[++i]);
        };
        if (option == "--help") {
            line.help = true;
        } else if (option == "--headless") {
            line.headless = true;
        } else if (option == "--scene") {
            scene = value();
        } else if (option == "--level") {
            level = parseInt(option, value(), ParameterTable::kLevel.min, ParameterTable::kLevel.max);
        } else if (option == "--technique") {
            techniqueA = parseTechnique(option, value());
        } else if (option == "--compare") {
            techniqueB = parseTechnique(option, value());
        } else if (option == "--shadow-size") {
            const shadows::IntLimits sizes = shadows::integerLimits("resolution");
            shadowSize = parseInt(option, value(), sizes.min, sizes.max);
        } else if (option == "--settings") {
            line.settingsFile = value();
        } else if (option == "--size") {
            try {
                line.size = cli::sizeIn(option, value(), 1, 16384);
            } catch (const std::invalid_argument& error) {
                throw SandboxError(error.what());
            }
        } else if (option == "--frames") {
            line.frames = parseInt(option, value(), 1, 1000000);
        } else if (option == "--out") {
            line.out = value();
            headlessOnly = option;
        } else if (option == "--ground-truth") {
            line.groundTruth = value();
            headlessOnly = option;
        } else if (option == "--screenshot") {
            line.screenshot = value();
            windowOnly = option;
        } else if (option == "--no-ui") {
            line.showUi = false;
            windowOnly = option;
        } else {
            throw SandboxError("unknown option '" + option + "'");
        }
    }
    if (line.help) {
        return line;
    }
    if (line.headless && windowOnly) {
        throw SandboxError(*windowOnly +
                           " applies to the window only, not to --headless (which writes --out)");
    }
    if (!line.headless && headlessOnly) {
        throw SandboxError(*headlessOnly + " applies to --headless only (the window writes --screenshot)");
    }

    std::string sceneSource = "--scene";
    if (line.settingsFile) {
        line.settings = SandboxSettings::load(*line.settingsFile);
        sceneSource = line.settingsFile->string() + ": field 'scene'";
    }
    if (scene) {
        line.settings.scene = *scene;
        sceneSource = "--scene";
    }
    try {
        (void)catalog.resolve(line.settings.scene);
    } catch (const SandboxError& error) {
        throw SandboxError(sceneSource + ": " + error.what());
    }
    if (level) {
        line.settings.level = *level;
    }
    if (techniqueA) {
        line.settings.a.technique = *techniqueA;
        // A technique alone is a single-technique view; --compare brings the split back.
        line.settings.compare = false;
    }
    if (techniqueB) {
        line.settings.b.technique = *techniqueB;
        line.settings.compare = true;
    }
    if (shadowSize) {
        line.settings.a.resolution = *shadowSize;
        line.settings.b.resolution = *shadowSize;
    }
    return line;
}

} // namespace sandbox
