#include <epoxy/gl.h>

#include "WindowApp.h"

#include "ControlPanel.h"
#include "GroundTruthOverlay.h"
#include "ImGuiLayer.h"
#include "ParameterTable.h"
#include "Session.h"

#include <engine/Error.h>
#include <engine/PassTimer.h>
#include <engine/RenderTarget.h>
#include <engine/WindowContext.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Texture.h>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

namespace sandbox {

namespace {

/// Degrees of orbit per pixel of mouse movement.
constexpr float kOrbitDegreesPerPixel = 0.3f;
/// Half-width of the divider's grab zone, pixels.
constexpr float kDividerGrab = 5.0f;

/// True on the frame a key goes down.
class KeyEdge {
public:
    explicit KeyEdge(int key) : key_(key) {}
    bool pressed(GLFWwindow* window) {
        const bool down = glfwGetKey(window, key_) == GLFW_PRESS;
        const bool pressed = down && !wasDown_;
        wasDown_ = down;
        return pressed;
    }

private:
    int key_;
    bool wasDown_ = false;
};

} // namespace

WindowApp::WindowApp(CommandLine line, SceneCatalog catalog)
    : line_(std::move(line)), catalog_(std::move(catalog)) {}

int WindowApp::run() {
    engine::WindowContext window("gs-sandbox", line_.size);
    ImGuiLayer ui(window.window());
    Session session(catalog_, line_.settings);
    for (const std::string& warning : session.scene().warnings()) {
        std::cerr << "gs-sandbox: warning: " << warning << "\n";
    }
    const engine::TimingMethod timing = engine::PassTimer::methodFor(window);
    session.setPassTiming(timing);
    ControlPanel panel(line_.settingsFile.value_or("sandbox.json"),
                       line_.screenshot.value_or("sandbox-screenshot.png"), timing, window.renderer());

    std::optional<engine::RenderTarget> view;
    std::optional<GroundTruthView> truth;
    std::optional<engine::gl::Texture> truthTexture;
    std::optional<engine::gl::Framebuffer> truthFramebuffer;
    FrameReport last;
    bool showUi = line_.showUi;
    KeyEdge toggleUi(GLFW_KEY_F1);
    KeyEdge screenshotKey(GLFW_KEY_F12);
    for (int frame = 0; !line_.frames || frame < *line_.frames; ++frame) {
        if (!window.pollEvents()) {
            break;
        }
        ui.beginFrame();
        if (toggleUi.pressed(window.window())) {
            showUi = !showUi;
        }
        bool screenshot = screenshotKey.pressed(window.window());
        if (showUi) {
            screenshot |= panel.draw(session);
        }
        handleMouse(session);

        const glm::ivec2 size = window.framebufferSize();
        if (size.x > 0 && size.y > 0) { // zero while minimised
            if (!view || view->size() != size) {
                view.emplace(size);
            }
            last = session.render({view->framebuffer().id(), size});
            // A raw copy: with sRGB writes off, blits neither decode nor encode, so the window holds the
            // headless image's bytes.
            glDisable(GL_FRAMEBUFFER_SRGB);
            glBlitNamedFramebuffer(view->framebuffer().id(), 0, 0, 0, size.x, size.y, 0, 0, size.x, size.y,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
            if (panel.takeGroundTruthRequest()) {
                try {
                    truth = measureGroundTruth(session, view->readPixels());
                    // Upload bottom row first, as GL stores images.
                    std::vector<std::uint8_t> rows(truth->overlay.pixels.size());
                    const std::size_t stride = static_cast<std::size_t>(size.x) * 4;
                    for (int y = 0; y < size.y; ++y) {
                        std::copy_n(truth->overlay.pixels.begin() +
                                        static_cast<std::ptrdiff_t>(stride * static_cast<std::size_t>(y)),
                                    stride,
                                    rows.begin() + static_cast<std::ptrdiff_t>(
                                                       stride * static_cast<std::size_t>(size.y - 1 - y)));
                    }
                    truthTexture.emplace(GL_RGBA8, size);
                    glTextureSubImage2D(truthTexture->id(), 0, 0, 0, size.x, size.y, GL_RGBA,
                                        GL_UNSIGNED_BYTE, rows.data());
                    truthFramebuffer.emplace("ground truth overlay");
                    truthFramebuffer->attach(GL_COLOR_ATTACHMENT0, *truthTexture);
                    panel.setStatus("ground truth A: " + GroundTruthView::summary(truth->a) +
                                        (truth->b ? "; B: " + GroundTruthView::summary(*truth->b) : "") +
                                        " (red acne, blue leak, yellow edge band)",
                                    false);
                } catch (const engine::Error& error) {
                    panel.setStatus(error.what(), true);
                }
            }
            if (truth && truth->settings == session.settings() && truth->size == size) {
                glBlitNamedFramebuffer(truthFramebuffer->id(), 0, 0, 0, size.x, size.y, 0, 0, size.x, size.y,
                                       GL_COLOR_BUFFER_BIT, GL_NEAREST);
            }
            const bool lastFrame = line_.frames && frame + 1 == *line_.frames;
            if (screenshot || (lastFrame && line_.screenshot)) {
                const std::filesystem::path path = panel.screenshotPath();
                if (lastFrame) {
                    engine::writePng(path, readWindow(size)); // errors end the run: the caller asked for it
                } else {
                    try {
                        engine::writePng(path, readWindow(size));
                        panel.setStatus("wrote " + path.string(), false);
                    } catch (const engine::IoError& error) {
                        panel.setStatus(error.what(), true);
                    }
                }
            }
        }
        if (showUi) {
            drawDivider(session);
            panel.drawTimings(session, last);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, size.x, size.y);
        ui.render();
        window.swapBuffers();
    }
    return 0;
}

void WindowApp::handleMouse(Session& session) {
    const ImGuiIO& io = ImGui::GetIO();
    SandboxSettings& settings = session.settings();
    const ImVec2 display = io.DisplaySize;
    if (display.x <= 0.0f || display.y <= 0.0f) {
        return;
    }
    const bool nearDivider =
        settings.compare && std::abs(io.MousePos.x - settings.split * display.x) <= kDividerGrab;
    if (drag_ == Drag::None && !io.WantCaptureMouse) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            drag_ = nearDivider ? Drag::Divider : io.KeyShift ? Drag::Pan : Drag::Orbit;
        } else if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
                   ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) {
            drag_ = Drag::Pan;
        }
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right) &&
        !ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
        drag_ = Drag::None;
    }
    if ((nearDivider && !io.WantCaptureMouse) || drag_ == Drag::Divider) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    }
    const float wheel = io.WantCaptureMouse ? 0.0f : io.MouseWheel;
    const ImVec2 delta = io.MouseDelta;
    const bool moved = delta.x != 0.0f || delta.y != 0.0f;
    if (drag_ == Drag::Divider) {
        settings.split =
            std::clamp(io.MousePos.x / display.x, ParameterTable::kSplit.min, ParameterTable::kSplit.max);
        return;
    }
    if ((drag_ == Drag::None || !moved) && wheel == 0.0f) {
        return;
    }
    // The first camera move starts from the file's camera.
    OrbitCamera camera = settings.camera.value_or(session.scene().fileOrbit());
    if (drag_ == Drag::Orbit) {
        camera.orbit(-delta.x * kOrbitDegreesPerPixel, delta.y * kOrbitDegreesPerPixel);
    } else if (drag_ == Drag::Pan) {
        // One view height of mouse travel moves the target by about the visible height at its distance.
        camera.pan(-delta.x / display.y, delta.y / display.y);
    }
    if (wheel != 0.0f) {
        camera.zoom(std::pow(0.9f, wheel));
    }
    settings.camera = camera;
}

