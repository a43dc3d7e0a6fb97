#include "CommandLine.h"

#include <cli/OptionValues.h>

#include "ParameterTable.h"
#include "SandboxError.h"
#include "SoakRun.h"

#include <shadows/ShadowSettingsSchema.h>

#include <algorithm>
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
  --ground-truth F  headless: measure both sides against ray-traced truth, write the acne/leak overlay to F
  --soak N          headless: N cycles (3..100000) of every scene x technique x light type, one frame each;
                    checks that RSS and live GL objects stay flat after two cycles of warm-up and that GL reports
                    no error; exit 1 otherwise (no image written)
  --soak-scenes S   headless soak: all, content (content/scenes only) or NAME,NAME,...       [all]
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

/// The scenes `--soak-scenes` names: all, content, or a comma-separated list checked against `catalog`.
std::vector<std::string> soakSceneList(const std::string& text, const SceneCatalog& catalog) {
    if (text == "all") {
        return catalog.names();
    }
    if (text == "content") {
        return catalog.contentNames();
    }
    std::vector<std::string> scenes;
    std::string::size_type begin = 0;
    while (begin <= text.size()) {
        const auto comma = std::min(text.find(',', begin), text.size());
        const std::string scene = text.substr(begin, comma - begin);
        try {
            (void)catalog.resolve(scene);
        } catch (const SandboxError& error) {
            throw SandboxError(std::string("--soak-scenes: ") + error.what());
        }
        scenes.push_back(scene);
        begin = comma + 1;
    }
    return scenes;
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
    std::optional<std::string> soakScenes;
    std::optional<std::string> imageOption;
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
            imageOption = option;
        } else if (option == "--out") {
            line.out = value();
            headlessOnly = option;
            imageOption = option;
        } else if (option == "--soak") {
            line.soakCycles = parseInt(option, value(), kSoakWarmUpCycles + 1, 100000);
            headlessOnly = option;
        } else if (option == "--soak-scenes") {
            soakScenes = value();
            headlessOnly = option;
        } else if (option == "--ground-truth") {
            line.groundTruth = value();
            headlessOnly = option;
            imageOption = option;
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

    if (line.soakCycles && imageOption) {
        throw SandboxError(*imageOption +
                           " does not apply to --soak (which renders many views and writes none)");
    }
    if (soakScenes && !line.soakCycles) {
        throw SandboxError("--soak-scenes applies to --soak only");
    }
    if (line.soakCycles) {
        line.soakScenes = soakSceneList(soakScenes.value_or("all"), catalog);
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
