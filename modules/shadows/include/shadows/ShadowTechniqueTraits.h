#pragma once

#include <shadows/ShadowSettings.h>

#include <span>
#include <string_view>
#include <vector>

namespace shadows {

/// @brief How the lighting pass samples a technique's shadow map.
enum class MapSampler {
    CompareNearest, ///< sampler2DShadow, one hardware comparison per lookup
    CompareLinear,  ///< sampler2DShadow with LINEAR filtering: hardware 2x2 PCF
    DepthLinear,    ///< sampler2D returning linearly filtered depth (GSM, gathers)
    Moments,        ///< trilinear sampler2D over the blurred, mipmapped moments target (VSM, MSM)
};

/// @brief The strategy table behind ShadowModule: what each technique needs, one row per technique.
struct ShadowTechniqueTraits {
    ShadowTechnique technique;
    /// Stable name for CLIs and files.
    std::string_view name;
    MapSampler sampler;
    /// Lighting-pass defines (besides GS_SHADOWS) that select the technique in shaders/shadows/receiver.glsl.
    std::vector<std::string_view> defines;
    /// Reads a per-fragment depth gradient (ShadowSettings::gradientSource applies).
    bool readsPointGradient;
    /// Uses the PCF tap pattern (pcfLayout, pcfTaps, pcfRadius, pcfRotate apply).
    bool usesTapPattern;
    /// Renders casters with slope-scaled polygon offset.
    bool offsetsCasters;
    /// Moments stored per texel by the shadow pass (0: depth only; 2: VSM; 4: MSM).
    int moments = 0;
};

/// @brief Every technique's row, in ShadowTechnique order.
std::span<const ShadowTechniqueTraits> techniqueTable();

/// @brief The row for `settings.technique`, adjusted by the options that change what it needs (the
/// receiver-plane per-tap kernel; the average gradient's circular-8 forms).
ShadowTechniqueTraits techniqueTraits(const ShadowSettings& settings);

/// @brief Every lighting-pass define `settings` select: technique, gradient source, options and debug view.
std::vector<std::string_view> lightingDefines(const ShadowSettings& settings);

} // namespace shadows
