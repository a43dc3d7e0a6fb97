#include "JitterTexture.h"
#include "ShadowBlock.h"
#include "ShadowMapArray.h"
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
#include <iostream>
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

/// `drawn` when any slot of `maps` holds a map this frame, else None (the lighting pass reads nothing).
std::int32_t drawnKind(const LightMapsBlock& maps, LightMapsKind drawn) {
    const bool any = glm::any(glm::greaterThanEqual(maps.slots, glm::ivec4(0))) ||
                     glm::any(glm::greaterThanEqual(maps.faceSlots, glm::ivec4(0)));
    return static_cast<std::int32_t>(any ? drawn : LightMapsKind::None);
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
    stats.bytes = maps_ ? maps_->bytes(plan_) : 0;
    stats.virtualMaps = virtualFrame_;
    if (virtualFrame_ && virtual_) {
        stats.bytes += virtual_->bytes();
        stats.pages = virtual_->stats();
    }
    return stats;
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
    dirty_ = true;
}

void ShadowModule::detach() {
    releaseResources();
    samples_.reset();
    pageMarkProgram_.reset();
    shadowBlock_.reset();
    samplers_.reset();
    jitter_.reset();
    fullscreenVertexArray_.reset();
    host_ = nullptr;
}

void ShadowModule::releaseResources() {
    slots_.clear();
    maps_.reset();
    virtual_.reset();
    virtualFrame_ = false;
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
}

bool ShadowModule::fitToVisibleSamples(const engine::FrameContext& frame, const engine::FrameLight& light,
                                       const FitView& fit, std::span<const Aabb> boxes,
                                       LightMapsBlock& maps) {
    if (!samples_) {
        samples_ = std::make_unique<VisibleSamples>();
    }
    const auto bounds = samples_->measure(*host_, frame, fit, lightView(light.direction),
                                          settings_.cascadeSplitWeight, settings_.cascadeBlend);
    if (!bounds) {
        if (!warnedNoSamples_) {
            std::cerr
                << "shadows: the view shows no surface to fit the directional maps to (an empty view, or "
                   "the camera inside geometry): fitted to mesh bounds instead\n";
            warnedNoSamples_ = true;
        }
        return false;
    }
    // Only the samples a caster can shadow need texels.
    const Aabb shadowable = shadowableRegion(light.direction, fit.projection * fit.view, boxes);
    std::array<LightRect, kSampleSlices> slices{};
    for (std::size_t s = 0; s < slices.size(); ++s) {
        slices[s] = clippedTo(bounds->slices[s], shadowable);
    }
    const int resolution = settings_.resolution;
    const int count = settings_.cascadeCount > 0
                          ? settings_.cascadeCount
                          : densityCascadeCount(slices, bounds->sliceDepths, resolution, fit.projection,
                                                frame.target.size.y);
    const auto fitted = [&](int cascade) {
        return fitToSamples(light.direction,
                            slices[static_cast<std::size_t>(sampleSliceIndex(count, cascade))], boxes,
                            resolution, plan_.kernelReachTexels, settings_.texelSnapping);
    };
    if (count == 1) {
        maps.slots.x = addSlot(light.index, fitted(0));
        maps.kind.x = drawnKind(maps, LightMapsKind::Single);
        return true;
    }
    for (int cascade = 0; cascade < count; ++cascade) {
        const auto slice = static_cast<std::size_t>(sampleSliceIndex(count, cascade));
        // The split itself, not the slice, which starts earlier by the previous cascade's blend band.
        maps.splitNear[cascade] = cascade == 0 ? bounds->viewDepth.x : bounds->sliceDepths[slice - 1].y;
        maps.splitFar[cascade] = bounds->sliceDepths[slice].y;
        if (!slices[slice].empty()) {
            maps.slots[cascade] = addSlot(light.index, fitted(cascade));
        }
    }
    maps.kind = glm::ivec4(drawnKind(maps, LightMapsKind::Cascades), count, 0, 0);
    return true;
}

int ShadowModule::addSlot(int lightIndex, const LightProjection& projection) {
    if (!projection.valid || slots_.size() == static_cast<std::size_t>(kMaxMaps)) {
        return -1;
    }
    slots_.push_back({lightIndex, projection, settings_.resolution});
    return static_cast<int>(slots_.size()) - 1;
}

