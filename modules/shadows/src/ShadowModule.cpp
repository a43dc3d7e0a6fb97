#include "FittedShadowMaps.h"
#include "JitterTexture.h"
#include "MapInputs.h"
#include "PageMarkPrograms.h"
#include "ShadowSamplers.h"
#include "VirtualShadowMaps.h"
#include "VisibleSamples.h"

#include <shadows/ShadowModule.h>
#include <shadows/VisibilityMath.h>

#include <engine/ForwardRenderer.h>
#include <engine/ProgramCache.h>
#include <engine/gl/Program.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

std::span<const engine::EmbeddedShaderFile> gsShadowShaders();

namespace shadows {

namespace {

const engine::ProgramDesc kDepthProgram{"shadows/depth.vert", "shadows/depth.frag"};
const engine::ProgramDesc kBlurProgram{"shadows/fullscreen.vert", "shadows/blur.frag"};

/// Each cascade's or clipmap level's texture coordinates from those of its light's first drawn cascade or
/// finest level (whose slot goes to, or already is, the light's kind.z), for the vertex stage's one
/// projection per light. Their matrices differ by an orthographic box around one light rotation, so the
/// relation is a scale and an offset per axis; in double, so the first's own is exactly the identity.
void relateToFirstMap(ShadowBlock& block) {
    for (int slot = 0; slot < kMaxMaps; ++slot) {
        block.cascadeScale[slot] = glm::vec4(1.0f);
        block.cascadeOffset[slot] = glm::vec4(0.0f);
    }
    const auto relate = [&](int first, int slot) {
        const glm::dmat4 relation =
            glm::dmat4(block.worldToShadow[slot]) * glm::inverse(glm::dmat4(block.worldToShadow[first]));
        block.cascadeScale[slot] = glm::vec4(relation[0][0], relation[1][1], relation[2][2], 1.0);
        block.cascadeOffset[slot] = glm::vec4(glm::dvec3(relation[3]), 0.0);
    };
    for (LightMapsBlock& maps : block.lights) {
        if (maps.kind.x == static_cast<int>(LightMapsKind::Virtual)) {
            for (int level = 1; level < maps.kind.y; ++level) {
                relate(maps.kind.z, maps.kind.z + level);
            }
            continue;
        }
        if (maps.kind.x != static_cast<int>(LightMapsKind::Cascades)) {
            continue;
        }
        int first = -1;
        for (int cascade = 0; cascade < maps.kind.y && first < 0; ++cascade) {
            first = maps.slots[cascade];
        }
        maps.kind.z = std::max(first, 0);
        if (first < 0) {
            continue;
        }
        for (int cascade = 0; cascade < maps.kind.y; ++cascade) {
            const int slot = maps.slots[cascade];
            if (slot >= 0 && slot != first) {
                relate(first, slot);
            }
        }
    }
}

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
    stats.shadowMaps = static_cast<int>(slots_.size());
    stats.reusedMaps = reusedMaps_;
    stats.keptMaps = keptMaps_;
    stats.sharedViewDepth = sharedViewDepth_;
    stats.casters = casters_;
    stats.fitMilliseconds = fitMilliseconds_;
    stats.mapsMilliseconds = mapsMilliseconds_;
    if (allocation_) {
        stats.bytes = allocation_->bytes();
        stats.virtualMaps = allocation_->servedVirtualMaps();
        if (stats.virtualMaps) {
            stats.pages = allocation_->pageStats();
        } else if (!slots_.empty()) {
            stats.mapResolution = slots_.front().resolution; // one array holds every map, at one side
            for (const MapSlot& slot : slots_) {
                const glm::ivec4 drawn = drawnTexels(slot.projection, stats.mapResolution);
                stats.casterTexels += static_cast<std::size_t>(drawn.z) * static_cast<std::size_t>(drawn.w);
            }
        }
    }
    return stats;
}

void ShadowModule::setPartTiming(std::optional<engine::TimingMethod> method) {
    if (!method) {
        partTimer_.reset();
    } else if (!partTimer_ || partTimer_->method() != *method) {
        partTimer_.emplace(*method);
    }
    fitMilliseconds_ = mapsMilliseconds_ = -1.0;
}

std::optional<LightProjection> ShadowModule::lightProjection(int lightIndex) const {
    for (const MapSlot& slot : slots_) {
        if (slot.lightIndex == lightIndex) {
            return slot.projection;
        }
    }
    return std::nullopt;
}

std::vector<LightProjection> ShadowModule::lightProjections(int lightIndex) const {
    std::vector<LightProjection> projections;
    for (const MapSlot& slot : slots_) {
        if (slot.lightIndex == lightIndex) {
            projections.push_back(slot.projection);
        }
    }
    return projections;
}

void ShadowModule::attach(engine::ModuleHost& host) {
    host_ = &host;
    host.shaders().add(gsShadowShaders());
    host.shaders().add("shadows/techniques.glsl", techniqueIncludes());
    mapUnit_ = host.reserveTextureUnit();
    gradientUnit_ = host.reserveTextureUnit();
    jitterUnit_ = host.reserveTextureUnit();
    pageTableUnit_ = host.reserveTextureUnit();
    samples_ = std::make_unique<VisibleSamples>();
    warnings_ = std::make_unique<OnceWarnings>();
    dirty_ = true;
}

void ShadowModule::detach() {
    releaseResources();
    samples_.reset();
    warnings_.reset();
    pageMarkPrograms_.reset();
    shadowBlock_.reset();
    samplers_.reset();
    jitter_.reset();
    fullscreenVertexArray_.reset();
    if (partTimer_) {
        partTimer_.emplace(partTimer_->method()); // its queries belong to this context
    }
    host_ = nullptr;
}

void ShadowModule::releaseResources() {
    slots_.clear();
    allocation_.reset();
    uploadedFrame_.clear();
    drawnFrom_.reset();
    reusedMaps_ = false;
    keptMaps_ = false;
}

MapAllocator& ShadowModule::allocation() {
    if (allocation_) {
        return *allocation_;
    }
    if (settings_.mapAllocation == MapAllocation::Virtual) {
        if (!pageMarkPrograms_) {
            pageMarkPrograms_ = std::make_unique<PageMarkPrograms>(host_->shaders());
        }
        allocation_ = std::make_unique<VirtualShadowMaps>(*host_, settings_, plan_, *samples_,
                                                          *pageMarkPrograms_, *warnings_);
    } else {
        allocation_ = std::make_unique<FittedShadowMaps>(*host_, settings_, plan_, *samples_, *warnings_);
    }
    return *allocation_;
}

std::vector<engine::ShaderChunk> ShadowModule::shaderChunks() const {
    return {{"vertex_declarations", "shadows/chunk-vertex-declarations",
             "#ifdef GS_SHADOWS\n#include \"shadows/vertex.glsl\"\n#endif"},
            {"vertex_outputs", "shadows/chunk-vertex-outputs",
             "#ifdef GS_SHADOWS\ngsShadowVertexOutputs(world);\n#endif"},
            {"declarations", "shadows/chunk-declarations",
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
}

void ShadowModule::fitMaps(const engine::FrameContext& frame, const FitView& fit,
                           const std::vector<Aabb>& boxes, const std::vector<engine::EntityId>& entities) {
    slots_.clear();
    std::vector<LightMapsBlock> lights(engine::ForwardRenderer::kMaxLights);
    for (LightMapsBlock& maps : lights) {
        maps.slots = maps.faceSlots = glm::ivec4(-1);
    }
    allocation().allocate({frame, fit, boxes, entities, !fitView_.has_value()}, slots_, lights);
    if (slots_.empty()) {
        return;
    }
    layoutKey_ = layoutKey(lights);
    uploadBlock(lights, fit, frame.lights);
}

engine::ShaderVariantKey ShadowModule::layoutKey(const std::vector<LightMapsBlock>& lights) const {
    // llvmpipe runs both sides of every branch under a mask, so a layout compiled in costs its lookups on
    // every fragment whether a light uses it or not; only this frame's layouts are compiled.
    constexpr std::array<std::string_view, 6> kDefines{"",
                                                       "GS_SHADOW_LAYOUT_SINGLE",
                                                       "GS_SHADOW_LAYOUT_CASCADES",
                                                       "GS_SHADOW_LAYOUT_CUBE",
                                                       "GS_SHADOW_LAYOUT_VIRTUAL",
                                                       "GS_SHADOW_LAYOUT_VIRTUAL_FACES"};
    engine::ShaderVariantKey key = 0;
    for (const LightMapsBlock& maps : lights) {
        if (maps.kind.x > 0) {
            key |= host_->variantFlag(kDefines[static_cast<std::size_t>(maps.kind.x)]);
        }
    }
    // One map in all: its slot is 0, and the lookups index the block's arrays by a constant.
    if (slots_.size() == 1) {
        key |= host_->variantFlag("GS_SHADOW_ONE_MAP");
    }
    // Only directional maps: no perspective divide or distance-scaled texel in the lookups.
    if (std::none_of(slots_.begin(), slots_.end(),
                     [](const MapSlot& slot) { return slot.projection.perspective; })) {
        key |= host_->variantFlag("GS_SHADOW_ORTHOGRAPHIC");
    }
    return key;
}

void ShadowModule::renderPrePasses(const engine::FrameContext& frame) {
    casters_ = {};
    sharedViewDepth_ = false;
    // Fitted here rather than in prepareFrame, so the pass timing includes the view's sample pass. World
    // bounds of every mesh (computed once per mesh by the host): receivers for the fit, and casters.
    MapInputs inputs{
        fitView_.value_or(FitView{frame.view, frame.projection}), frame.target.size, frame.lights, {}};
    std::vector<Aabb> boxes;
    std::vector<engine::EntityId> entities;
    host_->forEachMeshBounds(
        frame.scene, [&](engine::EntityId entity, const glm::mat4& model, const Aabb& local) {
            boxes.push_back(local.transformed(model));
            entities.push_back(entity);
            inputs.meshes.push_back({entity, model, frame.scene.entity(entity).mesh->mesh});
        });
    // Virtual maps are kept once an update with these inputs drew no page: their page table's drawn bits (the
    // pages debug view) and page counters then say what a kept frame draws, nothing.
    const bool reusable = settings_.reuseUnchangedMaps;
    reusedMaps_ = reusable && allocation_ && drawnFrom_ && *drawnFrom_ == inputs &&
                  (!allocation_->servedVirtualMaps() || allocation_->pageStats().rendered == 0);
    fitMilliseconds_ = mapsMilliseconds_ = partTimer_ ? 0.0 : -1.0;
    keptMaps_ = false;
    if (reusedMaps_) {
        return;
    }
    const std::unique_ptr<MapInputs> drawnFrom = std::move(drawnFrom_); // until this frame's maps are drawn
    const auto timedPart = [&](double& milliseconds, const auto& part) {
        if (partTimer_) {
            partTimer_->begin();
        }
        part();
        if (partTimer_) {
            milliseconds = partTimer_->end();
        }
    };
    const std::uint64_t sampleDraws = samples_->draws();
    timedPart(fitMilliseconds_, [&] { fitMaps(frame, inputs.fit, boxes, entities); });
    sharedViewDepth_ = samples_->draws() != sampleDraws && samples_->sharedDepth();
    // The view moved, but within the placements of the maps drawn last, nothing they hold having changed.
    keptMaps_ = reusable && drawnFrom && drawnFrom->sameScene(inputs) && allocation_->holds(slots_);
    if (!slots_.empty() && !keptMaps_) {
        timedPart(mapsMilliseconds_, [&] { drawMaps(frame); });
    }
    if (reusable) {
        drawnFrom_ = std::make_unique<MapInputs>(std::move(inputs));
    }
}

void ShadowModule::drawMaps(const engine::FrameContext& frame) {
    const engine::gl::Program& program = host_->programs().get(kDepthProgram, depthKey_);
    program.use();
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBlockBinding, shadowBlock_->id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const bool cullsEveryMesh =
        settings_.casterFaces == CasterFaces::Front || settings_.casterFaces == CasterFaces::Back;
    if (cullsEveryMesh) {
        glEnable(GL_CULL_FACE);
        glCullFace(settings_.casterFaces == CasterFaces::Front ? GL_BACK : GL_FRONT);
    }
    if (plan_.offsetsCasters) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(settings_.slopeScale, settings_.slopeUnits);
    }
    glDisable(GL_FRAMEBUFFER_SRGB);
    const CasterOmissions omissions{settings_.casterFaces == CasterFaces::Auto ? engine::HiddenFaces::Skip
                                                                               : engine::HiddenFaces::Draw,
                                    plan_.leavesOutShadowlessPlanes};
    casters_ = allocation_->render(frame.scene, program, slots_, omissions);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    if (plan_.blursMoments) {
        blurMoments();
    }
    // The levels a soft technique filters over; a virtual atlas's tiles keep their chains apart within the
    // levels its border holds (msm-soft.glsl reads no coarser one). A virtual atlas none of whose pages was
    // drawn this frame keeps last frame's chain.
    const bool drewPages = !allocation_->servedVirtualMaps() || allocation_->pageStats().rendered > 0;
    if (plan_.momentLevels > 1 && drewPages) {
        glGenerateTextureMipmap(allocation_->sampled()->moments->id());
    }
}

void ShadowModule::blurMoments() {
    const engine::gl::Program& blur = host_->programs().get(kBlurProgram, 0);
    blur.use();
    blur.set("uSource", static_cast<int>(mapUnit_));
    blur.set("uRadius", settings_.momentBlurRadius);
    glDisable(GL_DEPTH_TEST);
    if (!fullscreenVertexArray_) {
        fullscreenVertexArray_ = std::make_unique<engine::gl::VertexArray>();
    }
    fullscreenVertexArray_->bind();
    glBindSampler(mapUnit_, 0);
    allocation_->blurMoments(blur, mapUnit_);
    glEnable(GL_DEPTH_TEST);
}

engine::ShaderVariantKey ShadowModule::variantBits(const engine::DrawContext&) const {
    return slots_.empty() ? 0 : lightingKey_ | layoutKey_;
}

void ShadowModule::bindLightingResources(const engine::gl::Program& program, const engine::DrawContext&) {
    if (slots_.empty()) {
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
    const ShadowMapArray& maps = *allocation_->sampled();
    glBindTextureUnit(mapUnit_, maps.sampledTexture());
    glBindSampler(mapUnit_, samplers_->forMap(plan_.sampler));
    if (maps.gradient) {
        glBindTextureUnit(gradientUnit_, maps.gradient->id());
        glBindSampler(gradientUnit_, samplers_->linear());
    }
    if (const GLuint pageTable = allocation_->pageTable(); pageTable != 0) {
        glBindTextureUnit(pageTableUnit_, pageTable);
        glBindSampler(pageTableUnit_, 0);
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
    program.set("gsShadowMaps", static_cast<int>(mapUnit_));
    if (const GLint location = program.uniformLocation("gsShadowGradientMaps"); location >= 0) {
        glProgramUniform1i(id, location, static_cast<GLint>(gradientUnit_));
    }
    program.set("gsShadowJitter", static_cast<int>(jitterUnit_));
    if (const GLint location = program.uniformLocation("gsShadowPageTable"); location >= 0) {
        glProgramUniform1i(id, location, static_cast<GLint>(pageTableUnit_));
    }
    if (const GLint location = program.uniformLocation("gsTapOffsets"); location >= 0) {
        glProgramUniform2fv(id, location, static_cast<GLsizei>(pattern_.offsets.size()),
                            glm::value_ptr(pattern_.offsets[0]));
    }
    if (const GLint location = program.uniformLocation("gsTapFitRows"); location >= 0) {
        glProgramUniform1fv(id, location, static_cast<GLsizei>(pattern_.quadraticFitRows.size()),
                            pattern_.quadraticFitRows.data());
    }
    if (const GLint location = program.uniformLocation("gsTapNearestFirst"); location >= 0) {
        glProgramUniform1iv(id, location, static_cast<GLsizei>(pattern_.nearestFirst.size()),
                            pattern_.nearestFirst.data());
    }
    if (const GLint location = program.uniformLocation("gsTapLinkDistance"); location >= 0) {
        glProgramUniform1f(id, location, pattern_.linkDistance);
    }
}

void ShadowModule::uploadBlock(const std::vector<LightMapsBlock>& lights, const FitView& fit,
                               std::span<const engine::FrameLight> frameLights) {
    ShadowBlock block{};
    for (int slot = 0; slot < kMaxMaps; ++slot) {
        block.worldToShadow[slot] = glm::mat4(1.0f);
    }
    for (std::size_t slot = 0; slot < slots_.size(); ++slot) {
        const LightProjection& projection = slots_[slot].projection;
        const auto resolution = static_cast<float>(slots_[slot].resolution);
        block.worldToShadow[slot] = projection.worldToShadow;
        block.texel[slot] = glm::vec4(resolution, 1.0f / resolution, projection.texelScale,
                                      projection.perspective ? 1.0f : 0.0f);
        float size = 0.0f;
        for (const engine::FrameLight& light : frameLights) {
            if (light.index == slots_[slot].lightIndex) {
                size = softLightSize(light.light, settings_.lightSizeScale);
            }
        }
        block.depthRange[slot] = glm::vec4(projection.depthRange, projection.litBorderTexels, size);
        block.softReachTexels[slot / 4][static_cast<int>(slot % 4)] =
            std::max(projection.softReachTexels, plan_.softReachTexels);
    }
    std::copy(lights.begin(), lights.end(), block.lights);
    relateToFirstMap(block);
    // View depth is -z in view space: minus the view matrix's third row.
    block.viewDepth = -glm::vec4(fit.view[0][2], fit.view[1][2], fit.view[2][2], fit.view[3][2]);
    block.msmDequantize = glm::inverse(glsl::GS_MSM_QUANTIZE);
    block.tapInverseCovariance[0] = glm::vec4(pattern_.inverseCovariance[0], 0.0f, 0.0f);
    block.tapInverseCovariance[1] = glm::vec4(pattern_.inverseCovariance[1], 0.0f, 0.0f);
    block.techniqueParameters = plan_.shaderParameters;
    block.constantBiasTexels = plan_.constantBiasTexels;
    block.depthStep = depthStep(settings_.depthFormat);
    block.fuzzyScale = settings_.fuzzyScale;
    block.normalOffset = plan_.normalOffsetTexels;
    block.depthBias = plan_.depthBias;
    block.depthBiasFloor = plan_.depthBiasFloor;
    block.minimumVariance = settings_.vsmMinimumVariance;
    block.bleedingReduction = settings_.lightBleedingReduction;
    block.momentBias = settings_.msmMomentBias;
    block.jitterRadius = settings_.pcfRadius;
    block.receiverPlaneClamp = settings_.receiverPlaneClamp ? 1 : 0;
    block.jitterPairs = settings_.jitterTaps / 2;
    block.earlyOutPairs = settings_.earlyOutTestTaps / 2;
    block.tapCount = static_cast<std::int32_t>(pattern_.offsets.size());
    block.tapDisplace = settings_.pcfRadius / std::sqrt(2.0f);
    block.cascadeBlend = settings_.cascadeBlend;
    allocation_->describe(block);
    if (!shadowBlock_) {
        shadowBlock_ =
            std::make_unique<engine::gl::Buffer>(sizeof(ShadowBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    shadowBlock_->update(0, sizeof block, &block);
}

} // namespace shadows
