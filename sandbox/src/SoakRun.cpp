#include "SoakRun.h"

#include "Session.h"

#include <engine/RenderTarget.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>

#include <malloc.h>
#include <unistd.h>

namespace sandbox {

namespace {

std::string describe(const engine::gl::LiveObjectCounts& c) {
    std::ostringstream text;
    text << c.total() << " (buffers " << c.buffers << ", textures " << c.textures << ", framebuffers "
         << c.framebuffers << ", vertex arrays " << c.vertexArrays << ", programs " << c.programs
         << ", shaders " << c.shaders << ", samplers " << c.samplers << ", queries " << c.queries << ")";
    return text.str();
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

} // namespace

SoakVerdict judgeSoak(const std::vector<SoakSample>& samples, std::size_t glErrors, double rssTolerance) {
    SoakVerdict verdict;
    verdict.glErrors = glErrors;
    const SoakSample& baseline = samples.front();
    verdict.rssToleranceMiB = rssTolerance * baseline.rssMiB;
    for (const SoakSample& sample : samples) {
        verdict.rssGrowthMiB = std::max(verdict.rssGrowthMiB, sample.rssMiB - baseline.rssMiB);
        const long growth = sample.glObjects.total() - baseline.glObjects.total();
        if (std::abs(growth) > std::abs(verdict.glObjectGrowth)) {
            verdict.glObjectGrowth = growth;
        }
    }
    if (verdict.rssGrowthMiB > verdict.rssToleranceMiB) {
        verdict.failures.push_back("RSS grew " + fixed(verdict.rssGrowthMiB, 1) +
                                   " MiB after warm-up (tolerance " + fixed(verdict.rssToleranceMiB, 1) +
                                   " MiB)");
    }
    for (const SoakSample& sample : samples) {
        if (sample.glObjects != baseline.glObjects) {
            verdict.failures.push_back(
                "live GL objects changed after warm-up: " + describe(baseline.glObjects) + " after cycle " +
                std::to_string(baseline.cycle) + ", " + describe(sample.glObjects) + " after cycle " +
                std::to_string(sample.cycle));
            break;
        }
    }
    if (glErrors > 0) {
        verdict.failures.push_back(std::to_string(glErrors) + " GL error(s)");
    }
    return verdict;
}

double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    std::size_t sizePages = 0;
    std::size_t residentPages = 0;
    statm >> sizePages >> residentPages;
    return static_cast<double>(residentPages) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
           (1024.0 * 1024.0);
}

namespace {

constexpr int kSoakVirtualFrames = 4;

/// Counts and reports the GL errors raised since the last call, at frame `frame`; `describe()` says what
/// the frame drew (called only when there is an error).
template <typename Describe>
void countGlErrors(std::size_t frame, std::size_t& glErrors, std::ostream& out, Describe&& describe) {
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
        ++glErrors;
        out << "soak: GL error 0x" << std::hex << error << std::dec << " at frame " << frame << " ("
            << describe() << ")" << std::endl;
    }
}

/// Virtual maps under a moving camera and a moving caster: kSoakVirtualFrames frames of the directional
/// light, the camera orbiting and the first mesh sliding, so that pages are marked, evicted, invalidated and
/// drawn every frame; then everything is put back, so each cycle repeats the last.
void soakVirtualMaps(Session& session, engine::RenderTarget& target, std::size_t& frames,
                     std::size_t& glErrors, std::ostream& out) {
    session.scene().setLightType(engine::LightType::Directional);
    SandboxSettings& settings = session.settings();
    const SandboxSettings before = settings;
    settings.a.technique = shadows::ShadowSettings{}.technique;
    settings.b.technique = shadows::ShadowTechnique::Evsm;
    settings.a.mapAllocation = settings.b.mapAllocation = shadows::MapAllocation::Virtual;
    // Small pools: over budget, pages are coarsened and evicted every frame.
    settings.a.virtualBudgetMiB = 4;
    settings.b.virtualBudgetMiB = 8;
    settings.compare = true;
    OrbitCamera orbit = session.scene().fileOrbit();
    for (int frame = 0; frame < kSoakVirtualFrames; ++frame) {
        orbit.yaw += 7.0f;
        settings.camera = orbit;
        session.scene().offsetFirstMesh(
            glm::vec3(0.02f * orbit.distance * static_cast<float>(frame), 0.0f, 0.0f));
        session.render({target.framebuffer().id(), target.size()});
        ++frames;
        countGlErrors(frames, glErrors, out,
                      [] { return std::string("virtual maps, moving camera and caster"); });
    }
    session.scene().offsetFirstMesh(glm::vec3(0.0f));
    settings = before;
}

} // namespace

