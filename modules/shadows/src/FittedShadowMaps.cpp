#include "FittedShadowMaps.h"

#include "VisibleSamples.h"

#include <engine/ForwardRenderer.h>

#include <algorithm>
#include <array>
#include <iostream>

namespace shadows {

FittedShadowMaps::FittedShadowMaps(engine::ModuleHost& host, const ShadowSettings& settings,
                                   const ShadowPlan& plan, VisibleSamples& samples, OnceWarnings& warnings)
    : host_(host), settings_(settings), plan_(plan), samples_(samples), warnings_(warnings) {}

FittedShadowMaps::~FittedShadowMaps() = default;

std::size_t FittedShadowMaps::bytes() const {
    return maps_ ? maps_->bytes(plan_) : 0;
}

float FittedShadowMaps::kernelReach(const engine::FrameLight& light) const {
    const SoftMargin soft = softMargin(light);
    return plan_.kernelReachTexels - plan_.softReachTexels + soft.texels;
}

SoftMargin FittedShadowMaps::softMargin(const engine::FrameLight& light) const {
    // A light of no size casts hard shadows whatever the technique: its maps need no soft margin.
    const float size = softLightSize(light.light, settings_.lightSizeScale);
    if (!(size > 0.0f)) {
        return {};
    }
    const bool follows =
        plan_.traits->softReachFollowsLight && light.light.type == engine::LightType::Directional;
    return {plan_.softReachTexels, follows ? size : 0.0f};
}

int FittedShadowMaps::budgetedSide(const engine::FrameContext& frame) {
    // The most maps, not this frame's: a face or cascade coming into view then leaves the side as it is.
    int layers = 0;
    for (const engine::FrameLight& light : frame.lights) {
        if (light.light.castsShadows) {
            layers += light.light.type == engine::LightType::Point ? kCubeFaces
                      : light.light.type == engine::LightType::Spot
                          ? 1
                          : (settings_.cascadeCount > 0 ? settings_.cascadeCount : kMaxCascades);
        }
    }
    layers = std::min(layers, kMaxMaps);
    const std::size_t budget = static_cast<std::size_t>(settings_.fittedBudgetMiB) << 20;
    const int side = budgetedResolution(plan_, settings_.resolution, layers, budget);
    if (side < settings_.resolution && !warnings_.mapBudget) {
        std::cerr << "shadows: fittedBudgetMiB " << settings_.fittedBudgetMiB << " is less than the "
                  << (plan_.mapBytes(settings_.resolution, layers) >> 20) << " MiB of " << layers
                  << " maps of " << settings_.resolution << "², the most these lights may take: drawn at "
                  << side << "² (" << (plan_.mapBytes(side, layers) >> 20) << " MiB)\n";
        warnings_.mapBudget = true;
    }
    return side;
}

bool FittedShadowMaps::fitToVisibleSamples(const AllocationFrame& frame, const engine::FrameLight& light,
                                           int resolution, bool sizeToView, std::vector<MapSlot>& slots,
                                           LightMapsBlock& maps) {
    auto bounds = samples_.measure(host_, frame.frame, frame.fit, lightView(light.direction),
                                   settings_.cascadeSplitWeight, settings_.cascadeBlend);
    if (!bounds) {
        if (!warnings_.noSamples) {
            std::cerr
                << "shadows: the view shows no surface to fit the directional maps to (an empty view, or "
                   "the camera inside geometry): fitted to mesh bounds instead\n";
            warnings_.noSamples = true;
        }
        return false;
    }
    // Only the samples a caster can shadow need texels.
    const Aabb shadowable =
        shadowableRegion(light.direction, frame.fit.projection * frame.fit.view, frame.boxes);
    std::array<LightRect, kSampleSlices> slices{};
    slices[0] = clippedTo(bounds->slices[0], shadowable);
    // The cascades' slices only where more than one map may be drawn.
    const int imageHeight = frame.frame.target.size.y;
    const bool oneMap =
        settings_.cascadeCount == 1 ||
        (settings_.cascadeCount == 0 &&
         oneMapResolvesView(slices, bounds->sliceDepths, resolution, frame.fit.projection, imageHeight));
    if (!oneMap) {
        samples_.measureCascadeSlices(host_, *bounds);
        for (std::size_t s = 1; s < slices.size(); ++s) {
            slices[s] = clippedTo(bounds->slices[s], shadowable);
        }
    }
    const int count = settings_.cascadeCount > 0 ? settings_.cascadeCount
                      : oneMap                   ? 1
                               : densityCascadeCount(slices, bounds->sliceDepths, resolution,
                                                     frame.fit.projection, imageHeight);
    const float hardMargin = plan_.kernelReachTexels - plan_.softReachTexels;
    const int side =
        sizeToView ? viewResolution(slices, bounds->sliceDepths, count, resolution, hardMargin,
                                    settings_.fittedTexelPixels / (1.0f + 2.0f * plan_.filterRadiusTexels),
                                    frame.fit.projection, imageHeight)
                   : resolution;
    // Where the maps may stay as a camera moves, the placements drawn last are kept while they hold its
    // samples.
    std::vector<LightProjection> kept;
    if (settings_.reuseUnchangedMaps && frame.fitIsCamera) {
        for (const MapSlot& slot : drawn_) {
            if (slot.lightIndex == light.index && slot.resolution == side) {
                kept.push_back(slot.projection);
            }
        }
    }
    const auto fitted = [&](int cascade) {
        const auto slice = static_cast<std::size_t>(sampleSliceIndex(count, cascade));
        LightProjection projection =
            fitToSamples(light.direction, slices[slice], frame.boxes, side, hardMargin,
                         settings_.texelSnapping, softMargin(light), &bounds->slices[slice], kept);
        if (!frame.fitIsCamera) { // the pixels shaded are not the fit's samples
            projection.drawnRegion = LightProjection{}.drawnRegion;
        }
        return projection;
    };
    if (count == 1) {
        maps.slots.x = addSlot(slots, light.index, fitted(0), side);
        maps.kind.x = drawnKind(maps, LightMapsKind::Single);
        return true;
    }
    for (int cascade = 0; cascade < count; ++cascade) {
        const auto slice = static_cast<std::size_t>(sampleSliceIndex(count, cascade));
        // The split itself, not the slice, which starts earlier by the previous cascade's blend band.
        maps.splitNear[cascade] = cascade == 0 ? bounds->viewDepth.x : bounds->sliceDepths[slice - 1].y;
        maps.splitFar[cascade] = bounds->sliceDepths[slice].y;
        if (!slices[slice].empty()) {
            maps.slots[cascade] = addSlot(slots, light.index, fitted(cascade), side);
        }
    }
    maps.kind = glm::ivec4(drawnKind(maps, LightMapsKind::Cascades), count, 0, 0);
    return true;
}

void FittedShadowMaps::fitToBounds(const AllocationFrame& frame, const engine::FrameLight& light,
                                   int resolution, std::optional<glm::vec2> visibleRange,
                                   std::vector<MapSlot>& slots, LightMapsBlock& maps) const {
    const int count = settings_.cascadeCount > 0
                          ? settings_.cascadeCount
                          : automaticCascadeCount(visibleRange.value_or(glm::vec2(1.0f)));
    if (count == 1 || !visibleRange) {
        maps.slots.x = addSlot(slots, light.index,
                               fitDirectionalLight(light.direction, frame.fit.projection * frame.fit.view,
                                                   frame.boxes, resolution, settings_.texelSnapping),
                               resolution);
        maps.kind.x = drawnKind(maps, LightMapsKind::Single);
        return;
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
        if (hasReceiversBetween(frame.fit, frame.boxes, sliceNear, splits[c + 1])) {
            maps.slots[cascade] = addSlot(slots, light.index,
                                          fitCascade(light.direction, frame.fit, sliceNear, splits[c + 1],
                                                     frame.boxes, resolution, settings_.texelSnapping),
                                          resolution);
        }
    }
    maps.kind = glm::ivec4(drawnKind(maps, LightMapsKind::Cascades), count, 0, 0);
}

void FittedShadowMaps::allocate(const AllocationFrame& frame, std::vector<MapSlot>& slots,
                                std::vector<LightMapsBlock>& lights) {
    const std::vector<LightMapsBlock> unfitted = lights;
    for (;;) {
        fit(frame, slots, lights);
        try {
            allocateMaps(slots);
            return;
        } catch (const MapAllocationError& error) {
            const int side = largestSide(slots);
            if (side <= kSmallestMapSide) {
                throw;
            }
            // Every side is tried once: the next fits are capped below the one the driver refused.
            allocatableSide_ = side / 2;
            std::cerr << "shadows: " << error.what() << ": drawn at " << allocatableSide_
                      << "² while these settings hold; lower resolution or fittedBudgetMiB to what this "
                         "driver holds\n";
            // The refused allocation's GL_OUT_OF_MEMORY is answered here; where GL holds any other error
            // flag (one per kind at most), the engine reports them all, this one among them.
            bool outOfMemoryOnly = true;
            for (int flags = 0; flags < 8; ++flags) {
                const GLenum flag = glGetError();
                if (flag == GL_NO_ERROR) {
                    break;
                }
                outOfMemoryOnly = outOfMemoryOnly && flag == GL_OUT_OF_MEMORY;
            }
            if (outOfMemoryOnly) {
                host_.takeGlErrors();
            }
            maps_.reset();
            drawn_.clear();
            slots.clear();
            lights = unfitted;
        }
    }
}

void FittedShadowMaps::fit(const AllocationFrame& frame, std::vector<MapSlot>& slots,
                           std::vector<LightMapsBlock>& lights) {
    // The maps share one array, so one light's view may size them: a frame whose only shadowed light is
    // directional. Spot and point maps, and a second sun's, keep `resolution`; so do the soft techniques,
    // whose margin of 64 texels and more would take a quarter of a 512² map.
    const auto casters =
        std::count_if(frame.frame.lights.begin(), frame.frame.lights.end(),
                      [](const engine::FrameLight& light) { return light.light.castsShadows; });
    const bool sizeToView =
        settings_.fittedTexelPixels > 0.0f && plan_.softReachTexels == 0.0f && casters == 1 &&
        std::any_of(frame.frame.lights.begin(), frame.frame.lights.end(), [](const auto& light) {
            return light.light.castsShadows && light.light.type == engine::LightType::Directional;
        });
    const int resolution = std::min(budgetedSide(frame.frame), allocatableSide_);
    // Where the receivers in view lie in depth: the cascades' range, and their automatic count.
    const std::optional<glm::vec2> visibleRange = visibleDepthRange(frame.fit, frame.boxes);
    for (const engine::FrameLight& light : frame.frame.lights) {
        LightMapsBlock& maps = lights[static_cast<std::size_t>(light.index)];
        if (!light.light.castsShadows) {
            continue;
        }
        switch (light.light.type) {
        case engine::LightType::Directional:
            if (settings_.directionalFit != DirectionalFit::Samples ||
                !fitToVisibleSamples(frame, light, resolution, sizeToView, slots, maps)) {
                fitToBounds(frame, light, resolution, visibleRange, slots, maps);
            }
            break;
        case engine::LightType::Spot:
            maps.slots.x = addSlot(slots, light.index,
                                   fitSpotLight(light.position, light.direction, light.light.outerConeAngle,
                                                light.light.range, frame.boxes, resolution),
                                   resolution);
            maps.kind.x = drawnKind(maps, LightMapsKind::Single);
            break;
        case engine::LightType::Point:
            for (int face = 0; face < kCubeFaces; ++face) {
                const int slot = addSlot(slots, light.index,
                                         fitPointLightFace(light.position, face, light.light.range,
                                                           frame.fit.projection * frame.fit.view, frame.boxes,
                                                           resolution, kernelReach(light)),
                                         resolution);
                setFaceSlot(maps, face, slot);
            }
            maps.kind.x = drawnKind(maps, LightMapsKind::Cube);
            break;
        }
    }
}

int FittedShadowMaps::largestSide(std::span<const MapSlot> slots) {
    int side = 0;
    for (const MapSlot& slot : slots) {
        side = std::max(side, slot.resolution);
    }
    return side;
}

void FittedShadowMaps::allocateMaps(std::span<const MapSlot> slots) {
    if (slots.empty()) {
        maps_.reset(); // nothing casts this frame: give the memory back
        drawn_.clear();
        return;
    }
    // The arrays hold exactly the maps in use, at the side the frame's fits took; a change in either
    // reallocates them.
    const int side = largestSide(slots);
    if (!maps_ || maps_->layers() != static_cast<int>(slots.size()) || maps_->depth.size().x != side) {
        maps_.reset(); // the old maps' memory is free before the new ones ask for theirs
        drawn_.clear();
        maps_ = std::make_unique<ShadowMapArray>(side, static_cast<int>(slots.size()), plan_);
    }
}

namespace {

bool regionWithin(const glm::vec4& region, const glm::vec4& outer) {
    return glm::all(glm::greaterThanEqual(glm::vec2(region), glm::vec2(outer))) &&
           glm::all(glm::lessThanEqual(glm::vec2(region.z, region.w), glm::vec2(outer.z, outer.w)));
}

/// Of a map side, the margin drawn beyond the region a moving view reads (FittedShadowMaps::render).
constexpr float kMovingViewMargin = 1.0f / 16.0f;

} // namespace

engine::DrawnMeshes FittedShadowMaps::render(const engine::Scene& scene, const engine::gl::Program& program,
                                             std::span<const MapSlot> slots,
                                             const CasterOmissions& omissions) {
    engine::DrawnMeshes drawnMeshes;
    std::vector<MapSlot> drawing(slots.begin(), slots.end());
    for (std::size_t layer = 0; maps_ && layer < slots.size(); ++layer) {
        const engine::gl::Framebuffer& framebuffer = maps_->framebuffers[layer];
        LightProjection& projection = drawing[layer].projection;
        // A map drawn again where it lay, because the region the view reads grew past what was drawn: the
        // view moves across it, so a margin beyond that region is drawn too, which the next frames' regions
        // then fall within (holds).
        if (layer < drawn_.size() && projection.square.z > 0.0f &&
            drawn_[layer].projection.square == projection.square &&
            !regionWithin(projection.drawnRegion, drawn_[layer].projection.drawnRegion)) {
            const glm::vec4& now = projection.drawnRegion;
            const glm::vec4& before = drawn_[layer].projection.drawnRegion;
            const glm::vec4 grown(glm::min(glm::vec2(now), glm::vec2(before)) - kMovingViewMargin,
                                  glm::max(glm::vec2(now.z, now.w), glm::vec2(before.z, before.w)) +
                                      kMovingViewMargin);
            projection.drawnRegion = glm::clamp(grown, 0.0f, 1.0f);
        }
        framebuffer.bind();
        const glm::ivec2 size = maps_->depth.size();
        glViewport(0, 0, size.x, size.y);
        clearMapTargets(*maps_, framebuffer.id(), plan_);
        const glm::ivec4 drawn = drawnTexels(projection, size.x);
        const bool whole = drawn == glm::ivec4(0, 0, size);
        if (!whole) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(drawn.x, drawn.y, drawn.z, drawn.w);
        }
        accumulate(drawnMeshes, drawCasters(host_, scene, program, projection, omissions));
        if (!whole) {
            glDisable(GL_SCISSOR_TEST);
        }
    }
    drawn_ = std::move(drawing);
    return drawnMeshes;
}

