#include <shadows/ShadowSettings.h>
#include <shadows/ShadowSettingsSchema.h>

#include <algorithm>

namespace shadows {

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

float depthBiasStep(DepthFormat format) {
    // Receiver depths come from a float matrix product in the lighting pass, stored ones from the
    // rasteriser's own interpolation: measured on the content scenes, they disagree by up to ~2^-18 of the
    // depth range, more than a D24 or D32F step.
    constexpr float kArithmeticStep = 1.0f / 262144.0f;
    return std::max(depthStep(format), kArithmeticStep);
}

std::vector<std::string> ShadowSettings::validate() const {
    std::vector<std::string> problems;
    for (const SettingRow& row : settingsSchema()) {
        if (std::optional<std::string> problem = row.problem(*this)) {
            problems.push_back(std::move(*problem));
        }
    }
    return problems;
}

TapPattern ShadowSettings::tapPattern() const {
    const bool circular = averageGradientForm != AverageGradientForm::LeastSquares &&
                          technique == ShadowTechnique::PcfGsmAverageGradient;
    return TapPattern::make(circular ? TapLayout::Circular8 : pcfLayout, pcfTaps, pcfRadius);
}

} // namespace shadows
