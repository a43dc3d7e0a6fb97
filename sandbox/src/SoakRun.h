#pragma once

#include "CommandLine.h"
#include "SceneCatalog.h"

#include <engine/AddressSanitizer.h>
#include <engine/Components.h>
#include <engine/gl/GlObject.h>

#include <cstddef>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

namespace sandbox {

/// @brief Light types the soak run gives each scene's first light: every engine::LightType.
inline constexpr const auto& kSoakLightTypes = engine::kLightTypes;

/// @brief Cycles of warm-up before the soak's baseline sample: the first compiles programs and fills caches,
/// the second shows the steady state the rest must keep.
inline constexpr int kSoakWarmUpCycles = 2;

#if defined(GS_ADDRESS_SANITIZER)
/// @brief Not judged under AddressSanitizer: freed blocks wait in its quarantine (256 MiB by default) before
/// they are reused, so RSS moves by the size of what was freed last (shadow map arrays are 16-192 MiB) and
/// says nothing about leaks; LeakSanitizer checks those at exit.
inline constexpr double kSoakRssTolerance = std::numeric_limits<double>::infinity();
#else
/// @brief Growth of the trimmed RSS after warm-up that still counts as flat, as a fraction of the baseline
/// sample. The driver keeps caches whose size at a cycle's end depends on where in their own cycle it stops:
/// on llvmpipe one scene's heap toggles between two states 4 MiB apart, and over the content scenes the
/// trimmed RSS spread 6.6 % of itself on the 2-core machine and 5.4 % in a CI run (docs/ROBUSTNESS.md). The
/// allowance does not grow with the run, so a longer soak catches a smaller leak per frame.
inline constexpr double kSoakRssTolerance = 0.10;
#endif

/// @brief What the soak run measured at the end of one cycle (every scene × technique × light type once).
struct SoakSample {
    int cycle = 0;
    std::size_t frames = 0;
    /// RSS after malloc_trim(0), the memory in use. On CPU rasterisers the context keeps freed heap memory
    /// (engine::GlContext::applyAllocatorPolicy), so the untrimmed RSS is a high-water mark that steps up
    /// whenever the heap fragments differently (by 30 MiB once in a corpus run), not only when memory leaks.
    double rssMiB = 0.0;
    /// RSS before trimming, reported beside it.
    double untrimmedRssMiB = 0.0;
    engine::gl::LiveObjectCounts glObjects;
    double seconds = 0.0;
};

/// @brief Whether the samples are flat after warm-up, the first sample (the last warm-up cycle's) being the
/// baseline: trimmed RSS at most `rssTolerance` × the baseline's above it, the live GL objects equal to it
/// kind by kind, no GL error.
struct SoakVerdict {
    double rssGrowthMiB = 0.0;
    double rssToleranceMiB = 0.0;
    long glObjectGrowth = 0;
    std::size_t glErrors = 0;
    /// One line per violated bound; empty when the run passed.
    std::vector<std::string> failures;

    [[nodiscard]] bool passed() const { return failures.empty(); }
};

/// @brief Judges `samples` (at least one) of a soak with `glErrors` GL errors seen.
SoakVerdict judgeSoak(const std::vector<SoakSample>& samples, std::size_t glErrors, double rssTolerance);

/// @brief Resident set size of this process, MiB (/proc/self/statm).
double residentMiB();

/// @brief `gs-sandbox --headless --soak N`: renders the split view `line.soakCycles` times over every scene
/// of `line.soakScenes` × every technique (side A; side B the next technique) × kSoakLightTypes, one frame
/// each, through the same Session as --headless, loading each scene anew every cycle. Checks glGetError after
/// every frame and samples RSS and the live GL objects after every cycle, judging them from the last of the
/// kSoakWarmUpCycles on; prints a line per cycle and a summary to `out`. Returns 0 when judgeSoak passes, 1
/// otherwise. Needs a current GL context.
int runSoak(const CommandLine& line, const SceneCatalog& catalog, std::ostream& out);

} // namespace sandbox