bool FittedShadowMaps::holds(std::span<const MapSlot> slots) const {
    if (!maps_ || slots.empty() || drawn_.size() != slots.size()) {
        return false;
    }
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const LightProjection& now = slots[i].projection;
        const LightProjection& drawn = drawn_[i].projection;
        if (slots[i].lightIndex != drawn_[i].lightIndex || slots[i].resolution != drawn_[i].resolution ||
            now.worldToShadow != drawn.worldToShadow || now.depthRange != drawn.depthRange ||
            !regionWithin(now.drawnRegion, drawn.drawnRegion)) {
            return false;
        }
    }
    return true;
}

void FittedShadowMaps::blurMoments(const engine::gl::Program& blur, GLuint unit) {
    if (!maps_ || !maps_->blurFramebuffer) {
        return;
    }
    blur.set("uSourceOffset", glm::ivec2(0));
    for (int layer = 0; layer < maps_->layers(); ++layer) {
        // Horizontal into the temporary layer, then vertical back into the moments' layer, level 0.
        maps_->blurFramebuffer->bind();
        glBindTextureUnit(unit, maps_->moments->id());
        blur.set("uLayer", layer);
        blur.set("uDirection", glm::ivec2(1, 0));
        glDrawArrays(GL_TRIANGLES, 0, 3);
        maps_->framebuffers[static_cast<std::size_t>(layer)].bind();
        glBindTextureUnit(unit, maps_->blurTemporary->id());
        blur.set("uLayer", 0);
        blur.set("uDirection", glm::ivec2(0, 1));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

} // namespace shadows