bool ShadowModule::fitVirtualMaps(const engine::FrameContext& frame, const FitView& fit,
                                  std::span<const Aabb> boxes,
                                  const std::map<engine::EntityId, Aabb>& casters,
                                  std::vector<LightMapsBlock>& lights) {
    std::vector<engine::FrameLight> casting;
    for (const engine::FrameLight& light : frame.lights) {
        if (light.light.castsShadows) {
            casting.push_back(light);
        }
    }
    if (casting.empty()) {
        return false;
    }
    if (!samples_) {
        samples_ = std::make_unique<VisibleSamples>();
    }
    samples_->draw(*host_, frame, fit);
    if (!virtual_) {
        virtual_ = std::make_unique<VirtualShadowMaps>(settings_, plan_);
    }
    if (!pageMarkProgram_) {
        const std::array stages{host_->shaders().preprocess(GL_COMPUTE_SHADER, "shadows/pages.comp", {})};
        pageMarkProgram_ = std::make_unique<engine::gl::Program>("shadows/pages.comp", stages);
    }
    const std::vector<VirtualShadowMaps::Light> virtualLights = virtual_->update(
        *pageMarkProgram_, fit, casting, casters, boxes, samples_->depthTexture(), samples_->size());
    static_assert(kPageTableLayers == kMaxMaps, "a page-table layer per map slot");
    for (const engine::FrameLight& light : casting) {
        if (std::none_of(
                virtualLights.begin(), virtualLights.end(),
                [&](const VirtualShadowMaps::Light& served) { return served.index == light.index; })) {
            std::cerr << "shadows: light " << light.index << " casts no shadow this frame: its virtual maps' "
                      << "page tables do not fit the " << kPageTableLayers << " layers beside the others\n";
        }
    }
    for (const VirtualShadowMaps::Light& light : virtualLights) {
        LightMapsBlock& maps = lights[static_cast<std::size_t>(light.index)];
        int needed = light.faceCount == 0 ? kClipmapLevels : 0;
        for (int face = 0; face < light.faceCount; ++face) {
            needed += light.faces[static_cast<std::size_t>(face)].face.valid ? 1 : 0;
        }
        if (slots_.size() + static_cast<std::size_t>(needed) > static_cast<std::size_t>(kMaxMaps)) {
            std::cerr << "shadows: light " << light.index << " casts no shadow this frame: its " << needed
                      << " virtual maps do not fit the " << kMaxMaps << " map slots beside the others\n";
            continue;
        }
        if (light.faceCount == 0) {
            const int first = static_cast<int>(slots_.size());
            for (int level = 0; level < kClipmapLevels; ++level) {
                slots_.push_back({light.index,
                                  light.geometry.levelProjection(light.geometry.finestLevel + level),
                                  kVirtualResolution});
            }
            maps.kind =
                glm::ivec4(static_cast<int>(LightMapsKind::Virtual), kClipmapLevels, first, light.pageLayer);
            continue;
        }
        // A spot map or cube faces in the fitted layout's slots; the levels are the mip levels of each.
        for (int face = 0; face < light.faceCount; ++face) {
            const LightProjection& projection = light.faces[static_cast<std::size_t>(face)].face;
            int slot = -1;
            if (projection.valid) {
                slot = static_cast<int>(slots_.size());
                slots_.push_back({light.index, projection, kVirtualResolution});
            }
            if (face < 4) {
                maps.slots[face] = slot;
            } else {
                maps.faceSlots[face - 4] = slot;
            }
        }
        maps.kind = glm::ivec4(drawnKind(maps, LightMapsKind::VirtualFaces), light.levels(), light.faceCount,
                               light.pageLayer);
    }
    const VirtualPageStats& pages = virtual_->stats();
    if ((pages.coarsened > 0 || pages.refused > 0) && !warnedPageBudget_) {
        std::cerr << "shadows: the page budget (virtualBudgetMiB " << settings_.virtualBudgetMiB << ", "
                  << pages.poolPages
                  << " pages) holds fewer pages than the view asks for: " << pages.coarsened
                  << " requests moved to coarser levels, " << pages.refused
                  << " left without texels (lit); the stats count them every frame\n";
        warnedPageBudget_ = true;
    }
    return true;
}

