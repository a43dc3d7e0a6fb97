#include <shadows/ShadowSettings.h>
#include <shadows/ShadowSettingsSchema.h>
#include <shadows/VirtualPages.h>

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
    // A float depth in [0.5, 1) is rounded to 2^-24: a perspective map stores most depths there.
    constexpr float kFloatStepBelowOne = 1.0f / 16777216.0f;
    return std::max(depthStep(format), kFloatStepBelowOne);
}

std::vector<std::string> ShadowSettings::validate() const {
    std::vector<std::string> problems;
    for (const SettingRow& row : settingsSchema()) {
        if (std::optional<std::string> problem = row.problem(*this)) {
            problems.push_back(std::move(*problem));
        }
    }
    if (problems.empty() && mapAllocation == MapAllocation::Virtual) {
        const ShadowPlan plan = ShadowPlan::resolve(*this);
        const std::size_t tile = virtualTileBytes(plan, virtualPageSize);
        const std::size_t requests = virtualOverheadBytes(virtualPageSize, 0);
        if ((static_cast<std::size_t>(virtualBudgetMiB) << 20) < tile + requests) {
            problems.push_back("virtualBudgetMiB " + std::to_string(virtualBudgetMiB) +
                               " holds no page: one page of this technique with its border takes " +
                               std::to_string(tile) + " bytes, the page requests " +
                               std::to_string(requests));
        }
    }
    return problems;
}

TapPattern ShadowSettings::tapPattern() const {
    return TapPattern::make(usesCircular8Average() ? TapLayout::Circular8 : pcfLayout, pcfTaps, pcfRadius);
}

bool ShadowSettings::usesCircular8Average() const {
    return technique == ShadowTechnique::PcfGsmAverageGradient &&
           averageGradientForm != AverageGradientForm::LeastSquares;
}

} // namespace shadows
