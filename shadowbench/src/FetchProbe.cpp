#include <shadowbench/FetchProbe.h>

#include <engine/Error.h>
#include <engine/gl/Program.h>
#include <shadows/ShadowPlan.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

namespace shadowbench {

namespace {

// The reads sit on a 4-wide grid of texels around the projected point, as a PCF kernel's do, so no two are
// the same read; their mean is the visibility, so none is optimised away.
constexpr const char* kDeclarations = R"glsl(
#ifdef GS_FETCH_PROBE
#if defined(GS_FETCH_PROBE_16)
#define GS_FETCH_PROBE_COUNT 16
#elif defined(GS_FETCH_PROBE_8)
#define GS_FETCH_PROBE_COUNT 8
#elif defined(GS_FETCH_PROBE_4)
#define GS_FETCH_PROBE_COUNT 4
#elif defined(GS_FETCH_PROBE_2)
#define GS_FETCH_PROBE_COUNT 2
#else
#define GS_FETCH_PROBE_COUNT 1
#endif
#ifdef GS_FETCH_PROBE_COMPARE
uniform sampler2DArrayShadow gsFetchProbeMap;
#else
uniform sampler2DArray gsFetchProbeMap;
#endif
uniform mat4 gsFetchProbeMatrix;
float gsFetchProbe(vec3 worldPosition) {
    vec3 coord = (gsFetchProbeMatrix * vec4(worldPosition, 1.0)).xyz;
    float sum = 0.0;
    for (int i = 0; i < GS_FETCH_PROBE_COUNT; ++i) {
        vec2 tap = coord.xy + vec2(float(i % 4), float(i / 4)) / vec2(textureSize(gsFetchProbeMap, 0).xy);
#ifdef GS_FETCH_PROBE_COMPARE
        sum += texture(gsFetchProbeMap, vec4(tap, 0.0, coord.z));
#else
        sum += texture(gsFetchProbeMap, vec3(tap, 0.0)).r;
#endif
    }
    return sum / float(GS_FETCH_PROBE_COUNT);
}
#endif
)glsl";

std::string countDefine(int fetches) {
    return "GS_FETCH_PROBE_" + std::to_string(fetches);
}

} // namespace

FetchProbe::FetchProbe(FetchKind kind, int fetches, const glm::mat4& worldToMap, ProbeMap map)
    : kind_(kind), fetches_(1), worldToMap_(worldToMap), mapFormat_(map) {
    if (map.size < 1 || map.size > 16384) {
        throw engine::Error("fetch probe: a map of " + std::to_string(map.size) +
                            " texels a side (1..16384)");
    }
    if (shadows::toString(map.format) == "?") {
        throw engine::Error("fetch probe: a map format other than d16, d24 or d32f");
    }
    setFetches(fetches);
}

void FetchProbe::setFetches(int fetches) {
    if (std::find(std::begin(kCounts), std::end(kCounts), fetches) == std::end(kCounts)) {
        throw engine::Error("fetch probe: " + std::to_string(fetches) + " fetches (1, 2, 4, 8 or 16)");
    }
    fetches_ = fetches;
}

void FetchProbe::attach(engine::ModuleHost& host) {
    host_ = &host;
    unit_ = host.reserveTextureUnit();
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture);
    map_ = decltype(map_)(texture);
    const int side = mapFormat_.size;
    glTextureStorage3D(texture, 1, shadows::glDepthFormat(mapFormat_.format), side, side, 1);
    // A ramp, so comparisons go both ways over the view (a constant map would compare alike everywhere).
    std::vector<float> depths(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    for (std::size_t i = 0; i < depths.size(); ++i) {
        depths[i] = static_cast<float>(i % static_cast<std::size_t>(side)) / static_cast<float>(side);
    }
    glTextureSubImage3D(texture, 0, 0, 0, 0, side, side, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    GLuint sampler = 0;
    glCreateSamplers(1, &sampler);
    sampler_ = decltype(sampler_)(sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
    if (kind_ == FetchKind::Compare) {
        glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
}

std::vector<engine::ShaderChunk> FetchProbe::shaderChunks() const {
    return {{"declarations", "shadowbench/fetch-probe", kDeclarations},
            {"light_visibility", "shadowbench/fetch-probe-visibility",
             "#ifdef GS_FETCH_PROBE\nvisibility *= gsFetchProbe(vWorldPosition);\n#endif"}};
}

engine::ShaderVariantKey FetchProbe::variantBits(const engine::DrawContext&) const {
    engine::ShaderVariantKey key =
        host_->variantFlag("GS_FETCH_PROBE") | host_->variantFlag(countDefine(fetches_));
    if (kind_ == FetchKind::Compare) {
        key |= host_->variantFlag("GS_FETCH_PROBE_COMPARE");
    }
    return key;
}

void FetchProbe::bindLightingResources(const engine::gl::Program& program, const engine::DrawContext&) {
    glBindTextureUnit(unit_, map_.id());
    glBindSampler(unit_, sampler_.id());
    program.set("gsFetchProbeMap", static_cast<int>(unit_));
    program.set("gsFetchProbeMatrix", worldToMap_);
}

} // namespace shadowbench
