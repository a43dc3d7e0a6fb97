#include "ControlPanel.h"

#include "ParameterTable.h"
#include "SandboxError.h"

#include <shadows/ShadowPlan.h>

#include <content/ContentError.h>

#include <engine/Components.h>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace sandbox {

namespace {

const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};

void tooltip(std::string_view text) {
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%.*s", static_cast<int>(text.size()), text.data());
    }
}

bool combo(const char* label, int& index, const std::vector<std::string_view>& options) {
    bool changed = false;
    const std::string preview(index >= 0 && index < static_cast<int>(options.size()) ? options[index] : "?");
    if (ImGui::BeginCombo(label, preview.c_str())) {
        for (int i = 0; i < static_cast<int>(options.size()); ++i) {
            if (ImGui::Selectable(std::string(options[i]).c_str(), i == index)) {
                changed = changed || i != index;
                index = i;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

/// Draws the control of one schema row; returns true when the value changed.
bool drawRow(const shadows::SettingRow& row, shadows::ShadowSettings& settings) {
    const std::string label = row.labelWithUnit();
    bool changed = false;
    if (const auto* real = std::get_if<shadows::FloatSetting>(&row.field)) {
        changed =
            ImGui::SliderFloat(label.c_str(), &(settings.*real->member), real->sliderMin, real->sliderMax,
                               real->format, real->logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
    } else if (const auto* integer = std::get_if<shadows::IntSetting>(&row.field)) {
        // The slider moves through the offered values; it shows the value itself.
        int& value = settings.*integer->member;
        const std::vector<int> values = ParameterTable::offeredValues(*integer, settings);
        const int nearest = ParameterTable::nearest(values, value);
        int index = static_cast<int>(std::find(values.begin(), values.end(), nearest) - values.begin());
        const std::string shown = std::to_string(value);
        if (ImGui::SliderInt(label.c_str(), &index, 0, static_cast<int>(values.size()) - 1, shown.c_str(),
                             ImGuiSliderFlags_NoInput)) {
            value =
                values[static_cast<std::size_t>(std::clamp(index, 0, static_cast<int>(values.size()) - 1))];
            changed = true;
        }
    } else if (const auto* toggle = std::get_if<shadows::BoolSetting>(&row.field)) {
        changed = ImGui::Checkbox(label.c_str(), &(settings.*toggle->member));
    } else if (const auto* choice = std::get_if<shadows::EnumSetting>(&row.field)) {
        int index = choice->get(settings);
        if (combo(label.c_str(), index, choice->names)) {
            choice->set(settings, index);
            changed = true;
        }
    }
    tooltip(row.help);
    return changed;
}

std::string uses(const shadows::ShadowSettings& settings) {
    const shadows::ShadowPlan plan = shadows::ShadowPlan::resolve(settings);
    std::string text;
    switch (plan.sampler) {
    case shadows::MapSampler::CompareNearest:
        text = "hardware compare";
        break;
    case shadows::MapSampler::CompareLinear:
        text = "hardware 2x2 PCF";
        break;
    case shadows::MapSampler::DepthLinear:
        text = "filtered depth";
        break;
    case shadows::MapSampler::Moments:
        text = plan.momentsFormat == GL_RG32F ? "2 filtered moments" : "4 filtered moments";
        break;
    case shadows::MapSampler::MomentMips:
        text = "4 moments filtered over their mip chain";
        break;
    }
    if (plan.usesTapPattern) {
        text += ", tap pattern";
    }
    if (plan.traits->readsPointGradient) {
        text += ", point gradient";
    }
    if (plan.offsetsCasters) {
        text += ", caster polygon offset";
    }
    return text;
}

double smooth(double previous, double sample) {
    if (sample < 0.0) {
        return -1.0;
    }
    return previous < 0.0 ? sample : previous + 0.1 * (sample - previous);
}

} // namespace

ControlPanel::ControlPanel(std::filesystem::path settingsPath, std::filesystem::path screenshotPath,
                           engine::TimingMethod timing, std::string renderer)
    : settingsPath_(settingsPath.string()), screenshotPath_(screenshotPath.string()), timing_(timing),
      renderer_(std::move(renderer)) {}

void ControlPanel::setStatus(std::string message, bool error) {
    status_ = std::move(message);
    statusIsError_ = error;
}

bool ControlPanel::draw(Session& session) {
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(440.0f, ImGui::GetIO().DisplaySize.y - 16.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    bool screenshot = false;
    if (ImGui::Begin("gs-sandbox  (F1 hides)")) {
        // Controls take half the panel; the labels (with their units) the other half.
        ImGui::PushItemWidth(ImGui::GetWindowWidth() * 0.5f);
        drawScene(session);
        drawLightAndCamera(session);
        drawView(session);
        SandboxSettings& settings = session.settings();
        if (ImGui::CollapsingHeader(settings.compare ? "A (left)" : "A", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawSide("A", settings.a);
        }
        if (settings.compare && ImGui::CollapsingHeader("B (right)", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawSide("B", settings.b);
        }
        if (ImGui::CollapsingHeader("Files", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawFiles(session);
            ImGui::InputText("screenshot", &screenshotPath_);
            screenshot = ImGui::Button("Screenshot (F12)");
            ImGui::SameLine();
            // Ray casting the view takes a moment: on demand only; the tint stays while the view is
            // unchanged.
            groundTruthRequested_ = ImGui::Button("Ground truth") || groundTruthRequested_;
        }
        if (!status_.empty()) {
            ImGui::PushTextWrapPos(0.0f);
            if (statusIsError_) {
                ImGui::TextColored(kErrorColor, "%s", status_.c_str());
            } else {
                ImGui::TextUnformatted(status_.c_str());
            }
            ImGui::PopTextWrapPos();
        }
        ImGui::PopItemWidth();
    }
    ImGui::End();
    return screenshot;
}

void ControlPanel::drawScene(Session& session) {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    SandboxSettings& settings = session.settings();
    auto load = [&](const std::string& scene, int level) {
        try {
            session.loadScene(scene, level);
            setStatus("loaded " + scene, false);
        } catch (const SandboxError& error) {
            setStatus(error.what(), true);
        } catch (const content::ContentError& error) {
            setStatus(error.what(), true);
        }
    };
    if (ImGui::BeginCombo("scene", settings.scene.c_str())) {
        for (const std::string& name : session.catalog().names()) {
            if (ImGui::Selectable(name.c_str(), name == settings.scene) && name != settings.scene) {
                load(name, settings.level);
            }
        }
        ImGui::EndCombo();
    }
    ImGui::InputTextWithHint("##path", "path/to/scene.gltf", &scenePath_);
    ImGui::SameLine();
    if (ImGui::Button("Load glTF") && !scenePath_.empty()) {
        load(scenePath_, settings.level);
    }
    int level = settings.level;
    ImGui::SliderInt("subdivision", &level, ParameterTable::kLevel.min, ParameterTable::kLevel.max,
                     level < 0 ? "file's own" : "level %d");
    tooltip("Subdivision level of every subdivided mesh; reloads the scene when released.");
    // Reload once the slider is let go: every level is a full reload and refinement.
    if (ImGui::IsItemDeactivatedAfterEdit() && level != settings.level) {
        load(settings.scene, level);
    }
    ImGui::Text("%zu triangles", session.scene().triangles());
    for (const std::string& warning : session.scene().warnings()) {
        ImGui::TextColored(kErrorColor, "%s", warning.c_str());
    }
}

void ControlPanel::drawLightAndCamera(Session& session) {
    if (!ImGui::CollapsingHeader("Light and camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    SandboxSettings& settings = session.settings();
    SandboxSettings::LightAngles angles = settings.light.value_or(session.scene().fileLightAngles());
    bool lightChanged = ImGui::SliderFloat("azimuth (deg)", &angles.azimuth, ParameterTable::kAzimuth.min,
                                           ParameterTable::kAzimuth.max, "%.1f");
    lightChanged |= ImGui::SliderFloat("elevation (deg)", &angles.elevation, ParameterTable::kElevation.min,
                                       ParameterTable::kElevation.max, "%.2f", ImGuiSliderFlags_Logarithmic);
    tooltip("Down to 0.5 degrees: grazing light. Logarithmic, so low angles get most of the slider.");
    if (lightChanged) {
        angles.azimuth =
            std::clamp(angles.azimuth, ParameterTable::kAzimuth.min, ParameterTable::kAzimuth.max);
        angles.elevation =
            std::clamp(angles.elevation, ParameterTable::kElevation.min, ParameterTable::kElevation.max);
        settings.light = angles;
    }
    std::vector<std::string_view> typeNames;
    int typeIndex = 0;
    for (std::size_t i = 0; i < engine::kLightTypes.size(); ++i) {
        typeNames.emplace_back(engine::toString(engine::kLightTypes[i]));
        typeIndex = engine::kLightTypes[i] == session.scene().lightType() ? static_cast<int>(i) : typeIndex;
    }
    if (combo("light type", typeIndex, typeNames)) {
        session.scene().setLightType(engine::kLightTypes[static_cast<std::size_t>(typeIndex)]);
        // A converted light is placed by the angles: the file's transform of a sun may sit anywhere.
        settings.light = angles;
    }
    tooltip("The file's first light, or a conversion of it: a spot gets a cone just covering the scene, and "
            "a sun's intensity is scaled by the distance squared, so the scene's centre stays as bright.");
    const bool sun = session.scene().lightType() == engine::LightType::Directional;
    float size = sun ? glm::degrees(session.scene().lightSize()) : session.scene().lightSize();
    if (ImGui::SliderFloat(sun ? "light size (deg)" : "light radius", &size, 0.0f, sun ? 10.0f : 1.0f,
                           sun ? "%.2f" : "%.3f", ImGuiSliderFlags_Logarithmic)) {
        session.scene().setLightSize(sun ? glm::radians(size) : size);
    }
    tooltip("The light's size, for soft shadows (pcss) and their ray-traced truth: a sun's angular diameter "
            "(the real sun's is 0.53 degrees), a spot or point light's radius in world units; 0 casts hard "
            "shadows.");
    ImGui::Text("light %s", settings.light ? "at the angles above" : "as in the file");
    ImGui::SameLine();
    if (ImGui::Button("file's light")) {
        settings.light.reset();
        session.scene().setLightType(session.scene().fileLightType());
    }
    const OrbitCamera camera = settings.camera.value_or(session.scene().fileOrbit());
    ImGui::Text("camera yaw %.1f, pitch %.1f, distance %.2f%s", static_cast<double>(camera.yaw),
                static_cast<double>(camera.pitch), static_cast<double>(camera.distance),
                settings.camera ? "" : " (file's)");
    ImGui::TextDisabled("drag: orbit; right/middle or shift+drag: pan; wheel: zoom");
    if (ImGui::Button("file's camera")) {
        settings.camera.reset();
    }
}

void ControlPanel::drawView(Session& session) {
    if (!ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    SandboxSettings& settings = session.settings();
    ImGui::Checkbox("split screen A | B", &settings.compare);
    if (settings.compare) {
        ImGui::SliderFloat("divider", &settings.split, ParameterTable::kSplit.min, ParameterTable::kSplit.max,
                           "%.2f", ImGuiSliderFlags_AlwaysClamp);
        tooltip("Or drag the line in the view.");
    }
    bool timing = session.passTiming().has_value();
    if (ImGui::Checkbox("time passes", &timing)) {
        // Timing waits for the GPU after each pass: switch it off to see the frame rate without those waits.
        session.setPassTiming(timing ? std::optional(timing_) : std::nullopt);
    }
}

void ControlPanel::drawSide(const char* id, shadows::ShadowSettings& settings) {
    ImGui::PushID(id);
    shadows::ShadowSettings edited = settings;
    bool changed = drawRow(*shadows::findSetting("technique"), edited);
    ImGui::TextDisabled("uses: %s", uses(edited).c_str());
    for (const shadows::SettingRow& row : ParameterTable::shadowRows()) {
        if (row.applies(edited)) {
            changed |= drawRow(row, edited);
        }
    }
    if (changed) {
        ParameterTable::repairIntegers(edited);
        const std::vector<std::string> problems = edited.validate();
        if (problems.empty()) {
            settings = edited;
        } else {
            setStatus(std::string(id) + ": " + problems.front(), true);
        }
    }
    ImGui::PopID();
}

void ControlPanel::drawFiles(Session& session) {
    ImGui::InputText("settings", &settingsPath_);
    if (ImGui::Button("Save")) {
        try {
            session.settings().save(settingsPath_);
            setStatus("saved " + settingsPath_, false);
        } catch (const engine::Error& error) {
            setStatus(error.what(), true);
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Load")) {
        try {
            const SandboxSettings loaded = SandboxSettings::load(settingsPath_);
            session.loadScene(loaded.scene, loaded.level);
            session.settings() = loaded;
            setStatus("loaded " + settingsPath_, false);
        } catch (const engine::Error& error) {
            setStatus(error.what(), true);
        }
    }
}

void ControlPanel::drawTimings(const Session& session, const FrameReport& last) {
    const SideStats* sides[2] = {&last.a, last.b ? &*last.b : nullptr};
    for (int side = 0; side < 2; ++side) {
        if (sides[side]) {
            smoothed_[side][0] = smooth(smoothed_[side][0], sides[side]->frame.prePassMilliseconds);
            smoothed_[side][1] = smooth(smoothed_[side][1], sides[side]->frame.lightingMilliseconds);
        }
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 8.0f, display.y - 8.0f), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings;
    if (ImGui::Begin("timings", nullptr, flags)) {
        const SandboxSettings& settings = session.settings();
        const shadows::ShadowSettings* techniques[2] = {&settings.a, &settings.b};
        for (int side = 0; side < 2; ++side) {
            if (!sides[side]) {
                continue;
            }
            const std::string name(shadows::toString(techniques[side]->technique));
            if (smoothed_[side][0] < 0.0) {
                ImGui::Text("%c %-18s timing off", side == 0 ? 'A' : 'B', name.c_str());
                continue;
            }
            ImGui::Text("%c %-18s shadow pass %6.2f ms   lighting %6.2f ms   maps %.1f MiB",
                        side == 0 ? 'A' : 'B', name.c_str(), smoothed_[side][0], smoothed_[side][1],
                        static_cast<double>(sides[side]->shadows.bytes) / (1024.0 * 1024.0));
            if (const shadows::ShadowStats& stats = sides[side]->shadows; stats.virtualMaps) {
                const shadows::VirtualPageStats& pages = stats.pages;
                ImGui::Text("  pages: %d requested, %d drawn, %d cached, %d of %d resident%s",
                            pages.requested, pages.rendered, pages.cached, pages.resident, pages.poolPages,
                            pages.coarsened + pages.refused > 0 ? "  OVER BUDGET" : "");
                if (pages.coarsened + pages.refused > 0) {
                    ImGui::Text("  %d requests at coarser levels, %d without texels (lit)", pages.coarsened,
                                pages.refused);
                }
            }
        }
        if (const auto method = session.passTiming()) {
            const std::string described(engine::PassTimer::describe(*method));
            ImGui::TextDisabled("%s, averaged; %s", described.c_str(), renderer_.c_str());
            if (last.b) {
                ImGui::TextDisabled("lighting covers its own side of the divider only");
            }
        }
    }
    ImGui::End();
}

} // namespace sandbox
