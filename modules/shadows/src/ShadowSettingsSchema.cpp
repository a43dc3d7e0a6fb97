#include <shadows/LightFrustum.h>
#include <shadows/ShadowPlan.h>
#include <shadows/ShadowSettingsSchema.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace shadows {

namespace {

using T = ShadowTechnique;
using S = ShadowSettings;

/// An EnumSetting over `Member`, with its enum's one name table.
template <typename Enum, Enum ShadowSettings::*Member>
EnumSetting choice() {
    std::vector<std::string_view> names;
    for (const EnumName<Enum>& entry : enumNames<Enum>()) {
        names.push_back(entry.name);
    }
    return {std::move(names), [](const S& s) { return static_cast<int>(s.*Member); },
            [](S& s, int index) { s.*Member = enumNames<Enum>()[static_cast<std::size_t>(index)].value; }};
}

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

bool always(const S&) {
    return true;
}
bool usesTaps(const S& s) {
    return ShadowPlan::resolve(s).usesTapPattern;
}
/// The circular-8 forms of the average gradient bring their own 8-tap layout (ShadowSettings::tapPattern).
bool layoutForced(const S& s) {
    return s.usesCircular8Average();
}
bool offsetsCasters(const S& s) {
    return traitsOf(s.technique).offsetsCasters;
}
bool offsetsAlongNormal(const S& s) {
    return traitsOf(s.technique).footprintTexels != nullptr;
}
bool biasesDepth(const S& s) {
    return traitsOf(s.technique).biasesDepth;
}
bool readsPointGradient(const S& s) {
    return ShadowPlan::resolve(s).readsPointGradient;
}
bool comparesInHardware(const S& s) {
    const MapSampler sampler = ShadowPlan::resolve(s).sampler;
    return sampler == MapSampler::CompareNearest || sampler == MapSampler::CompareLinear;
}
bool storesFourMoments(const S& s) {
    return shadows::storesFourMoments(s.technique);
}
bool storesMomentsIn16Bits(const S& s) {
    return s.technique == T::Vsm || s.technique == T::Msm;
}
bool filtersMoments(const S& s) {
    return traitsOf(s.technique).moments.format != nullptr;
}
bool comparesFuzzily(const S& s) {
    return traitsOf(s.technique).fuzzyComparison;
}
bool chebyshevBound(const S& s) {
    return traitsOf(s.technique).chebyshevBound;
}
bool castsSoftShadows(const S& s) {
    return traitsOf(s.technique).softReachTexels != nullptr;
}
bool jittered(const S& s) {
    return traitsOf(s.technique).jittered;
}
bool virtualMaps(const S& s) {
    return s.mapAllocation == MapAllocation::Virtual;
}
bool fittedMaps(const S& s) {
    return s.mapAllocation == MapAllocation::Fitted;
}
bool sizedToTheView(const S& s) {
    return s.mapAllocation == MapAllocation::Fitted && s.directionalFit == DirectionalFit::Samples &&
           !castsSoftShadows(s);
}
bool cascaded(const S& s) {
    return s.cascadeCount != 1;
}
template <ShadowTechnique Technique>
bool only(const S& s) {
    return s.technique == Technique;
}

std::optional<IntLimits> fixed(IntLimits limits) {
    return limits;
}

const std::vector<SettingRow>& rows() {
    static const std::vector<SettingRow> table = {
        {"technique", "", "technique", "Visibility function (see the techniques table).",
         choice<ShadowTechnique, &S::technique>(), always, "--technique"},
        {"resolution", "texels", "shadow map", "Width and height of the shadow map.",
         IntSetting{
             &S::resolution,
             [](const S&) { return fixed({.min = kSmallestMapSide, .max = 16384, .powersOfTwo = true}); }},
         always, "--shadow-size"},
        {"depthFormat", "", "depth format", "Depth format of the shadow map.",
         choice<DepthFormat, &S::depthFormat>(), always, "--depth-format"},
        {"casterFaces", "", "caster faces",
         "Faces (as seen from the light) drawn into the shadow map. auto: both of open meshes, since real "
         "models mix windings and a culled face casts no shadow; of closed ones only those facing the light, "
         "which store the same depth at about half the triangles; and, where the technique only compares "
         "depths, no flat caster that nothing lies behind as the light sees it (a ground, a room's walls).",
         choice<CasterFaces, &S::casterFaces>(), always, "--caster-faces"},
        {"constantBiasTexels", "texels", "constant bias",
         "Receiver moved towards the light before the comparison, in shadow texel sizes at the receiver (so "
         "one value holds at any scene scale and map size), on top of the technique's own lift for relief. 0 "
         "(the default) adds none, so the naive `hard` has no bias.",
         FloatSetting{&S::constantBiasTexels, {.max = 64.0f}, 0.0f, 16.0f, "%.3f"}, always},
        {"slopeScale", "", "slope scale", "glPolygonOffset factor on the casters (scales their depth slope).",
         FloatSetting{&S::slopeScale, {}, 0.0f, 8.0f, "%.2f"}, offsetsCasters},
        {"slopeUnits", "", "slope units",
         "glPolygonOffset units (multiples of the format's resolvable step).",
         FloatSetting{&S::slopeUnits, {}, 0.0f, 16.0f, "%.2f"}, offsetsCasters},
        {"averageGradientForm", "", "average gradient form",
         "Least squares over any pattern, or the reference's circular-8 forms (which bring their own "
         "layout).",
         choice<AverageGradientForm, &S::averageGradientForm>(), only<T::PcfGsmAverageGradient>},
        {"pcfLayout", "", "PCF layout", "Layout of the PCF taps.", choice<TapLayout, &S::pcfLayout>(),
         [](const S& s) { return usesTaps(s) && !layoutForced(s); }},
        {"pcfTaps", "", "PCF taps", "Taps per side of a grid, or the number of Poisson taps.",
         IntSetting{&S::pcfTaps,
                    [](const S& s) -> std::optional<IntLimits> {
                        if (s.pcfLayout == TapLayout::Grid) {
                            return IntLimits{.min = 2, .max = 8, .qualifier = "for a grid"};
                        }
                        if (s.pcfLayout == TapLayout::Poisson) {
                            return IntLimits{.min = 8, .max = 64, .qualifier = "for a Poisson disk"};
                        }
                        return std::nullopt; // circular-8 has its own count
                    }},
         [](const S& s) { return usesTaps(s) && !layoutForced(s) && s.pcfLayout != TapLayout::Circular8; }},
        {"pcfRadius", "texels", "PCF radius", "Radius of the tap pattern (and of the jittered offsets).",
         FloatSetting{&S::pcfRadius, {.minExclusive = true}, 0.5f, 8.0f, "%.2f"},
         [](const S& s) { return usesTaps(s) || jittered(s); }},
        {"pcfRotate", "", "rotate pattern per pixel",
         "Trades banding for noise (interleaved gradient noise).", BoolSetting{&S::pcfRotate}, usesTaps},
        {"gradientSource", "", "gradient source", "Where the fragment's depth gradient comes from.",
         choice<GradientSource, &S::gradientSource>(), readsPointGradient},
        {"fuzzyScale", "texels", "fuzzy scale", "Width of the GSM fuzzy comparison band.",
         FloatSetting{&S::fuzzyScale, {.minExclusive = true}, 0.1f, 8.0f, "%.2f", true}, comparesFuzzily},
        {"receiverPlaneKernel", "", "receiver-plane kernel", "2x2 bilinear gather, or one bias per PCF tap.",
         choice<ReceiverPlaneKernel, &S::receiverPlaneKernel>(), only<T::ReceiverPlaneBias>},
        {"receiverPlaneClamp", "", "clamp bias to min(0, bias)",
         "Only let the bias move receivers towards the light.", BoolSetting{&S::receiverPlaneClamp},
         only<T::ReceiverPlaneBias>},
        {"footprintNormalOffset", "", "normal offset by the footprint",
         "Push the receiver along its normal by the comparison's footprint (half a texel diagonal for one "
         "NEAREST or linearly filtered fetch, a diagonal for 2x2 bilinear PCF) times the sine of its angle "
         "to the light (docs/SHADOWS.md, \"Automatic bias\"); those comparing along the receiver's "
         "plane at one fetch (normal-offset, the adaptive bias, GSM and PCF over GSM) also move it half a "
         "texel towards the light. Off: only normalOffsetTexels and constantBiasTexels, as the references' "
         "techniques have it.",
         BoolSetting{&S::footprintNormalOffset}, offsetsAlongNormal},
        {"normalOffsetTexels", "texels", "normal offset margin",
         "Margin beyond the comparison's footprint: the receiver is pushed along its normal by "
         "(footprint + this) texel sizes times the sine of its angle to the light, which clears a plane "
         "over the footprint at any angle (docs/SHADOWS.md, \"Automatic bias\").",
         FloatSetting{&S::normalOffsetTexels, {.max = 16.0f}, 0.0f, 8.0f, "%.2f"}, offsetsAlongNormal},
        {"depthBiasSteps", "depth steps", "depth bias",
         "Comparison depth lowered by this many steps of the depth format, but steps no finer than 2^-18 "
         "(the "
         "float arithmetic's disagreement between the two passes): the rounding of stored and receiver "
         "depths, which no slope-dependent bias covers where the receiver faces the light.",
         FloatSetting{&S::depthBiasSteps, {.max = 1024.0f}, 0.0f, 1024.0f, "%.1f", true}, biasesDepth},
        {"floorReceiverDepth", "", "floor receiver depth",
         "Floor the reference to the format's step so the hardware comparison's rounding adds no acne.",
         BoolSetting{&S::floorReceiverDepth}, comparesInHardware},
        {"momentBlurRadius", "texels", "moment blur", "Half-width of the separable box blur of the moments.",
         IntSetting{&S::momentBlurRadius, [](const S&) { return fixed({.min = 0, .max = 16}); }},
         filtersMoments},
        {"vsmMinimumVariance", "depth units squared", "minimum variance",
         "Smallest variance the Chebyshev bound uses.",
         FloatSetting{&S::vsmMinimumVariance, {}, 0.0f, 1e-3f, "%.2e", true}, chebyshevBound},
        {"lightBleedingReduction", "", "light-bleeding reduction",
         "Tail of the Chebyshev bound cut off (linstep).",
         FloatSetting{&S::lightBleedingReduction, {.max = 0.95f}, 0.0f, 0.95f, "%.2f"}, chebyshevBound},
        {"msmMomentBias", "", "moment bias",
         "Bias of the moments towards (0, 0.63, 0, 0.63); more hides numerical trouble, leaks more light.",
         FloatSetting{&S::msmMomentBias, {.max = 0.5f}, 0.0f, 0.05f, "%.2e", true}, storesFourMoments},
        {"moments16", "", "16-bit moments",
         "Store the moments in 16-bit unorm: vsm's in RG16 (32 bits per texel), msm's in RGBA16 through the "
         "optimised basis (64 bits per texel); off: 32-bit floats.",
         BoolSetting{&S::moments16}, storesMomentsIn16Bits},
        {"lightSizeScale", "", "light size scale",
         "Every light's size (a sun's angular diameter, a local light's radius) times this, for the soft "
         "techniques: 0 casts hard shadows, 2 penumbrae twice as wide. The ray-traced truth takes the "
         "light's own "
         "size.",
         FloatSetting{&S::lightSizeScale, {.max = 16.0f}, 0.0f, 4.0f, "%.2f"}, castsSoftShadows},
        {"evsmPositiveExponent", "", "positive exponent",
         "c+ of the warp exp(c+ d): larger cuts more light bleeding; 42 at most keeps exp(2 c+) in float32.",
         FloatSetting{&S::evsmPositiveExponent,
                      {.min = 0.0f, .max = 42.0f, .minExclusive = true},
                      1.0f,
                      42.0f,
                      "%.1f"},
         only<T::Evsm>},
        {"evsmNegativeExponent", "", "negative exponent",
         "c- of the warp -exp(-c- d): bounds the receivers the positive warp lets light through.",
         FloatSetting{&S::evsmNegativeExponent,
                      {.min = 0.0f, .max = 42.0f, .minExclusive = true},
                      1.0f,
                      42.0f,
                      "%.1f"},
         only<T::Evsm>},
        {"jitterTaps", "", "jittered taps", "Stratified taps per pixel (two per jitter texel).",
         IntSetting{&S::jitterTaps, [](const S&) { return fixed({.min = 8, .max = 64, .step = 2}); }},
         jittered},
        {"earlyOutTestTaps", "", "early-out test taps",
         "Taps taken before deciding whether the pixel needs the full kernel; 0 always takes the full "
         "kernel.",
         IntSetting{&S::earlyOutTestTaps,
                    [](const S& s) {
                        // Fewer test taps than the kernel has, so the early-out can save something.
                        return fixed({.min = 4,
                                      .max = std::min(16, s.jitterTaps - 1),
                                      .step = 2,
                                      .zeroAllowed = true,
                                      .qualifier = "and below jitterTaps"});
                    }},
         jittered},
        {"directionalFit", "", "directional fit",
         "What directional maps are fitted to. samples: a depth pass of the view is reduced on the GPU to "
         "the visible samples' depth range and, per cascade, their light-space rectangle (Sample "
         "Distribution Shadow Maps, Lauritzen et al. 2011); the automatic cascade count is the fewest whose "
         "slices have a texel no larger than a pixel at their near end. bounds: mesh bounding boxes (one map "
         "over where visible boxes can be shadowed, cascades around the view frustum's slices). A view with "
         "no visible sample falls back to bounds, saying so once.",
         choice<DirectionalFit, &S::directionalFit>(), always, "--fit"},
        {"mapAllocation", "", "map allocation",
         "How shadow texels are allocated. fitted: whole maps of `resolution`² fitted to the view. virtual: "
         "per directional light a clipmap of 16k² levels, each twice the radius of the last; per spot light, "
         "and per face of a point light, one 16k² map with mip levels. Their pages are drawn only where "
         "visible pixels ask for them, at the level whose texels are no larger than a pixel there (the "
         "receiver's slope to the light included), in a pool of virtualBudgetMiB, cached while casters and "
         "light stay put. Over budget, pages fall back to coarser levels and the stats say so.",
         choice<MapAllocation, &S::mapAllocation>(), always, "--maps"},
        {"fittedBudgetMiB", "MiB", "map budget",
         "Memory of the whole maps, all lights together (depth, and the gradient or moments the technique "
         "stores). Where the most maps the lights may take (six faces per point light, a sun's cascades: "
         "four when counted automatically) would need more at `resolution`, every map takes the largest "
         "side, halved down to 64, that fits, and the module says so once: eight point lights under a "
         "moment technique at 2048² would otherwise hold 3.8 GiB.",
         IntSetting{&S::fittedBudgetMiB,
                    [](const S&) { return fixed({.min = 4, .max = 65536, .powersOfTwo = true}); }},
         fittedMaps, "--map-budget"},
        {"virtualBudgetMiB", "MiB", "page budget",
         "Memory of the virtual maps: the page pool (every light's pages, their borders and the technique's "
         "stored values), the lights' page tables and the page requests; it must hold at least one page "
         "beside them.",
         IntSetting{&S::virtualBudgetMiB, [](const S&) { return fixed({.min = 1, .max = 4096}); }},
         virtualMaps, "--page-budget"},
        {"virtualPageSize", "texels", "page size", "Side of a virtual page.",
         IntSetting{&S::virtualPageSize,
                    [](const S&) { return fixed({.min = 32, .max = 512, .powerOfTwoRequired = true}); }},
         virtualMaps, "--page-size"},
        {"virtualTexelPixels", "pixels", "texel on screen",
         "The largest extent on screen of one texel of the level each pixel's page is drawn at (Lloyd's m). "
         "1 "
         "gives a texel per pixel or finer; 2 draws about a quarter of the texels, with edges up to two "
         "pixels "
         "off.",
         FloatSetting{&S::virtualTexelPixels, {.min = 0.25f, .max = 16.0f}, 0.25f, 8.0f, "%.2f", true},
         virtualMaps, "--texel-pixels"},
        {"fittedTexelPixels", "pixels", "texel on screen",
         "Directional maps fitted to the samples: the largest size on screen of one texel at each cascade's "
         "nearest sample, for a technique that filters over 1 + 2 × its filter radius in texels (pcfRadius, "
         "momentBlurRadius, half a texel for a bilinear lookup) that many times smaller. The maps take the "
         "smallest power-of-two side up to `resolution` that meets it, so a "
         "view that needs fewer texels than `resolution`² draws fewer (a frame with spot or point lights, "
         "whose maps share the array, keeps `resolution`, as do the soft techniques, whose margins are "
         "64 texels and more). 0: always `resolution`.",
         FloatSetting{&S::fittedTexelPixels, {.max = 16.0f}, 0.0f, 4.0f, "%.2f"}, sizedToTheView},
        {"reuseUnchangedMaps", "", "reuse unchanged maps",
         "Keep the last frame's maps when nothing they are drawn from changed (the view, its size, the "
         "lights, every mesh and its transform): a still view draws no map and runs no sample pass "
         "(virtual maps: from the frame after one that drew no page). A moving view keeps a fitted map "
         "where it was placed while that holds the view's samples at the same texel size, and then draws "
         "none either. Off, every frame draws its fitted maps and updates its virtual ones, as a camera "
         "cut does.",
         BoolSetting{&S::reuseUnchangedMaps}, always},
        {"texelSnapping", "", "snap to texels",
         "Snap the directional light's frustum to whole texels so shadows do not shimmer.",
         BoolSetting{&S::texelSnapping}, always},
        {"cascadeCount", "", "cascades",
         "Cascades of each directional light's shadow map. 1: one map over where visible receivers can be "
         "shadowed. 2-4: the view depths of visible receivers (the samples' range, or the visible boxes') "
         "are "
         "split by the practical split scheme, each slice gets a map (around its samples, or around its "
         "bounding sphere), snapped to texels; a cascade no visible receiver falls in is not drawn. 0: "
         "automatic: fitted to samples, the fewest cascades whose texels are no larger than a pixel at each "
         "slice's near end (else 4); fitted to bounds, one map below a depth range of 1000:1 and one more "
         "cascade per decade beyond.",
         IntSetting{&S::cascadeCount,
                    [](const S&) { return fixed({.min = 1, .max = kMaxCascades, .zeroAllowed = true}); }},
         always, "--cascades"},
        {"cascadeSplitWeight", "", "split weight",
         "Weight of the logarithmic split scheme against the uniform one (Zhang et al. 2006, practical split "
         "scheme): 1 gives texels proportional to depth, 0 equal slices.",
         FloatSetting{&S::cascadeSplitWeight, {.max = 1.0f}, 0.0f, 1.0f, "%.2f"}, cascaded},
        {"cascadeBlend", "", "cascade blend",
         "Fraction of each cascade's depth span, at its far end, where visibility blends linearly into the "
         "next cascade's (hides the seam; those pixels sample two maps).",
         FloatSetting{&S::cascadeBlend, {.max = 0.5f}, 0.0f, 0.5f, "%.2f"}, cascaded},
        {"debugView", "", "debug view", "What the lighting pass shows instead of the shaded colour.",
         choice<ShadowDebugView, &S::debugView>(), always, "--debug-view"},
    };
    return table;
}

} // namespace

