#pragma once

#include "CommandLine.h"
#include "SceneCatalog.h"

#include <engine/Components.h>
#include <engine/gl/GlObject.h>

#include <array>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace sandbox {

/// @brief Light types the soak run gives each scene's first light. Add new engine::LightType values here.
inline constexpr std::array kSoakLightTypes{engine::LightType::Directional, engine::LightType::Spot};

/// @brief Cycles of warm-up before the soak's baseline sample: the first compiles programs and fills caches;
/// in the second the driver's and the allocator's caches still settle (a 64x48 run over the corpus grew 26
/// MiB from the first cycle to the second, then 0.4 MiB over six more; docs/ROBUSTNESS.md).
inline constexpr int kSoakWarmUpCycles = 2;

/// @brief Process RSS growth after warm-up that still counts as flat, MiB: allocator and driver caches move
/// by a few MiB from one cycle to the next (docs/ROBUSTNESS.md has the measured spread).
inline constexpr double kSoakRssToleranceMiB = 8.0;

/// @brief What the soak run measured at the end of one cycle (every scene × technique × light type once).
struct SoakSample {
    int cycle = 0;
    std::size_t frames = 0;
    double rssMiB = 0.0;
    engine::gl::LiveObjectCounts glObjects;
    double seconds = 0.0;
};

/// @brief Whether the samples are flat after warm-up (the first sample, the last warm-up cycle's, is the
/// baseline): RSS at most
/// `rssToleranceMiB` above the baseline, the live GL objects equal to it, no GL error.
struct SoakVerdict {
    double rssGrowthMiB = 0.0;
    long glObjectGrowth = 0;
    std::size_t glErrors = 0;
    /// One line per violated bound; empty when the run passed.
    std::vector<std::string> failures;

    [[nodiscard]] bool passed() const { return failures.empty(); }
};

/// @brief Judges `samples` (at least one) of a soak with `glErrors` GL errors seen.
SoakVerdict judgeSoak(const std::vector<SoakSample>& samples, std::size_t glErrors, double rssToleranceMiB);

/// @brief Resident set size of this process, MiB (/proc/self/statm).
double residentMiB();

/// @brief `gs-sandbox --headless --soak N`: renders the split view `line.soakCycles` times over every scene
/// of `line.soakScenes` × every technique (side A; side B the next technique) × kSoakLightTypes, one frame
/// each, through the same Session as --headless, loading each scene anew every cycle. Checks glGetError after
/// every frame and samples RSS and the live GL objects after every cycle; prints a line per cycle and a
/// summary to `out`. Returns 0 when judgeSoak passes, 1 otherwise. Needs a current GL context.
int runSoak(const CommandLine& line, const SceneCatalog& catalog, std::ostream& out);

} // namespace sandbox