void WindowApp::drawDivider(const Session& session) {
    const SandboxSettings& settings = session.settings();
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImU32 white = IM_COL32(255, 255, 255, 220);
    const std::string a = "A  " + std::string(shadows::toString(settings.a.technique));
    if (!settings.compare) {
        draw->AddText(ImVec2(display.x - ImGui::CalcTextSize(a.c_str()).x - 8.0f, 8.0f), white, a.c_str());
        return;
    }
    const float x = std::round(settings.split * display.x);
    draw->AddLine(ImVec2(x, 0.0f), ImVec2(x, display.y), white, 1.0f);
    const std::string b = std::string(shadows::toString(settings.b.technique)) + "  B";
    draw->AddText(ImVec2(x - ImGui::CalcTextSize(a.c_str()).x - 8.0f, 8.0f), white, a.c_str());
    draw->AddText(ImVec2(x + 8.0f, 8.0f), white, b.c_str());
}

engine::Image WindowApp::readWindow(glm::ivec2 size) {
    engine::Image image;
    image.size = size;
    const std::size_t row = static_cast<std::size_t>(size.x) * 4;
    std::vector<std::uint8_t> bottomUp(row * static_cast<std::size_t>(size.y));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    image.pixels.resize(bottomUp.size());
    for (int y = 0; y < size.y; ++y) {
        std::copy_n(
            bottomUp.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(size.y - 1 - y)),
            row, image.pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
    }
    return image;
}

} // namespace sandbox