bool FloatLimits::contains(float value) const {
    return std::isfinite(value) && (minExclusive ? value > min : value >= min) && value <= max;
}

bool IntLimits::contains(int value) const {
    const bool powerOfTwo = value > 0 && (value & (value - 1)) == 0;
    return (zeroAllowed && value == 0) ||
           (value >= min && value <= max && (value - min) % step == 0 && (!powerOfTwoRequired || powerOfTwo));
}

std::vector<int> IntLimits::offered() const {
    std::vector<int> values;
    if (zeroAllowed) {
        values.push_back(0);
    }
    for (int value = min; value <= max;
         value = powersOfTwo || powerOfTwoRequired ? value * 2 : value + step) {
        values.push_back(value);
    }
    return values;
}

std::string IntLimits::describe() const {
    std::string text = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
    if (step > 1) {
        text += " in steps of " + std::to_string(step);
    }
    if (powerOfTwoRequired) {
        text += ", a power of two";
    }
    return zeroAllowed ? "0, or " + text : text;
}

std::string EnumSetting::nameList() const {
    std::string list;
    for (const std::string_view name : names) {
        list += (list.empty() ? "" : ", ") + std::string(name);
    }
    return list;
}

std::optional<std::string> SettingRow::problem(const ShadowSettings& settings) const {
    const std::string qualified(name);
    if (const auto* real = std::get_if<FloatSetting>(&field)) {
        if (real->valid.contains(settings.*real->member)) {
            return std::nullopt;
        }
        return qualified + " must be " + rangeText() + (unit.empty() ? "" : " (" + std::string(unit) + ")");
    }
    if (const auto* integer = std::get_if<IntSetting>(&field)) {
        const int value = settings.*integer->member;
        const std::optional<IntLimits> limits = integer->limits(settings);
        if (!limits || limits->contains(value)) {
            return std::nullopt;
        }
        return qualified + " " + std::to_string(value) + " is outside " + limits->describe() +
               (limits->qualifier.empty() ? "" : " " + std::string(limits->qualifier));
    }
    return std::nullopt; // booleans and enum values read through the name tables are always valid
}

