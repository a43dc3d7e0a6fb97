#include "HeadlessApp.h"

#include "GroundTruthOverlay.h"
#include "Session.h"
#include "SoakRun.h"

#include <engine/HeadlessContext.h>
#include <engine/Image.h>
#include <engine/PassTimer.h>
#include <engine/RenderTarget.h>

#include <iostream>

namespace sandbox {

namespace {

void printSide(const char* label, const shadows::ShadowSettings& settings, const SideStats& stats) {
    std::cout << "  " << label << ' ' << shadows::toString(settings.technique) << ": shadow pass "
              << stats.frame.prePassMilliseconds << " ms, lighting " << stats.frame.lightingMilliseconds
              << " ms, " << stats.shadows.shadowMaps << " shadow map(s)";
    if (stats.shadows.virtualMaps) {
        const shadows::VirtualPageStats& pages = stats.shadows.pages;
        std::cout << ", pages " << pages.requested << " requested, " << pages.rendered << " drawn, "
                  << pages.cached << " cached, " << pages.coarsened << " coarsened, " << pages.refused
                  << " refused";
    }
    std::cout << '\n';
}

} // namespace

HeadlessApp::HeadlessApp(CommandLine line, SceneCatalog catalog)
    : line_(std::move(line)), catalog_(std::move(catalog)) {}

int HeadlessApp::run() {
    engine::HeadlessContext context;
    if (line_.soakCycles) {
        return runSoak(line_, catalog_, std::cout);
    }
    Session session(catalog_, line_.settings);
    for (const std::string& warning : session.scene().warnings()) {
        std::cerr << "gs-sandbox: warning: " << warning << "\n";
    }
    const engine::TimingMethod timing = engine::PassTimer::methodFor(context);
    session.setPassTiming(timing);
    engine::RenderTarget target(line_.size);
    FrameReport report;
    for (int frame = 0; frame < line_.frames.value_or(1); ++frame) {
        report = session.render({target.framebuffer().id(), target.size()});
    }
    const engine::Image image = target.readPixels();
    engine::writePng(line_.out, image);

    const SandboxSettings& settings = session.settings();
    std::cout << "wrote " << line_.out.string() << " (" << line_.size.x << "x" << line_.size.y << ", "
              << settings.scene << ", " << session.scene().triangles() << " triangles, " << context.renderer()
              << ")\n";
    printSide("A", settings.a, report.a);
    if (report.b) {
        printSide("B", settings.b, *report.b);
    }
    std::cout << "  timing: " << engine::PassTimer::describe(timing) << ", last of "
              << line_.frames.value_or(1) << " frame(s)\n";
    if (line_.groundTruth) {
        const GroundTruthView truth = measureGroundTruth(session, image);
        engine::writePng(*line_.groundTruth, truth.overlay);
        std::cout << "  ground truth (A): " << GroundTruthView::summary(truth.a) << "\n";
        if (truth.b) {
            std::cout << "  ground truth (B): " << GroundTruthView::summary(*truth.b) << "\n";
        }
        std::cout << "  overlay " << line_.groundTruth->string() << "\n";
    }
    return 0;
}

} // namespace sandbox
