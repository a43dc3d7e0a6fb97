#include "JitterTexture.h"
#include "ShadowBlock.h"
#include "ShadowMapTarget.h"
#include "ShadowSamplers.h"

#include <shadows/ShadowModule.h>
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

const engine::ProgramDesc kDepthProgram{"shadows/depth.vert", "shadows/depth.frag"};
const engine::ProgramDesc kBlurProgram{"shadows/fullscreen.vert", "shadows/blur.frag"};

/// Includes every embedded technique file (shaders/shadows/techniques/), so adding one needs no list.
std::string techniqueIncludes() {
    constexpr std::string_view kFolder = "shadows/techniques/";
    std::string includes;
    for (const engine::EmbeddedShaderFile& file : gsShadowShaders()) {
        if (std::string_view(file.name).starts_with(kFolder)) {
            includes += "#include \"" + std::string(file.name) + "\"\n";
        }
    }
    return includes;
}

} // namespace

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
    plan_ = ShadowPlan::resolve(settings_);
    pattern_ = settings_.tapPattern();
    dirty_ = true;
}

ShadowStats ShadowModule::stats() const {
    ShadowStats stats;
    stats.shadowMaps = static_cast<int>(maps_.size());
    for (const auto& map : maps_) {
        stats.bytes += map->bytes(plan_);
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
    host.shaders().add("shadows/techniques.glsl", techniqueIncludes());
    for (int slot = 0; slot < kMaxMaps; ++slot) {
        mapUnits_.push_back(host.reserveTextureUnit());
        gradientUnits_.push_back(host.reserveTextureUnit());
    }
    jitterUnit_ = host.reserveTextureUnit();
    dirty_ = true;
}

void ShadowModule::detach() {
    releaseResources();
    shadowBlock_.reset();
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

engine::ShaderVariantKey ShadowModule::variantKey(const std::vector<std::string_view>& defines) const {
    engine::ShaderVariantKey key = 0;
    for (const std::string_view define : defines) {
        key |= host_->variantFlag(define);
    }
    return key;
}

void ShadowModule::prepareFrame(const engine::FrameContext& frame) {
    frameIndex_ = frame.frameIndex;
    if (dirty_) {
        releaseResources();
        lightingKey_ = variantKey(plan_.lightingDefines);
        depthKey_ = variantKey(plan_.depthDefines);
        dirty_ = false;
    }
    // World bounds of every mesh (computed once per mesh by the host): receivers for the fit, and casters.
    std::vector<Aabb> boxes;
    host_->forEachMeshBounds(frame.scene, [&](engine::EntityId, const glm::mat4& model, const Aabb& local) {
        boxes.push_back(local.transformed(model));
    });

    std::vector<int> slotOfLight(engine::ForwardRenderer::kMaxLights, -1);
    std::size_t used = 0;
    for (const engine::FrameLight& light : frame.lights) {
        // Point lights get cube maps in a following commit.
        if (!light.light.castsShadows || used == kMaxMaps || light.light.type == engine::LightType::Point) {
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
            maps_.push_back(std::make_unique<ShadowMapTarget>(settings_.resolution, plan_));
        }
        maps_[used]->lightIndex = light.index;
        maps_[used]->projection = projection;
        slotOfLight[static_cast<std::size_t>(light.index)] = static_cast<int>(used);
        ++used;
    }
    // Lights that stopped casting (or left the view) give their maps back.
    maps_.resize(used);
    if (used > 0) {
        uploadBlock(slotOfLight);
    }
}

void ShadowModule::renderPrePasses(const engine::FrameContext& frame) {
    if (maps_.empty()) {
        return;
    }
    const engine::gl::Program& program = host_->programs().get(kDepthProgram, depthKey_);
    program.use();
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBlockBinding, shadowBlock_->id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    if (settings_.casterFaces != CasterFaces::Both) {
        glEnable(GL_CULL_FACE);
        glCullFace(settings_.casterFaces == CasterFaces::Front ? GL_BACK : GL_FRONT);
    }
    if (plan_.offsetsCasters) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(settings_.slopeScale, settings_.slopeUnits);
    }
    glDisable(GL_FRAMEBUFFER_SRGB);
    for (const auto& map : maps_) {
        map->framebuffer.bind();
        glViewport(0, 0, settings_.resolution, settings_.resolution);
        glClearDepth(1.0);
        if (map->gradient) {
            const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearNamedFramebufferfv(map->framebuffer.id(), GL_COLOR, 0, zero);
        } else if (map->moments) {
            glClearNamedFramebufferfv(map->framebuffer.id(), GL_COLOR, 0, glm::value_ptr(plan_.momentsClear));
        }
        glClear(GL_DEPTH_BUFFER_BIT);
        const glm::mat4 lightViewProjection = map->projection.projection * map->projection.view;
        program.set("uLightViewProjection", lightViewProjection);
        program.set("uDepthRange", map->projection.depthRange);
        // Culled to the light's own clip volume: casters outside it could not write a texel.
        host_->drawMeshes(frame.scene, lightViewProjection, [&](engine::EntityId, const glm::mat4& model) {
            program.set("uModel", model);
            return true;
        });
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    if (plan_.momentsFormat != 0) {
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
        samplers_ = std::make_unique<ShadowSamplers>();
    }
    if (plan_.needsJitterTexture) {
        if (!jitter_ || jitter_->taps() != settings_.jitterTaps) {
            jitter_ = std::make_unique<JitterTexture>(settings_.jitterTaps);
        }
        glBindTextureUnit(jitterUnit_, jitter_->id());
        glBindSampler(jitterUnit_, 0);
    }
    for (std::size_t slot = 0; slot < maps_.size(); ++slot) {
        glBindTextureUnit(mapUnits_[slot], maps_[slot]->sampledTexture());
        glBindSampler(mapUnits_[slot], samplers_->forMap(plan_.sampler));
        if (maps_[slot]->gradient) {
            glBindTextureUnit(gradientUnits_[slot], maps_[slot]->gradient->id());
            glBindSampler(gradientUnits_[slot], samplers_->linear());
        }
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBlockBinding, shadowBlock_->id());
    auto& uploaded = uploadedFrame_[program.id()];
    if (uploaded == frameIndex_ + 1) {
        return; // this program already holds this frame's uniforms
    }
    uploaded = frameIndex_ + 1;

    // What the block cannot hold: sampler units, and the tap arrays (std140 would pad each float to 16
    // bytes).
    const GLuint id = program.id();
    const std::vector<GLint> mapUnits(mapUnits_.begin(), mapUnits_.end());
    const std::vector<GLint> gradientUnits(gradientUnits_.begin(), gradientUnits_.end());
    glProgramUniform1iv(id, program.uniformLocation("gsShadowMap"), kMaxMaps, mapUnits.data());
    if (const GLint location = program.uniformLocation("gsShadowGradientMap"); location >= 0) {
        glProgramUniform1iv(id, location, kMaxMaps, gradientUnits.data());
    }
    program.set("gsShadowJitter", static_cast<int>(jitterUnit_));
    if (const GLint location = program.uniformLocation("gsTapOffsets"); location >= 0) {
        glProgramUniform2fv(id, location, static_cast<GLsizei>(pattern_.offsets.size()),
                            glm::value_ptr(pattern_.offsets[0]));
    }
    if (const GLint location = program.uniformLocation("gsTapFitRows"); location >= 0) {
        glProgramUniform1fv(id, location, static_cast<GLsizei>(pattern_.quadraticFitRows.size()),
                            pattern_.quadraticFitRows.data());
    }
}

void ShadowModule::uploadBlock(const std::vector<int>& slotOfLight) {
    ShadowBlock block{};
    const float resolution = static_cast<float>(settings_.resolution);
    for (int slot = 0; slot < kMaxMaps; ++slot) {
        block.worldToShadow[slot] = glm::mat4(1.0f);
    }
    for (std::size_t slot = 0; slot < maps_.size(); ++slot) {
        const LightProjection& projection = maps_[slot]->projection;
        block.worldToShadow[slot] = projection.worldToShadow;
        block.texel[slot] = glm::vec4(resolution, 1.0f / resolution, projection.texelScale,
                                      projection.perspective ? 1.0f : 0.0f);
        block.depthRange[slot] = glm::vec4(projection.depthRange, 0.0f, 0.0f);
    }
    for (std::size_t light = 0; light < slotOfLight.size(); ++light) {
        block.slotOfLight[light / 4][static_cast<glm::length_t>(light % 4)] = slotOfLight[light];
    }
    block.msmDequantize = glm::inverse(glsl::GS_MSM_QUANTIZE);
    block.tapInverseCovariance[0] = glm::vec4(pattern_.inverseCovariance[0], 0.0f, 0.0f);
    block.tapInverseCovariance[1] = glm::vec4(pattern_.inverseCovariance[1], 0.0f, 0.0f);
    block.techniqueParameters = plan_.shaderParameters;
    block.constantBiasTexels = settings_.constantBiasTexels;
    block.depthStep = depthStep(settings_.depthFormat);
    block.fuzzyScale = settings_.fuzzyScale;
    block.normalOffset = plan_.normalOffsetTexels;
    block.depthBias = plan_.depthBias;
    block.minimumVariance = settings_.vsmMinimumVariance;
    block.bleedingReduction = settings_.lightBleedingReduction;
    block.momentBias = settings_.msmMomentBias;
    block.jitterRadius = settings_.pcfRadius;
    block.receiverPlaneClamp = settings_.receiverPlaneClamp ? 1 : 0;
    block.jitterPairs = settings_.jitterTaps / 2;
    block.earlyOutPairs = settings_.earlyOutTestTaps / 2;
    block.tapCount = static_cast<std::int32_t>(pattern_.offsets.size());
    block.tapDisplace = settings_.pcfRadius / std::sqrt(2.0f);
    if (!shadowBlock_) {
        shadowBlock_ =
            std::make_unique<engine::gl::Buffer>(sizeof(ShadowBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    shadowBlock_->update(0, sizeof block, &block);
}

} // namespace shadows