std::string SettingRow::valueText(const ShadowSettings& settings) const {
    if (const auto* real = std::get_if<FloatSetting>(&field)) {
        return formatNumber(settings.*real->member);
    }
    if (const auto* integer = std::get_if<IntSetting>(&field)) {
        return std::to_string(settings.*integer->member);
    }
    if (const auto* toggle = std::get_if<BoolSetting>(&field)) {
        return settings.*toggle->member ? "true" : "false";
    }
    const auto& choice = std::get<EnumSetting>(field);
    return std::string(choice.names[static_cast<std::size_t>(choice.get(settings))]);
}

std::string SettingRow::rangeText() const {
    if (const auto* real = std::get_if<FloatSetting>(&field)) {
        const FloatLimits& valid = real->valid;
        if (std::isinf(valid.max)) {
            return std::string("a finite number ") + (valid.minExclusive ? "> " : ">= ") +
                   formatNumber(valid.min);
        }
        return "in [" + formatNumber(valid.min) + ", " + formatNumber(valid.max) + "]";
    }
    if (const auto* integer = std::get_if<IntSetting>(&field)) {
        // Limits that depend on a choice (pcfTaps on the layout): one description per distinct case.
        std::vector<ShadowSettings> cases{ShadowSettings{}};
        for (const SettingRow& other : rows()) {
            if (const auto* choice = std::get_if<EnumSetting>(&other.field)) {
                for (int index = 0; index < static_cast<int>(choice->names.size()); ++index) {
                    choice->set(cases.emplace_back(), index);
                }
            }
        }
        std::string text;
        for (const ShadowSettings& settings : cases) {
            const std::optional<IntLimits> limits = integer->limits(settings);
            const std::string one =
                limits ? limits->describe() +
                             (limits->qualifier.empty() ? "" : " " + std::string(limits->qualifier))
                       : "";
            if (!one.empty() && text.find(one) == std::string::npos) {
                text += (text.empty() ? "" : "; ") + one;
            }
        }
        return text;
    }
    if (std::holds_alternative<BoolSetting>(field)) {
        return "true, false";
    }
    return std::get<EnumSetting>(field).nameList();
}

