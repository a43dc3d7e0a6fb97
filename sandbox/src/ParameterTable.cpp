#include "ParameterTable.h"

#include <shadows/ShadowTechniqueTraits.h>

#include <algorithm>
#include <cstdlib>

namespace sandbox {

namespace {

using shadows::ShadowSettings;
using shadows::ShadowTechnique;

template <typename Enum>
ParameterTable::ChoiceField choice(Enum ShadowSettings::*member, std::vector<std::string> options) {
    return {std::move(options), [member](const ShadowSettings& s) { return static_cast<int>(s.*member); },
            [member](ShadowSettings& s, int index) { s.*member = static_cast<Enum>(index); }};
}

template <typename Enum, std::size_t N>
std::vector<std::string> namesOf(const Enum (&values)[N]) {
    std::vector<std::string> names;
    for (const Enum value : values) {
        names.emplace_back(shadows::toString(value));
    }
    return names;
}

/// low, low + step, ..., up to high.
std::vector<int> steps(int low, int high, int step) {
    std::vector<int> values;
    for (int value = low; value <= high; value += step) {
        values.push_back(value);
    }
    return values;
}

std::vector<int> powersOfTwo(int low, int high) {
    std::vector<int> values;
    for (int value = low; value <= high; value *= 2) {
        values.push_back(value);
    }
    return values;
}

bool always(const ShadowSettings&) {
    return true;
}
bool usesTaps(const ShadowSettings& s) {
    return shadows::techniqueTraits(s).usesTapPattern;
}
/// The circular-8 forms of the average gradient bring their own 8-tap layout (ShadowSettings::tapPattern).
bool layoutForced(const ShadowSettings& s) {
    return s.technique == ShadowTechnique::PcfGsmAverageGradient &&
           s.averageGradientForm != shadows::AverageGradientForm::LeastSquares;
}
bool isGsm(const ShadowSettings& s) {
    switch (s.technique) {
    case ShadowTechnique::Gsm:
    case ShadowTechnique::PcfGsmNaive:
    case ShadowTechnique::PcfGsmPointGradient:
    case ShadowTechnique::PcfGsmAverageGradient:
    case ShadowTechnique::PcfGsmQuadratic:
        return true;
    default:
        return false;
    }
}
auto techniqueIs(ShadowTechnique technique) {
    return [technique](const ShadowSettings& s) { return s.technique == technique; };
}
auto techniqueIsOneOf(ShadowTechnique first, ShadowTechnique second) {
    return [first, second](const ShadowSettings& s) { return s.technique == first || s.technique == second; };
}

std::vector<ParameterTable::Row> makeRows() {
    using T = ParameterTable;
    using shadows::DepthFormat;
    using shadows::GradientSource;
    using shadows::ShadowDebugView;
    const DepthFormat formats[] = {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F};
    const GradientSource sources[] = {GradientSource::StoredDerivatives, GradientSource::CentralDifferences,
                                      GradientSource::ScreenSpace};
    const ShadowDebugView views[] = {
        ShadowDebugView::None,      ShadowDebugView::TexelCheckerboard, ShadowDebugView::GradientMagnitude,
        ShadowDebugView::Bias,      ShadowDebugView::Visibility,        ShadowDebugView::ShadowMap,
        ShadowDebugView::FullKernel};
    return {
        {"resolution", "shadow map (texels)", "Width and height of the shadow map.",
         T::IntField{&ShadowSettings::resolution,
                     [](const ShadowSettings&) { return powersOfTwo(64, 8192); }},
         always},
        {"depthFormat", "depth format", "Depth format of the shadow map.",
         choice(&ShadowSettings::depthFormat, namesOf(formats)), always},
        {"casterFaces", "caster faces", "Faces (as seen from the light) drawn into the shadow map.",
         choice(&ShadowSettings::casterFaces, {"front", "back"}), always},
        {"constantBias", "constant bias (world)", "Receiver moved towards the light before the comparison.",
         T::FloatField{&ShadowSettings::constantBias, {0.0f, 0.1f}, "%.5f", true}, always},
        {"slopeScale", "slope scale", "glPolygonOffset factor on the casters (scales their depth slope).",
         T::FloatField{&ShadowSettings::slopeScale, {0.0f, 8.0f}, "%.2f", false},
         [](const ShadowSettings& s) { return shadows::techniqueTraits(s).offsetsCasters; }},
        {"slopeUnits", "slope units", "glPolygonOffset units (multiples of the format's resolvable step).",
         T::FloatField{&ShadowSettings::slopeUnits, {0.0f, 16.0f}, "%.2f", false},
         [](const ShadowSettings& s) { return shadows::techniqueTraits(s).offsetsCasters; }},
        {"averageGradientForm", "average gradient form",
         "Least squares over any pattern, or the reference's circular-8 forms (which bring their own "
         "layout).",
         choice(&ShadowSettings::averageGradientForm, {"least-squares", "circular8", "circular8-vec4"}),
         techniqueIs(ShadowTechnique::PcfGsmAverageGradient)},
        {"pcfLayout", "PCF layout", "Layout of the PCF taps.",
         choice(&ShadowSettings::pcfLayout, {"grid", "poisson", "circular8"}),
         [](const ShadowSettings& s) { return usesTaps(s) && !layoutForced(s); }},
        {"pcfTaps", "PCF taps", "Taps per side of a grid, or the number of Poisson taps.",
         T::IntField{&ShadowSettings::pcfTaps,
                     [](const ShadowSettings& s) {
                         return s.pcfLayout == shadows::TapLayout::Poisson ? steps(8, 64, 1) : steps(2, 8, 1);
                     }},
         [](const ShadowSettings& s) {
             return usesTaps(s) && !layoutForced(s) && s.pcfLayout != shadows::TapLayout::Circular8;
         }},
        {"pcfRadius", "PCF radius (texels)", "Radius of the tap pattern.",
         T::FloatField{&ShadowSettings::pcfRadius, {0.5f, 8.0f}, "%.2f", false},
         [](const ShadowSettings& s) { return usesTaps(s) || s.technique == ShadowTechnique::JitteredPcf; }},
        {"pcfRotate", "rotate pattern per pixel", "Trades banding for noise (interleaved gradient noise).",
         T::ToggleField{&ShadowSettings::pcfRotate}, usesTaps},
        {"gradientSource", "gradient source", "Where the fragment's depth gradient comes from.",
         choice(&ShadowSettings::gradientSource, namesOf(sources)),
         [](const ShadowSettings& s) { return shadows::techniqueTraits(s).readsPointGradient; }},
        {"fuzzyScale", "fuzzy scale (texels)", "Width of the GSM fuzzy comparison band.",
         T::FloatField{&ShadowSettings::fuzzyScale, {0.1f, 8.0f}, "%.2f", true}, isGsm},
        {"receiverPlaneKernel", "receiver-plane kernel", "2x2 bilinear gather, or one bias per PCF tap.",
         choice(&ShadowSettings::receiverPlaneKernel, {"bilinear2x2", "per-tap"}),
         techniqueIs(ShadowTechnique::ReceiverPlaneBias)},
        {"receiverPlaneClamp", "clamp bias to min(0, bias)",
         "Only let the bias move receivers towards the light.",
         T::ToggleField{&ShadowSettings::receiverPlaneClamp},
         techniqueIs(ShadowTechnique::ReceiverPlaneBias)},
        {"normalOffsetTexels", "normal offset (texels)", "Receiver pushed along its normal, in texel sizes.",
         T::FloatField{&ShadowSettings::normalOffsetTexels, {0.0f, 8.0f}, "%.2f", false},
         techniqueIs(ShadowTechnique::NormalOffset)},
        {"floorReceiverDepth", "floor receiver depth",
         "Floor the reference to the format's step so the hardware comparison's rounding adds no acne.",
         T::ToggleField{&ShadowSettings::floorReceiverDepth},
         [](const ShadowSettings& s) {
             const shadows::MapSampler sampler = shadows::techniqueTraits(s).sampler;
             return sampler == shadows::MapSampler::CompareNearest ||
                    sampler == shadows::MapSampler::CompareLinear;
         }},
        {"momentBlurRadius", "moment blur (texels)", "Half-width of the box blur of the moments.",
         T::IntField{&ShadowSettings::momentBlurRadius,
                     [](const ShadowSettings&) { return steps(0, 16, 1); }},
         techniqueIsOneOf(ShadowTechnique::Vsm, ShadowTechnique::Msm)},
        {"vsmMinimumVariance", "minimum variance",
         "Smallest variance the Chebyshev bound uses (depth units squared).",
         T::FloatField{&ShadowSettings::vsmMinimumVariance, {0.0f, 1e-3f}, "%.2e", true},
         techniqueIs(ShadowTechnique::Vsm)},
        {"lightBleedingReduction", "light-bleeding reduction", "Tail of the Chebyshev bound cut off.",
         T::FloatField{&ShadowSettings::lightBleedingReduction, {0.0f, 0.95f}, "%.2f", false},
         techniqueIs(ShadowTechnique::Vsm)},
        {"msmMomentBias", "moment bias",
         "Bias of the moments towards (0, 0.63, 0, 0.63); more hides trouble, leaks.",
         T::FloatField{&ShadowSettings::msmMomentBias, {0.0f, 0.05f}, "%.2e", true},
         techniqueIs(ShadowTechnique::Msm)},
        {"msmQuantize16", "16-bit moments", "Store the moments in 16-bit unorm through the optimised basis.",
         T::ToggleField{&ShadowSettings::msmQuantize16}, techniqueIs(ShadowTechnique::Msm)},
        {"jitterTaps", "jittered taps", "Stratified taps per pixel (two per jitter texel).",
         T::IntField{&ShadowSettings::jitterTaps, [](const ShadowSettings&) { return steps(8, 64, 2); }},
         techniqueIs(ShadowTechnique::JitteredPcf)},
        {"earlyOutTestTaps", "early-out test taps (0: off)",
         "Taps taken before deciding whether the pixel needs the full kernel.",
         T::IntField{&ShadowSettings::earlyOutTestTaps,
                     [](const ShadowSettings& s) {
                         std::vector<int> values{0};
                         for (const int taps : steps(4, std::min(16, s.jitterTaps - 2), 2)) {
                             values.push_back(taps);
                         }
                         return values;
                     }},
         techniqueIs(ShadowTechnique::JitteredPcf)},
        {"texelSnapping", "snap to texels",
         "Snap the directional light's frustum to whole texels (no shimmer).",
         T::ToggleField{&ShadowSettings::texelSnapping}, always},
        {"debugView", "debug view", "What the lighting pass shows instead of the shaded colour.",
         choice(&ShadowSettings::debugView, namesOf(views)), always},
    };
}

} // namespace

std::span<const ParameterTable::Row> ParameterTable::shadowRows() {
    static const std::vector<Row> rows = makeRows();
    return rows;
}

int ParameterTable::nearest(const std::vector<int>& values, int value) {
    return *std::min_element(values.begin(), values.end(),
                             [value](int a, int b) { return std::abs(a - value) < std::abs(b - value); });
}

void ParameterTable::repairIntegers(shadows::ShadowSettings& settings) {
    for (const Row& row : shadowRows()) {
        const auto* field = std::get_if<IntField>(&row.field);
        if (!field || !row.applies(settings)) {
            continue;
        }
        shadows::ShadowSettings snapped = settings;
        snapped.*field->member = nearest(field->values(settings), settings.*field->member);
        if (snapped.validate().size() < settings.validate().size()) {
            settings = snapped;
        }
    }
}

} // namespace sandbox
