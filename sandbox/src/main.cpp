// gs-sandbox: explore shadow techniques side by side, in a window (GLFW + Dear ImGui) or headless (EGL).
#include "CommandLine.h"
#include "HeadlessApp.h"
#include "SandboxError.h"
#include "SceneCatalog.h"
#include "WindowApp.h"

#include <engine/Error.h>

#include <iostream>
#include <string_view>
#include <vector>

int main(int argc, char** argv) {
    // Exit status 2: bad input (options, settings file, scene name); 1: the run failed (no display or GL
    // context, unreadable scene, unwritable output).
    try {
        const sandbox::SceneCatalog catalog(GS_CONTENT_DIR);
        const std::vector<std::string_view> arguments(argv + 1, argv + argc);
        sandbox::CommandLine line;
        try {
            line = sandbox::CommandLine::parse(arguments, catalog);
        } catch (const sandbox::SandboxError& error) {
            std::cerr << "gs-sandbox: " << error.what() << "\n(gs-sandbox --help lists the options)\n";
            return 2;
        }
        if (line.help) {
            std::cout << sandbox::CommandLine::usage() << "\n";
            return 0;
        }
        if (line.headless) {
            return sandbox::HeadlessApp(std::move(line), catalog).run();
        }
        return sandbox::WindowApp(std::move(line), catalog).run();
    } catch (const engine::Error& error) {
        std::cerr << "gs-sandbox: " << error.what() << "\n";
        return 1;
    }
}
