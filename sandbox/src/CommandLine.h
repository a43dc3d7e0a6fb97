#pragma once

#include "SandboxSettings.h"
#include "SceneCatalog.h"

#include <glm/vec2.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sandbox {

/// @brief The parsed command line of gs-sandbox: mode, outputs, and the settings to start from (the
/// --settings file, then --scene/--level/--technique/--compare/--shadow-size on top, in that order).
struct CommandLine {
    /// Render to a PNG through EGL instead of opening a window.
    bool headless = false;
    /// Print the usage and exit.
    bool help = false;
    SandboxSettings settings;
    /// The --settings file, if any (the window's save/load path starts there).
    std::optional<std::filesystem::path> settingsFile;
    /// Headless: the PNG to write.
    std::filesystem::path out = "sandbox.png";
    /// Headless: also measure side A against ray-traced ground truth and write the tinted overlay here.
    std::optional<std::filesystem::path> groundTruth;
    /// Windowed: where screenshots go (F12, the button, and after --frames N frames).
    std::optional<std::filesystem::path> screenshot;
    /// Window or image size in pixels.
    glm::ivec2 size{1280, 720};
    /// Frames to render: headless renders this many and writes the last (default 1); the window closes
    /// after this many (default: when closed).
    std::optional<int> frames;
    /// Headless: soak instead of one view, this many cycles over every scene × technique × light type
    /// (SoakRun.h).
    std::optional<int> soakCycles;
    /// Headless soak: the scenes it cycles through (every scene of the catalog unless --soak-scenes).
    std::vector<std::string> soakScenes;
    /// Windowed: show the panels at start (F1 toggles).
    bool showUi = true;

    /// @brief Parses `arguments` (without the program name). Throws SandboxError naming the option for a
    /// bad value, an unknown technique or scene (checked against `catalog`), or a bad settings file.
    static CommandLine parse(std::span<const std::string_view> arguments, const SceneCatalog& catalog);

    /// @brief The --help text.
    static std::string_view usage();
};

} // namespace sandbox
