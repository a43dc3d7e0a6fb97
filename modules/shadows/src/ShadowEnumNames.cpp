#include <shadows/ShadowSettings.h>
#include <shadows/ShadowTechniqueTraits.h>

#include <array>

namespace shadows {

template <>
std::span<const EnumName<ShadowTechnique>> enumNames() {
    static const std::vector<EnumName<ShadowTechnique>> names = [] {
        std::vector<EnumName<ShadowTechnique>> list;
        for (const ShadowTechniqueTraits& traits : techniqueTable()) {
            list.push_back({traits.technique, traits.name});
        }
        return list;
    }();
    return names;
}

template <>
std::span<const EnumName<TapLayout>> enumNames() {
    static constexpr std::array<EnumName<TapLayout>, 3> names{
        {{TapLayout::Grid, "grid"}, {TapLayout::Poisson, "poisson"}, {TapLayout::Circular8, "circular8"}}};
    return names;
}

template <>
std::span<const EnumName<GradientSource>> enumNames() {
    static constexpr std::array<EnumName<GradientSource>, 3> names{
        {{GradientSource::StoredDerivatives, "stored"},
         {GradientSource::CentralDifferences, "central"},
         {GradientSource::ScreenSpace, "screen"}}};
    return names;
}

template <>
std::span<const EnumName<DepthFormat>> enumNames() {
    static constexpr std::array<EnumName<DepthFormat>, 3> names{
        {{DepthFormat::D16, "d16"}, {DepthFormat::D24, "d24"}, {DepthFormat::D32F, "d32f"}}};
    return names;
}

template <>
std::span<const EnumName<DirectionalFit>> enumNames() {
    static constexpr std::array<EnumName<DirectionalFit>, 2> names{
        {{DirectionalFit::Samples, "samples"}, {DirectionalFit::Bounds, "bounds"}}};
    return names;
}

template <>
std::span<const EnumName<MapAllocation>> enumNames() {
    static constexpr std::array<EnumName<MapAllocation>, 2> names{
        {{MapAllocation::Fitted, "fitted"}, {MapAllocation::Virtual, "virtual"}}};
    return names;
}

template <>
std::span<const EnumName<CasterFaces>> enumNames() {
    static constexpr std::array<EnumName<CasterFaces>, 4> names{{{CasterFaces::Auto, "auto"},
                                                                 {CasterFaces::Both, "both"},
                                                                 {CasterFaces::Front, "front"},
                                                                 {CasterFaces::Back, "back"}}};
    return names;
}

template <>
std::span<const EnumName<AverageGradientForm>> enumNames() {
    static constexpr std::array<EnumName<AverageGradientForm>, 3> names{
        {{AverageGradientForm::LeastSquares, "least-squares"},
         {AverageGradientForm::Circular8, "circular8"},
         {AverageGradientForm::Circular8Vec4, "circular8-vec4"}}};
    return names;
}

template <>
std::span<const EnumName<ReceiverPlaneKernel>> enumNames() {
    static constexpr std::array<EnumName<ReceiverPlaneKernel>, 2> names{
        {{ReceiverPlaneKernel::Bilinear2x2, "bilinear2x2"}, {ReceiverPlaneKernel::PerTap, "per-tap"}}};
    return names;
}

template <>
std::span<const EnumName<ShadowDebugView>> enumNames() {
    static constexpr std::array<EnumName<ShadowDebugView>, 11> names{
        {{ShadowDebugView::None, "none"},
         {ShadowDebugView::TexelCheckerboard, "texels"},
         {ShadowDebugView::GradientMagnitude, "gradient"},
         {ShadowDebugView::Bias, "bias"},
         {ShadowDebugView::Visibility, "visibility"},
         {ShadowDebugView::ShadowMap, "shadow-map"},
         {ShadowDebugView::FullKernel, "kernel"},
         {ShadowDebugView::Maps, "maps"},
         {ShadowDebugView::Density, "density"},
         {ShadowDebugView::Pages, "pages"},
         {ShadowDebugView::Slot, "slot"}}};
    return names;
}

std::string_view toString(ShadowTechnique technique) {
    return nameOf(technique);
}
std::optional<ShadowTechnique> techniqueFromString(std::string_view name) {
    return enumFromName<ShadowTechnique>(name);
}
const std::vector<ShadowTechnique>& allTechniques() {
    static const std::vector<ShadowTechnique> all = [] {
        std::vector<ShadowTechnique> list;
        for (const EnumName<ShadowTechnique>& entry : enumNames<ShadowTechnique>()) {
            list.push_back(entry.value);
        }
        return list;
    }();
    return all;
}
std::string_view toString(DepthFormat format) {
    return nameOf(format);
}
std::optional<DepthFormat> depthFormatFromString(std::string_view name) {
    return enumFromName<DepthFormat>(name);
}
std::string_view toString(GradientSource source) {
    return nameOf(source);
}
std::optional<GradientSource> gradientSourceFromString(std::string_view name) {
    return enumFromName<GradientSource>(name);
}
std::string_view toString(ShadowDebugView view) {
    return nameOf(view);
}
std::optional<ShadowDebugView> debugViewFromString(std::string_view name) {
    return enumFromName<ShadowDebugView>(name);
}

} // namespace shadows