int runSoak(const CommandLine& line, const SceneCatalog& catalog, std::ostream& out) {
    const std::vector<shadows::ShadowTechnique>& techniques = shadows::allTechniques();
    const std::size_t framesPerCycle =
        line.soakScenes.size() * (techniques.size() * kSoakLightTypes.size() + kSoakVirtualFrames);
    out << "soak: " << *line.soakCycles << " cycles of " << line.soakScenes.size() << " scenes x "
        << techniques.size() << " techniques x " << kSoakLightTypes.size() << " light types, plus "
        << kSoakVirtualFrames
        << " frames of virtual maps under a moving camera and caster per scene = " << framesPerCycle
        << " frames each, " << line.size.x << "x" << line.size.y << "; the first " << kSoakWarmUpCycles
        << " cycles are the warm-up" << std::endl;

    Session session(catalog, line.settings);
    engine::RenderTarget target(line.size);
    std::vector<SoakSample> samples;
    std::size_t glErrors = 0;
    std::size_t frames = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int cycle = 1; cycle <= *line.soakCycles; ++cycle) {
        for (const std::string& scene : line.soakScenes) {
            // A fresh load each cycle: the previous scene's meshes must be released, not accumulated.
            session.loadScene(scene, line.settings.level);
            // Light angles place a spot or point light made from a directional light on the light's orbit
            // (setLightType).
            session.settings().light = session.scene().fileLightAngles();
            for (const engine::LightType lightType : kSoakLightTypes) {
                session.scene().setLightType(lightType);
                for (std::size_t t = 0; t < techniques.size(); ++t) {
                    session.settings().a.technique = techniques[t];
                    session.settings().b.technique = techniques[(t + 1) % techniques.size()];
                    session.settings().compare = true;
                    session.render({target.framebuffer().id(), target.size()});
                    ++frames;
                    countGlErrors(frames, glErrors, out, [&] {
                        return scene + ", " + std::string(engine::toString(lightType)) + ", " +
                               std::string(shadows::toString(techniques[t])) + " | " +
                               std::string(shadows::toString(session.settings().b.technique));
                    });
                }
            }
            soakVirtualMaps(session, target, frames, glErrors, out);
        }
        glFinish();
        SoakSample sample;
        sample.cycle = cycle;
        sample.frames = frames;
        sample.untrimmedRssMiB = residentMiB();
        malloc_trim(0);
        sample.rssMiB = residentMiB();
        sample.glObjects = engine::gl::liveObjectCounts();
        sample.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        out << "soak cycle " << cycle << "/" << *line.soakCycles
            << (cycle <= kSoakWarmUpCycles ? " (warm-up)" : "") << ": " << frames << " frames, RSS "
            << fixed(sample.rssMiB, 1) << " MiB after malloc_trim (" << fixed(sample.untrimmedRssMiB, 1)
            << " before), live GL objects " << describe(sample.glObjects) << ", " << fixed(sample.seconds, 1)
            << " s" << std::endl;
        if (cycle >= kSoakWarmUpCycles) {
            samples.push_back(sample);
        }
    }
    const SoakVerdict verdict = judgeSoak(samples, glErrors, kSoakRssTolerance);
    out << "soak: " << frames << " frames; after warm-up the trimmed RSS grew "
        << fixed(verdict.rssGrowthMiB, 1) << " MiB (tolerance " << fixed(verdict.rssToleranceMiB, 1)
        << " MiB), live GL objects changed by " << verdict.glObjectGrowth << " (tolerance 0), GL errors "
        << glErrors << ": " << (verdict.passed() ? "PASSED" : "FAILED") << std::endl;
    for (const std::string& failure : verdict.failures) {
        out << "soak: FAILED: " << failure << std::endl;
    }
    return verdict.passed() ? 0 : 1;
}

} // namespace sandbox