std::string SettingRow::labelWithUnit() const {
    return unit.empty() ? std::string(label) : std::string(label) + " (" + std::string(unit) + ")";
}

std::span<const SettingRow> settingsSchema() {
    return rows();
}

const SettingRow* findSetting(std::string_view name) {
    for (const SettingRow& row : rows()) {
        if (row.name == name) {
            return &row;
        }
    }
    return nullptr;
}

IntLimits integerLimits(std::string_view name, const ShadowSettings& settings) {
    const SettingRow* row = findSetting(name);
    const auto* integer = row ? std::get_if<IntSetting>(&row->field) : nullptr;
    const std::optional<IntLimits> limits = integer ? integer->limits(settings) : std::nullopt;
    if (!limits) {
        throw std::logic_error("shadow settings: '" + std::string(name) + "' has no integer limits here");
    }
    return *limits;
}

std::string settingsMarkdownTable() {
    std::string table = "| field | unit | default | accepts | applies to | what |\n"
                        "| --- | --- | --- | --- | --- | --- |\n";
    const ShadowSettings defaults;
    for (const SettingRow& row : rows()) {
        // The techniques whose default options the field applies to.
        std::string techniques;
        std::size_t count = 0;
        for (const EnumName<ShadowTechnique>& entry : enumNames<ShadowTechnique>()) {
            ShadowSettings settings;
            settings.technique = entry.value;
            if (row.applies(settings)) {
                techniques += (techniques.empty() ? "" : ", ") + std::string(entry.name);
                ++count;
            }
        }
        table += "| `" + std::string(row.name) + "` | " + std::string(row.unit) + " | `" +
                 row.valueText(defaults) + "` | " + row.rangeText() + " | " +
                 (count == kTechniqueCount ? "all" : techniques) + " | " + std::string(row.help) + " |\n";
    }
    return table;
}

} // namespace shadows
