#pragma once

#include "CommandLine.h"
#include "SceneCatalog.h"

namespace sandbox {

/// @brief `gs-sandbox --headless`: renders the view the window would show (same Session, same settings)
/// into an offscreen sRGB target through EGL and writes it as PNG.
class HeadlessApp {
public:
    HeadlessApp(CommandLine line, SceneCatalog catalog);

    /// @brief Renders --frames frames, writes the last to --out and prints what it wrote with the passes'
    /// timings (and both sides' ground-truth metrics with --ground-truth); with --soak, runs the soak instead
    /// (runSoak). Returns the exit status; throws engine::Error (context, content, I/O) for the caller to
    /// report.
    int run();

private:
    CommandLine line_;
    SceneCatalog catalog_;
};

} // namespace sandbox
