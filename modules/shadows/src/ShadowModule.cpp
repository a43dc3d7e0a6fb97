#include <shadows/ShadowModule.h>
#include <shadows/ShadowTechniqueTraits.h>
#include <shadows/VisibilityMath.h>

#include <engine/ForwardRenderer.h>
#include <engine/ProgramCache.h>
#include <engine/gl/Program.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <span>
#include <stdexcept>

std::span<const engine::EmbeddedShaderFile> gsShadowShaders();

namespace shadows {

namespace {

constexpr int kMaxMaps = 4; // GS_SHADOW_MAX_MAPS in receiver.glsl
const engine::ProgramDesc kDepthProgram{"shadows/depth.vert", "shadows/depth.frag"};
const engine::ProgramDesc kBlurProgram{"shadows/fullscreen.vert", "shadows/blur.frag"};

GLenum glDepthFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16:
        return GL_DEPTH_COMPONENT16;
    case DepthFormat::D24:
        return GL_DEPTH_COMPONENT24;
    case DepthFormat::D32F:
        return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT24;
}

std::size_t bytesPerDepthTexel(DepthFormat format) {
    return format == DepthFormat::D16 ? 2 : 4;
}

/// Colour format of the moments target, or 0 when the technique stores none.
GLenum momentsFormat(const ShadowSettings& settings) {
    switch (techniqueTraits(settings).moments) {
    case 2:
        return GL_RG32F;
    case 4:
        return settings.msmQuantize16 ? GL_RGBA16 : GL_RGBA32F;
    default:
        return 0;
    }
}

std::size_t bytesPerMomentTexel(GLenum format) {
    return format == GL_RG32F || format == GL_RGBA16 ? 8 : format == GL_RGBA32F ? 16 : 0;
}

GLsizei mipLevels(int resolution) {
    GLsizei levels = 1;
    while ((resolution >> levels) > 0) {
        ++levels;
    }
    return levels;
}

engine::gl::GlObject<engine::gl::detail::deleteSampler> makeSampler(GLenum filter, bool compare) {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    glSamplerParameteri(name, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    glSamplerParameteri(name, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    // Outside the map counts as unoccluded: a border at the far plane.
    glSamplerParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glSamplerParameterfv(name, GL_TEXTURE_BORDER_COLOR, border);
    if (compare) {
        glSamplerParameteri(name, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(name, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL); // lit when reference <= stored
    }
    return engine::gl::GlObject<engine::gl::detail::deleteSampler>(name);
}

} // namespace

struct ShadowModule::ShadowMap {
    ShadowMap(int resolution, DepthFormat format, bool withGradient, GLenum momentFormat)
        : depth(glDepthFormat(format), glm::ivec2(resolution)), framebuffer("shadow map") {
        framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
        if (withGradient) {
            gradient.emplace(GL_RG32F, glm::ivec2(resolution));
            framebuffer.attach(GL_COLOR_ATTACHMENT0, *gradient);
            framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        } else if (momentFormat != 0) {
            // Moments are filtered: blurred at level 0, then mipmapped for trilinear lookups.
            moments.emplace(momentFormat, glm::ivec2(resolution), mipLevels(resolution));
            blurTemporary.emplace(momentFormat, glm::ivec2(resolution));
            blurFramebuffer.emplace("shadow moments blur");
            blurFramebuffer->attach(GL_COLOR_ATTACHMENT0, *blurTemporary);
            blurFramebuffer->setDrawBuffers({GL_COLOR_ATTACHMENT0});
            blurFramebuffer->check();
            framebuffer.attach(GL_COLOR_ATTACHMENT0, *moments);
            framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        } else {
            framebuffer.setDrawBuffers({});
        }
        framebuffer.check();
    }

    int lightIndex = -1;
    LightProjection projection;
    engine::gl::Texture depth;
    std::optional<engine::gl::Texture> gradient;
    std::optional<engine::gl::Texture> moments;
    std::optional<engine::gl::Texture> blurTemporary;
    std::optional<engine::gl::Framebuffer> blurFramebuffer;
    engine::gl::Framebuffer framebuffer;
};

struct ShadowModule::Samplers {
    engine::gl::GlObject<engine::gl::detail::deleteSampler> compareNearest = makeSampler(GL_NEAREST, true);
    engine::gl::GlObject<engine::gl::detail::deleteSampler> compareLinear = makeSampler(GL_LINEAR, true);
    engine::gl::GlObject<engine::gl::detail::deleteSampler> depthLinear = makeSampler(GL_LINEAR, false);
    engine::gl::GlObject<engine::gl::detail::deleteSampler> moments = [] {
        auto sampler = makeSampler(GL_LINEAR, false);
        // Trilinear over the mip chain; edges clamp (a quantised border would not be "far").
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        return sampler;
    }();
};

/// The jitter texture of JitteredPcf (soft shadows reference), made when the technique is first used.
struct ShadowModule::Jitter {
    explicit Jitter(int tapCount) : taps(tapCount) {
        const JitterTexels texels = makeJitterTexels(tapCount);
        GLuint name = 0;
        glCreateTextures(GL_TEXTURE_3D, 1, &name);
        texture = engine::gl::GlObject<engine::gl::detail::deleteTexture>(name);
        glTextureStorage3D(name, 1, GL_RGBA16, texels.size, texels.size, texels.pairs);
        glTextureSubImage3D(name, 0, 0, 0, 0, texels.size, texels.size, texels.pairs, GL_RGBA,
                            GL_UNSIGNED_SHORT, texels.texels.data());
        glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    int taps;
    engine::gl::GlObject<engine::gl::detail::deleteTexture> texture;
};

ShadowModule::ShadowModule() : ShadowModule(ShadowSettings{}) {}

ShadowModule::ShadowModule(const ShadowSettings& settings) {
    setSettings(settings);
}

ShadowModule::~ShadowModule() = default;

void ShadowModule::setSettings(const ShadowSettings& settings) {
    const std::vector<std::string> problems = settings.validate();
    if (!problems.empty()) {
        std::string message = "shadow settings:";
        for (const std::string& problem : problems) {
            message += "\n  " + problem;
        }
        throw std::invalid_argument(message);
    }
    if (settings == settings_ && !dirty_) {
        return;
    }
    settings_ = settings;
    pattern_ = settings_.tapPattern();
    dirty_ = true;
}

ShadowStats ShadowModule::stats() const {
    ShadowStats stats;
    stats.shadowMaps = static_cast<int>(maps_.size());
    const auto texels =
        static_cast<std::size_t>(settings_.resolution) * static_cast<std::size_t>(settings_.resolution);
    const std::size_t momentBytes = bytesPerMomentTexel(momentsFormat(settings_));
    for (const auto& map : maps_) {
        stats.bytes += texels * (bytesPerDepthTexel(settings_.depthFormat) + (map->gradient ? 8 : 0));
        // Moments: the mip chain (4/3 of level 0) plus the blur's temporary level.
        stats.bytes += map->moments ? texels * momentBytes * 4 / 3 + texels * momentBytes : 0;
    }
    return stats;
}

std::optional<LightProjection> ShadowModule::lightProjection(int lightIndex) const {
    for (const auto& map : maps_) {
        if (map->lightIndex == lightIndex) {
            return map->projection;
        }
    }
    return std::nullopt;
}

void ShadowModule::attach(engine::ModuleHost& host) {
    host_ = &host;
    host.shaders().add(gsShadowShaders());
    for (int slot = 0; slot < kMaxMaps; ++slot) {
        mapUnits_.push_back(host.reserveTextureUnit());
        gradientUnits_.push_back(host.reserveTextureUnit());
    }
    jitterUnit_ = host.reserveTextureUnit();
    dirty_ = true;
}

void ShadowModule::detach() {
    releaseResources();
    samplers_.reset();
    jitter_.reset();
    fullscreenVertexArray_.reset();
    host_ = nullptr;
}

void ShadowModule::releaseResources() {
    maps_.clear();
    uploadedFrame_.clear();
}

std::vector<engine::ShaderChunk> ShadowModule::shaderChunks() const {
    return {{"declarations", "shadows/chunk-declarations",
             "#ifdef GS_SHADOWS\n#include \"shadows/receiver.glsl\"\n#endif"},
            {"light_visibility", "shadows/chunk-visibility",
             "#ifdef GS_SHADOWS\nvisibility *= gsShadowVisibility(lightIndex, vWorldPosition, normal, "
             "toLight);\n#endif"},
            {"final_color", "shadows/chunk-debug", "#ifdef GS_SHADOWS\ngsShadowDebug(color);\n#endif"}};
}

bool ShadowModule::needsGradientTarget() const {
    return techniqueTraits(settings_).readsPointGradient &&
           settings_.gradientSource == GradientSource::StoredDerivatives;
}

engine::ShaderVariantKey ShadowModule::lightingKey() const {
    engine::ShaderVariantKey key = 0;
    for (const std::string_view define : lightingDefines(settings_)) {
        key |= host_->variantFlag(define);
    }
    return key;
}

void ShadowModule::prepareFrame(const engine::FrameContext& frame) {
    frameIndex_ = frame.frameIndex;
    if (dirty_) {
        releaseResources();
        lightingKey_ = lightingKey();
        dirty_ = false;
    }
    // World bounds of every mesh (computed once per mesh by the host): receivers for the fit, and casters.
    std::vector<Aabb> boxes;
    host_->forEachMeshBounds(frame.scene, [&](engine::EntityId, const glm::mat4& model, const Aabb& local) {
        boxes.push_back(local.transformed(model));
    });

    slotOfLight_.assign(engine::ForwardRenderer::kMaxLights, -1);
    std::size_t used = 0;
    for (const engine::FrameLight& light : frame.lights) {
        if (!light.light.castsShadows || used == kMaxMaps) {
            continue;
        }
        const LightProjection projection =
            light.light.type == engine::LightType::Directional
                ? fitDirectionalLight(light.direction, frame.viewProjection, boxes, settings_.resolution,
                                      settings_.texelSnapping)
                : fitSpotLight(light.position, light.direction, light.light.outerConeAngle, light.light.range,
                               boxes, settings_.resolution);
        if (!projection.valid) {
            continue;
        }
        if (used == maps_.size()) {
            maps_.push_back(std::make_unique<ShadowMap>(settings_.resolution, settings_.depthFormat,
                                                        needsGradientTarget(), momentsFormat(settings_)));
        }
        maps_[used]->lightIndex = light.index;
        maps_[used]->projection = projection;
        slotOfLight_[static_cast<std::size_t>(light.index)] = static_cast<int>(used);
        ++used;
    }
    // Lights that stopped casting (or left the view) give their maps back.
    maps_.resize(used);
}

void ShadowModule::renderPrePasses(const engine::FrameContext& frame) {
    if (maps_.empty()) {
        return;
    }
    const bool storeGradient = needsGradientTarget();
    const int moments = techniqueTraits(settings_).moments;
    engine::ShaderVariantKey depthKey = 0;
    if (storeGradient) {
        depthKey = host_->variantFlag("GS_SHADOW_STORE_GRADIENT");
    } else if (moments > 0) {
        depthKey = host_->variantFlag(moments == 2 ? "GS_SHADOW_STORE_MOMENTS2" : "GS_SHADOW_STORE_MOMENTS4");
        if (moments == 4 && settings_.msmQuantize16) {
            depthKey |= host_->variantFlag("GS_SHADOW_MSM_QUANTIZED");
        }
    }
    const engine::gl::Program& program = host_->programs().get(kDepthProgram, depthKey);
    program.use();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(settings_.casterFaces == CasterFaces::Front ? GL_BACK : GL_FRONT);
    if (techniqueTraits(settings_).offsetsCasters) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(settings_.slopeScale, settings_.slopeUnits);
    }
    glDisable(GL_FRAMEBUFFER_SRGB);
    for (const auto& map : maps_) {
        map->framebuffer.bind();
        glViewport(0, 0, settings_.resolution, settings_.resolution);
        glClearDepth(1.0);
        if (storeGradient) {
            const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearNamedFramebufferfv(map->framebuffer.id(), GL_COLOR, 0, zero);
        } else if (map->moments) {
            // Empty texels hold the moments of the far plane (depth 1), in the stored basis.
            const glm::vec4 far = settings_.msmQuantize16 && moments == 4
                                      ? glsl::gsMsmQuantize(glm::vec4(1.0f))
                                      : glm::vec4(1.0f);
            glClearNamedFramebufferfv(map->framebuffer.id(), GL_COLOR, 0, glm::value_ptr(far));
        }
        glClear(GL_DEPTH_BUFFER_BIT);
        const glm::mat4 lightViewProjection = map->projection.projection * map->projection.view;
        program.set("uLightViewProjection", lightViewProjection);
        // Culled to the light's own clip volume: casters outside it could not write a texel.
        host_->drawMeshes(frame.scene, lightViewProjection, [&](engine::EntityId, const glm::mat4& model) {
            program.set("uModel", model);
            return true;
        });
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    if (moments > 0) {
        filterMoments();
    }
}

void ShadowModule::filterMoments() {
    const engine::gl::Program& blur = host_->programs().get(kBlurProgram, 0);
    blur.use();
    blur.set("uSource", static_cast<int>(mapUnits_[0]));
    blur.set("uRadius", settings_.momentBlurRadius);
    glDisable(GL_DEPTH_TEST);
    if (!fullscreenVertexArray_) {
        fullscreenVertexArray_ = std::make_unique<engine::gl::VertexArray>();
    }
    fullscreenVertexArray_->bind();
    glBindSampler(mapUnits_[0], 0);
    for (const auto& map : maps_) {
        if (settings_.momentBlurRadius > 0) {
            // Horizontal into the temporary level, then vertical back into the moments' level 0.
            map->blurFramebuffer->bind();
            map->moments->bind(mapUnits_[0]);
            blur.set("uDirection", glm::ivec2(1, 0));
            glDrawArrays(GL_TRIANGLES, 0, 3);
            map->framebuffer.bind();
            map->blurTemporary->bind(mapUnits_[0]);
            blur.set("uDirection", glm::ivec2(0, 1));
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glGenerateTextureMipmap(map->moments->id());
    }
    glEnable(GL_DEPTH_TEST);
}

engine::ShaderVariantKey ShadowModule::variantBits(const engine::DrawContext&) const {
    return maps_.empty() ? 0 : lightingKey_;
}

void ShadowModule::bindLightingResources(const engine::gl::Program& program, const engine::DrawContext&) {
    if (maps_.empty()) {
        return;
    }
    if (!samplers_) {
        samplers_ = std::make_unique<Samplers>();
    }
    const MapSampler sampler = techniqueTraits(settings_).sampler;
    const GLuint mapSampler = sampler == MapSampler::DepthLinear     ? samplers_->depthLinear.id()
                              : sampler == MapSampler::CompareLinear ? samplers_->compareLinear.id()
                              : sampler == MapSampler::Moments       ? samplers_->moments.id()
                                                                     : samplers_->compareNearest.id();
    if (settings_.technique == ShadowTechnique::JitteredPcf) {
        if (!jitter_ || jitter_->taps != settings_.jitterTaps) {
            jitter_ = std::make_unique<Jitter>(settings_.jitterTaps);
        }
        glBindTextureUnit(jitterUnit_, jitter_->texture.id());
        glBindSampler(jitterUnit_, 0);
    }
    for (std::size_t slot = 0; slot < maps_.size(); ++slot) {
        glBindTextureUnit(mapUnits_[slot],
                          maps_[slot]->moments ? maps_[slot]->moments->id() : maps_[slot]->depth.id());
        glBindSampler(mapUnits_[slot], mapSampler);
        if (maps_[slot]->gradient) {
            glBindTextureUnit(gradientUnits_[slot], maps_[slot]->gradient->id());
            glBindSampler(gradientUnits_[slot], samplers_->depthLinear.id());
        }
    }
    auto& uploaded = uploadedFrame_[program.id()];
    if (uploaded == frameIndex_ + 1) {
        return; // this program already holds this frame's uniforms
    }
    uploaded = frameIndex_ + 1;

    const GLuint id = program.id();
    glProgramUniform1iv(id, program.uniformLocation("gsShadowSlot"),
                        static_cast<GLsizei>(slotOfLight_.size()), slotOfLight_.data());
    std::vector<glm::mat4> matrices(kMaxMaps, glm::mat4(1.0f));
    std::vector<glm::vec4> texels(kMaxMaps, glm::vec4(0.0f));
    const float resolution = static_cast<float>(settings_.resolution);
    for (std::size_t slot = 0; slot < maps_.size(); ++slot) {
        const LightProjection& projection = maps_[slot]->projection;
        matrices[slot] = projection.worldToShadow;
        texels[slot] = glm::vec4(resolution, 1.0f / resolution, projection.texelScale,
                                 projection.perspective ? 1.0f : 0.0f);
    }
    glProgramUniformMatrix4fv(id, program.uniformLocation("gsShadowMatrix"), kMaxMaps, GL_FALSE,
                              glm::value_ptr(matrices[0]));
    glProgramUniform4fv(id, program.uniformLocation("gsShadowTexel"), kMaxMaps, glm::value_ptr(texels[0]));
    const std::vector<GLint> mapUnits(mapUnits_.begin(), mapUnits_.end());
    const std::vector<GLint> gradientUnits(gradientUnits_.begin(), gradientUnits_.end());
    glProgramUniform1iv(id, program.uniformLocation("gsShadowMap"), kMaxMaps, mapUnits.data());
    if (const GLint location = program.uniformLocation("gsShadowGradientMap"); location >= 0) {
        glProgramUniform1iv(id, location, kMaxMaps, gradientUnits.data());
    }
    program.set("gsShadowConstantBias", settings_.constantBias);
    program.set("gsShadowDepthStep", depthStep(settings_.depthFormat));
    program.set("gsShadowFuzzyScale", settings_.fuzzyScale);
    program.set("gsShadowNormalOffset", settings_.normalOffsetTexels);
    program.set("gsShadowReceiverPlaneClamp", settings_.receiverPlaneClamp ? 1 : 0);
    program.set("gsShadowMinimumVariance", settings_.vsmMinimumVariance);
    program.set("gsShadowBleedingReduction", settings_.lightBleedingReduction);
    program.set("gsShadowMomentBias", settings_.msmMomentBias);
    program.set("gsShadowMsmDequantize", glm::inverse(glsl::GS_MSM_QUANTIZE));
    program.set("gsShadowJitter", static_cast<int>(jitterUnit_));
    program.set("gsJitterPairs", settings_.jitterTaps / 2);
    program.set("gsEarlyOutPairs", settings_.earlyOutTestTaps / 2);
    program.set("gsShadowJitterRadius", settings_.pcfRadius);
    program.set("gsTapCount", static_cast<int>(pattern_.offsets.size()));
    program.set("gsTapInverseCovariance", pattern_.inverseCovariance);
    program.set("gsTapDisplace", settings_.pcfRadius / std::sqrt(2.0f));
    if (const GLint location = program.uniformLocation("gsTapOffsets"); location >= 0) {
        glProgramUniform2fv(id, location, static_cast<GLsizei>(pattern_.offsets.size()),
                            glm::value_ptr(pattern_.offsets[0]));
    }
    if (const GLint location = program.uniformLocation("gsTapFitRows"); location >= 0) {
        glProgramUniform1fv(id, location, static_cast<GLsizei>(pattern_.quadraticFitRows.size()),
                            pattern_.quadraticFitRows.data());
    }
}

} // namespace shadows
