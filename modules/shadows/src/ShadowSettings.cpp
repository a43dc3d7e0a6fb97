#include <shadows/ShadowSettings.h>
#include <shadows/ShadowTechniqueTraits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace shadows {

namespace {

template <typename Enum, std::size_t N>
std::string_view nameOf(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum value) {
    for (const auto& [entry, name] : table) {
        if (entry == value) {
            return name;
        }
    }
    return "?";
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::array<std::pair<Enum, std::string_view>, N>& table,
                            std::string_view name) {
    for (const auto& [entry, entryName] : table) {
        if (entryName == name) {
            return entry;
        }
    }
    return std::nullopt;
}

constexpr std::array<std::pair<DepthFormat, std::string_view>, 3> kFormatNames{
    {{DepthFormat::D16, "d16"}, {DepthFormat::D24, "d24"}, {DepthFormat::D32F, "d32f"}}};

constexpr std::array<std::pair<GradientSource, std::string_view>, 3> kGradientNames{
    {{GradientSource::StoredDerivatives, "stored"},
     {GradientSource::CentralDifferences, "central"},
     {GradientSource::ScreenSpace, "screen"}}};

constexpr std::array<std::pair<ShadowDebugView, std::string_view>, 7> kDebugNames{
    {{ShadowDebugView::None, "none"},
     {ShadowDebugView::TexelCheckerboard, "texels"},
     {ShadowDebugView::GradientMagnitude, "gradient"},
     {ShadowDebugView::Bias, "bias"},
     {ShadowDebugView::Visibility, "visibility"},
     {ShadowDebugView::ShadowMap, "shadow-map"},
     {ShadowDebugView::FullKernel, "kernel"}}};

} // namespace

std::string_view toString(ShadowTechnique technique) {
    return techniqueTable()[static_cast<std::size_t>(technique)].name;
}
std::optional<ShadowTechnique> techniqueFromString(std::string_view name) {
    for (const ShadowTechniqueTraits& traits : techniqueTable()) {
        if (traits.name == name) {
            return traits.technique;
        }
    }
    return std::nullopt;
}
const std::vector<ShadowTechnique>& allTechniques() {
    static const std::vector<ShadowTechnique> all = [] {
        std::vector<ShadowTechnique> list;
        for (const ShadowTechniqueTraits& traits : techniqueTable()) {
            list.push_back(traits.technique);
        }
        return list;
    }();
    return all;
}
std::string_view toString(DepthFormat format) {
    return nameOf(kFormatNames, format);
}
std::optional<DepthFormat> depthFormatFromString(std::string_view name) {
    return valueOf(kFormatNames, name);
}
std::string_view toString(GradientSource source) {
    return nameOf(kGradientNames, source);
}
std::optional<GradientSource> gradientSourceFromString(std::string_view name) {
    return valueOf(kGradientNames, name);
}
std::string_view toString(ShadowDebugView view) {
    return nameOf(kDebugNames, view);
}
std::optional<ShadowDebugView> debugViewFromString(std::string_view name) {
    return valueOf(kDebugNames, name);
}

float depthStep(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16:
        return 1.0f / 65535.0f;
    case DepthFormat::D24:
        return 1.0f / 16777215.0f;
    case DepthFormat::D32F:
        return 0.0f;
    }
    return 0.0f;
}

std::vector<std::string> ShadowSettings::validate() const {
    std::vector<std::string> problems;
    auto require = [&](bool ok, const std::string& problem) {
        if (!ok) {
            problems.push_back(problem);
        }
    };
    auto finiteAtLeast = [](float value, float low) { return std::isfinite(value) && value >= low; };
    require(resolution >= 64 && resolution <= 16384,
            "resolution " + std::to_string(resolution) + " is outside [64, 16384]");
    require(finiteAtLeast(constantBias, 0.0f), "constantBias must be a finite number >= 0");
    require(finiteAtLeast(slopeScale, 0.0f), "slopeScale must be a finite number >= 0");
    require(finiteAtLeast(slopeUnits, 0.0f), "slopeUnits must be a finite number >= 0");
    require(std::isfinite(pcfRadius) && pcfRadius > 0.0f, "pcfRadius must be a finite number > 0 (texels)");
    require(std::isfinite(fuzzyScale) && fuzzyScale > 0.0f,
            "fuzzyScale must be a finite number > 0 (texels)");
    require(finiteAtLeast(normalOffsetTexels, 0.0f), "normalOffsetTexels must be a finite number >= 0");
    require(momentBlurRadius >= 0 && momentBlurRadius <= 16,
            "momentBlurRadius " + std::to_string(momentBlurRadius) + " is outside [0, 16]");
    require(finiteAtLeast(vsmMinimumVariance, 0.0f), "vsmMinimumVariance must be a finite number >= 0");
    require(std::isfinite(lightBleedingReduction) && lightBleedingReduction >= 0.0f &&
                lightBleedingReduction <= 0.95f,
            "lightBleedingReduction must be in [0, 0.95]");
    require(std::isfinite(msmMomentBias) && msmMomentBias >= 0.0f && msmMomentBias <= 0.5f,
            "msmMomentBias must be in [0, 0.5]");
    require(jitterTaps >= 8 && jitterTaps <= 64 && jitterTaps % 2 == 0,
            "jitterTaps " + std::to_string(jitterTaps) + " must be even and in [8, 64]");
    require(earlyOutTestTaps == 0 || (earlyOutTestTaps >= 4 && earlyOutTestTaps <= 16 &&
                                      earlyOutTestTaps % 2 == 0 && earlyOutTestTaps < jitterTaps),
            "earlyOutTestTaps " + std::to_string(earlyOutTestTaps) +
                " must be 0, or even in [4, 16] and below jitterTaps");
    if (pcfLayout == TapLayout::Grid) {
        require(pcfTaps >= 2 && pcfTaps <= 8,
                "pcfTaps " + std::to_string(pcfTaps) + " is outside [2, 8] for a grid");
    } else if (pcfLayout == TapLayout::Poisson) {
        require(pcfTaps >= 8 && pcfTaps <= 64,
                "pcfTaps " + std::to_string(pcfTaps) + " is outside [8, 64] for a Poisson disk");
    }
    return problems;
}

TapPattern ShadowSettings::tapPattern() const {
    const bool circular = averageGradientForm != AverageGradientForm::LeastSquares &&
                          technique == ShadowTechnique::PcfGsmAverageGradient;
    return TapPattern::make(circular ? TapLayout::Circular8 : pcfLayout, pcfTaps, pcfRadius);
}

} // namespace shadows