void ShadowModule::fitMaps(const engine::FrameContext& frame) {
    // World bounds of every mesh (computed once per mesh by the host): receivers for the fit, and casters.
    std::vector<Aabb> boxes;
    std::map<engine::EntityId, Aabb> casters; // the same by entity: virtual maps redraw where one moved
    host_->forEachMeshBounds(frame.scene,
                             [&](engine::EntityId entity, const glm::mat4& model, const Aabb& local) {
                                 boxes.push_back(local.transformed(model));
                                 if (settings_.mapAllocation == MapAllocation::Virtual) {
                                     casters[entity].extend(boxes.back());
                                 }
                             });

    const FitView fit = fitView_.value_or(FitView{frame.view, frame.projection});
    const glm::mat4 fitViewProjection = fit.projection * fit.view;
    const int resolution = settings_.resolution;
    // Where the receivers in view lie in depth: the cascades' range, and their automatic count.
    const std::optional<glm::vec2> visibleRange = visibleDepthRange(fit, boxes);

    slots_.clear();
    std::vector<LightMapsBlock> lights(engine::ForwardRenderer::kMaxLights);
    for (LightMapsBlock& maps : lights) {
        maps.slots = maps.faceSlots = glm::ivec4(-1);
    }
    virtualFrame_ = settings_.mapAllocation == MapAllocation::Virtual &&
                    fitVirtualMaps(frame, fit, boxes, casters, lights);
    for (const engine::FrameLight& light : frame.lights) {
        LightMapsBlock& maps = lights[static_cast<std::size_t>(light.index)];
        if (!light.light.castsShadows || virtualFrame_) {
            continue;
        }
        // The slot of a fitted map, -1 when it has nothing to draw or every slot is taken.
        const auto add = [&](const LightProjection& projection) { return addSlot(light.index, projection); };
        const auto kind = [&](LightMapsKind drawn) { return drawnKind(maps, drawn); };
        switch (light.light.type) {
        case engine::LightType::Directional: {
            if (settings_.directionalFit == DirectionalFit::Samples &&
                fitToVisibleSamples(frame, light, fit, boxes, maps)) {
                break;
            }
            const int count = settings_.cascadeCount > 0
                                  ? settings_.cascadeCount
                                  : automaticCascadeCount(visibleRange.value_or(glm::vec2(1.0f)));
            if (count == 1 || !visibleRange) {
                maps.slots.x = add(fitDirectionalLight(light.direction, fitViewProjection, boxes, resolution,
                                                       settings_.texelSnapping));
                maps.kind.x = kind(LightMapsKind::Single);
                break;
            }
            const std::vector<float> splits =
                cascadeSplits(visibleRange->x, visibleRange->y, count, settings_.cascadeSplitWeight);
            for (int cascade = 0; cascade < count; ++cascade) {
                const auto c = static_cast<std::size_t>(cascade);
                // A cascade also covers the previous one's blend band, which fades into it.
                const float sliceNear =
                    splits[c] - (cascade > 0 ? settings_.cascadeBlend * (splits[c] - splits[c - 1]) : 0.0f);
                maps.splitNear[cascade] = splits[c];
                maps.splitFar[cascade] = splits[c + 1];
                if (hasReceiversBetween(fit, boxes, sliceNear, splits[c + 1])) {
                    maps.slots[cascade] = add(fitCascade(light.direction, fit, sliceNear, splits[c + 1],
                                                         boxes, resolution, settings_.texelSnapping));
                }
            }
            maps.kind = glm::ivec4(kind(LightMapsKind::Cascades), count, 0, 0);
            break;
        }
        case engine::LightType::Spot:
            maps.slots.x = add(fitSpotLight(light.position, light.direction, light.light.outerConeAngle,
                                            light.light.range, boxes, resolution));
            maps.kind.x = kind(LightMapsKind::Single);
            break;
        case engine::LightType::Point:
            for (int face = 0; face < kCubeFaces; ++face) {
                const int slot =
                    add(fitPointLightFace(light.position, face, light.light.range, fitViewProjection, boxes,
                                          resolution, plan_.kernelReachTexels));
                if (face < 4) {
                    maps.slots[face] = slot;
                } else {
                    maps.faceSlots[face - 4] = slot;
                }
            }
            maps.kind.x = kind(LightMapsKind::Cube);
            break;
        }
    }
    if (slots_.empty()) {
        maps_.reset(); // nothing casts this frame: give the memory back
        return;
    }
    if (virtualFrame_) {
        maps_.reset(); // the levels read the pool's atlas
    } else if (!maps_ || maps_->layers() != static_cast<int>(slots_.size())) {
        // The arrays hold exactly the maps in use; a change in their number reallocates them.
        maps_ = std::make_unique<ShadowMapArray>(resolution, static_cast<int>(slots_.size()), plan_);
    }
    layoutKey_ = layoutKey(lights);
    uploadBlock(lights, fit);
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
    // Fitted here rather than in prepareFrame, so the pass timing includes the view's sample pass.
    fitMaps(frame);
    if (slots_.empty()) {
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
    if (virtualFrame_) {
        virtual_->render(*host_, frame.scene, program, plan_.momentsClear);
    }
    for (std::size_t layer = 0; maps_ && layer < slots_.size(); ++layer) {
        const engine::gl::Framebuffer& framebuffer = maps_->framebuffers[layer];
        const LightProjection& projection = slots_[layer].projection;
        framebuffer.bind();
        glViewport(0, 0, settings_.resolution, settings_.resolution);
        glClearDepth(1.0);
        if (maps_->gradient) {
            const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, zero);
        } else if (maps_->moments) {
            glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, glm::value_ptr(plan_.momentsClear));
        }
        glClear(GL_DEPTH_BUFFER_BIT);
        const glm::mat4 lightViewProjection = projection.projection * projection.view;
        program.set("uLightViewProjection", lightViewProjection);
        program.set("uDepthRange", projection.depthRange);
        // Culled to the map's own clip volume: casters outside it could not write a texel.
        host_->drawMeshes(frame.scene, lightViewProjection, [&](engine::EntityId, const glm::mat4& model) {
            program.set("uModel", model);
            return true;
        });
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    if (plan_.blursMoments && (maps_ || virtualFrame_)) {
        blurMoments();
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
    if (virtualFrame_) {
        virtual_->blurPages(blur, mapUnit_);
        glEnable(GL_DEPTH_TEST);
        return;
    }
    blur.set("uSourceOffset", glm::ivec2(0));
    for (int layer = 0; layer < maps_->layers(); ++layer) {
        // Horizontal into the temporary layer, then vertical back into the moments' layer, level 0.
        maps_->blurFramebuffer->bind();
        glBindTextureUnit(mapUnit_, maps_->moments->id());
        blur.set("uLayer", layer);
        blur.set("uDirection", glm::ivec2(1, 0));
        glDrawArrays(GL_TRIANGLES, 0, 3);
        maps_->framebuffers[static_cast<std::size_t>(layer)].bind();
        glBindTextureUnit(mapUnit_, maps_->blurTemporary->id());
        blur.set("uLayer", 0);
        blur.set("uDirection", glm::ivec2(0, 1));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
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
    const ShadowMapArray& maps = virtualFrame_ ? virtual_->atlas() : *maps_;
    glBindTextureUnit(mapUnit_, maps.sampledTexture());
    glBindSampler(mapUnit_, samplers_->forMap(plan_.sampler));
    if (maps.gradient) {
        glBindTextureUnit(gradientUnit_, maps.gradient->id());
        glBindSampler(gradientUnit_, samplers_->linear());
    }
    if (virtualFrame_) {
        glBindTextureUnit(pageTableUnit_, virtual_->pageTable());
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

void ShadowModule::uploadBlock(const std::vector<LightMapsBlock>& lights, const FitView& fit) {
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
        block.depthRange[slot] = glm::vec4(projection.depthRange, projection.litBorderTexels, 0.0f);
    }
    std::copy(lights.begin(), lights.end(), block.lights);
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
    if (virtualFrame_) {
        block.virtualPages = virtual_->pagesUniform();
        block.virtualPage = virtual_->pageUniform();
    }
    if (!shadowBlock_) {
        shadowBlock_ =
            std::make_unique<engine::gl::Buffer>(sizeof(ShadowBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    shadowBlock_->update(0, sizeof block, &block);
}

} // namespace shadows
