#include "VirtualShadowMaps.h"

#include "VisibleSamples.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iostream>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace shadows {

namespace {

/// The light-space x, y rectangle (min x, min y, max x, max y) of a world box.
glm::vec4 lightRect(const glm::mat4& lightView, const Aabb& box) {
    const Aabb light = box.transformed(lightView);
    return {light.min.x, light.min.y, light.max.x, light.max.y};
}

/// The shadow texture rectangle (min x, min y, max x, max y) of a world box in a perspective map; nullopt
/// when the box straddles the light's plane (its image is unbounded), an empty one when it lies behind it.
std::optional<glm::vec4> shadowRect(const glm::mat4& worldToShadow, const Aabb& box) {
    glm::vec4 rect(std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                   std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest());
    int behind = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                              (corner & 4) ? box.max.z : box.min.z);
        const glm::vec4 clip = worldToShadow * glm::vec4(point, 1.0f);
        if (!(clip.w > 0.0f)) {
            ++behind;
            continue;
        }
        const glm::vec2 coord = glm::vec2(clip) / clip.w;
        rect = {std::min(rect.x, coord.x), std::min(rect.y, coord.y), std::max(rect.z, coord.x),
                std::max(rect.w, coord.y)};
    }
    if (behind == 8) {
        return glm::vec4(2.0f, 2.0f, -2.0f, -2.0f); // wholly behind the light: overlaps no page
    }
    return behind > 0 ? std::nullopt : std::optional<glm::vec4>(rect);
}

} // namespace

VirtualShadowMaps::VirtualShadowMaps(engine::ModuleHost& host, const ShadowSettings& settings,
                                     const ShadowPlan& plan, VisibleSamples& samples, PageMarkPrograms& marks,
                                     OnceWarnings& warnings)
    : host_(host), samples_(samples), marks_(marks), warnings_(warnings),
      budgetMiB_(settings.virtualBudgetMiB), plan_(plan), pageSize_(settings.virtualPageSize),
      border_(virtualPageBorderTexels(plan)),
      tile_(settings.virtualPageSize + 2 * virtualPageBorderTexels(plan)),
      texelPixels_(settings.virtualTexelPixels),
      budget_(static_cast<std::size_t>(settings.virtualBudgetMiB) << 20), pool_(0) {
    if (budget_ < virtualOverheadBytes(pageSize_, 0) + virtualTileBytes(plan, pageSize_)) {
        throw std::invalid_argument("shadow settings: virtualBudgetMiB " +
                                    std::to_string(settings.virtualBudgetMiB) + " holds no page of " +
                                    std::to_string(tile_) + "² texels beside the page requests");
    }
}

VirtualShadowMaps::~VirtualShadowMaps() = default;

std::size_t VirtualShadowMaps::blurTileBytes() const {
    return plan_.blursMoments
               ? static_cast<std::size_t>(tile_) * static_cast<std::size_t>(tile_) * plan_.momentBytesPerTexel
               : 0;
}

VirtualShadowMaps::PoolLayout VirtualShadowMaps::poolLayout(int tableLayers) const {
    const std::size_t overhead = virtualOverheadBytes(pageSize_, tableLayers) + blurTileBytes();
    const std::size_t tileBytes = virtualTileBytes(plan_, pageSize_);
    // At least one page, beyond the budget if it must be (allocatePool warns).
    const std::size_t affordable =
        std::max<std::size_t>(budget_ > overhead ? (budget_ - overhead) / tileBytes : 0, 1);
    GLint maxSize = 0;
    GLint maxLayers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    // Layers of a fixed size for the budget (as few tiles as keep the layers to a few hundred: 4 in 64 MiB):
    // the pool grows a layer at a time, and a tile lies at the same atlas texel whatever the pool's
    // size, so a grown pool reads exactly what a new one would.
    const auto perRow = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(affordable) / 256.0))));
    PoolLayout layout;
    layout.tilesPerRow = std::clamp(static_cast<int>(perRow), 1, std::max(maxSize / tile_, 1));
    layout.tilesPerLayer =
        static_cast<std::size_t>(layout.tilesPerRow) * static_cast<std::size_t>(layout.tilesPerRow);
    layout.layers = std::min(std::max<std::size_t>(affordable / layout.tilesPerLayer, 1),
                             static_cast<std::size_t>(std::max(maxLayers, 1)));
    layout.fitsBudget = budget_ > overhead && (budget_ - overhead) / tileBytes >= 1;
    return layout;
}

void VirtualShadowMaps::allocatePool(int tableLayers, std::size_t wanted) {
    const PoolLayout layout = poolLayout(tableLayers);
    if (!layout.fitsBudget) {
        std::cerr << "shadows: virtualBudgetMiB " << (budget_ >> 20)
                  << " holds no page beside the page tables of this frame's lights (" << tableLayers
                  << " layers, " << virtualOverheadBytes(pageSize_, tableLayers) + blurTileBytes()
                  << " bytes with the requests): one page is used, beyond the budget\n";
    }
    const int tilesPerRow = layout.tilesPerRow;
    const std::size_t perLayer = layout.tilesPerLayer;
    const std::size_t layers = std::clamp<std::size_t>((wanted + perLayer - 1) / perLayer, 1, layout.layers);
    ShadowPlan atlasPlan = plan_;
    atlasPlan.blursMoments = false; // blurred a tile at a time (blurMoments), not a whole layer
    std::unique_ptr<ShadowMapArray> atlas;
    try {
        atlas = std::make_unique<ShadowMapArray>(tilesPerRow * tile_, static_cast<int>(layers), atlasPlan);
    } catch (const MapAllocationError& error) {
        throw MapAllocationError(std::string(error.what()) +
                                 "; lower virtualBudgetMiB to what this driver holds");
    }
    const int total = static_cast<int>(perLayer * layers);
    if (atlas_ && poolTableLayers_ == tableLayers) {
        // Grown: the resident pages keep their tiles, copied to where those tiles lie in the new atlas.
        const auto place = [&](int tile, int perSide) {
            const int layerTiles = perSide * perSide;
            return glm::ivec3(glm::ivec2(tile % perSide, (tile % layerTiles) / perSide) * tile_,
                              tile / layerTiles);
        };
        pool_.forEachResident([&](const PageKey&, int tile) {
            const glm::ivec3 from = place(tile, tilesPerRow_);
            const glm::ivec3 to = place(tile, tilesPerRow);
            const auto copy = [&](GLuint source, GLuint target) {
                glCopyImageSubData(source, GL_TEXTURE_2D_ARRAY, 0, from.x, from.y, from.z, target,
                                   GL_TEXTURE_2D_ARRAY, 0, to.x, to.y, to.z, tile_, tile_, 1);
            };
            copy(atlas_->depth.id(), atlas->depth.id());
            if (atlas_->gradient) {
                copy(atlas_->gradient->id(), atlas->gradient->id());
            }
            if (atlas_->moments) {
                copy(atlas_->moments->id(), atlas->moments->id());
            }
        });
        pool_.grow(total);
    } else {
        pool_ = PagePool(total);
    }
    atlas_ = std::move(atlas);
    tilesPerRow_ = tilesPerRow;
    layers_ = static_cast<int>(layers);
    if (plan_.blursMoments && !blurTile_) {
        blurTile_.emplace(plan_.momentsFormat, glm::ivec2(tile_), 1);
        blurTileFramebuffer_.emplace("virtual page moments blur");
        blurTileFramebuffer_->attach(GL_COLOR_ATTACHMENT0, *blurTile_, 0);
        blurTileFramebuffer_->setDrawBuffers({GL_COLOR_ATTACHMENT0});
        blurTileFramebuffer_->check();
    }
    if (poolTableLayers_ != tableLayers) {
        poolTableLayers_ = tableLayers;
        pageTable_.reset();
    }
    uploaded_.clear();
}

std::size_t VirtualShadowMaps::bytes() const {
    std::size_t total = (atlas_ ? atlas_->bytes(plan_) : 0) + (blurTile_ ? blurTileBytes() : 0);
    if (pageTable_) {
        total += virtualOverheadBytes(pageSize_, pageTable_->layers());
    } else if (requests_) {
        total += requests_->size();
    }
    return total;
}

void VirtualShadowMaps::describe(ShadowBlock& block) const {
    block.virtualPages = glm::ivec4(kVirtualResolution / pageSize_, tilesPerRow_, tilesPerRow_ * tile_, 0);
    block.virtualPage =
        glm::vec4(static_cast<float>(pageSize_), static_cast<float>(tile_), static_cast<float>(border_),
                  1.0f / static_cast<float>(tilesPerRow_ * tile_));
}

VirtualShadowMaps::Light VirtualShadowMaps::fitLight(const engine::FrameLight& light, const FitView& fit,
                                                     std::span<const Aabb> boxes) {
    Light entry;
    entry.index = light.index;
    const glm::vec3 camera(glm::inverse(fit.view)[3]);
    LightState& state = lightStates_[light.index];
    if (light.light.type == engine::LightType::Directional) {
        ClipmapGeometry& geometry = entry.geometry;
        geometry.lightView = lightView(light.direction);
        geometry.pageSize = pageSize_;
        geometry.camera = glm::vec2(geometry.lightView * glm::vec4(camera, 1.0f));
        geometry.depth = depthRangeFor(geometry.lightView, boxes);
        // A turned light or a new depth range changes every texel of the light's pages.
        if (state.faceCount != 0 || state.direction != light.direction || state.depth != geometry.depth) {
            stats_.invalidated += pool_.invalidateLight(light.index);
            state = {};
            state.faceCount = 0;
            state.direction = light.direction;
            state.depth = geometry.depth;
        }
        return entry;
    }
    entry.faceCount = Light::facesOf(light.light.type);
    if (state.faceCount != entry.faceCount) {
        stats_.invalidated += pool_.invalidateLight(light.index);
        state = {};
        state.faceCount = entry.faceCount;
    }
    const auto faceProjection = [&](int face) {
        LightProjection fitted;
        if (entry.faceCount == 1) {
            fitted = fitSpotLight(light.position, light.direction, light.light.outerConeAngle,
                                  light.light.range, boxes, kVirtualResolution);
        } else {
            // Wide enough that the coarsest level's kernel, reaching the border in its own texels past the
            // face's edge, still reads this face (cubeFaceFieldOfView).
            const float margin = static_cast<float>(border_) *
                                 std::ldexp(1.0f, PerspectiveGeometry{{}, pageSize_}.levels() - 1);
            fitted = fitPointLightFace(light.position, face, light.light.range, fit.projection * fit.view,
                                       boxes, kVirtualResolution, margin);
        }
        if (!fitted.valid) {
            return fitted;
        }
        const float fov = 2.0f * std::atan(0.5f * fitted.texelScale * static_cast<float>(kVirtualResolution));
        return virtualPerspective(fitted.view, fov, fitted.depthRange);
    };
    for (int face = 0; face < entry.faceCount; ++face) {
        PerspectiveGeometry& geometry = entry.faces[static_cast<std::size_t>(face)];
        geometry.pageSize = pageSize_;
        geometry.face = faceProjection(face);
        if (!geometry.face.valid) {
            continue;
        }
        // A moved light, a turned spot or a new depth range changes every texel of the face's pages.
        std::optional<PerspectiveGeometry>& known = state.faces[static_cast<std::size_t>(face)];
        if (known && known->face.worldToShadow != geometry.face.worldToShadow) {
            stats_.invalidated +=
                pool_.invalidateWhere(light.index, [&](const PageKey& key) { return key.face == face; });
        }
        known = geometry;
    }
    return entry;
}

PageRequests VirtualShadowMaps::markPages(Light& light, const FitView& fit, int levelBase, glm::ivec2 size) {
    const engine::gl::Program& mark = marks_.forFaces(light.faceCount);
    const int side = kVirtualResolution / pageSize_;
    const glm::mat4 cameraWorld = glm::inverse(fit.view);
    const glm::vec3 camera(cameraWorld[3]);
    ClipmapGeometry& geometry = light.geometry;
    const std::uint32_t zero = 0;
    glClearNamedBufferData(requests_->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    mark.use();
    mark.set("uDepth", 0);
    mark.set("uSize", size);
    mark.set("uClipToWorld", glm::inverse(fit.projection * fit.view));
    glUniform3fv(mark.uniformLocation("uCamera"), 1, glm::value_ptr(camera));
    mark.set("uPageSize", pageSize_);
    mark.set("uPagesPerSide", side);
    glUniform1f(mark.uniformLocation("uReach"), static_cast<float>(border_));
    glUniform1f(mark.uniformLocation("uTexelPixels"), texelPixels_);
    if (light.faceCount == 0) {
        std::array<glm::ivec2, kRequestLevels> origins{};
        for (int level = 0; level < kRequestLevels; ++level) {
            origins[static_cast<std::size_t>(level)] = geometry.windowOrigin(levelBase + level);
        }
        mark.set("uWorldToLight", geometry.lightView);
        const glm::vec3 toLight =
            -glm::normalize(glm::vec3(glm::inverse(geometry.lightView) * glm::vec4(0, 0, -1, 0)));
        glUniform3fv(mark.uniformLocation("uToLight"), 1, glm::value_ptr(toLight));
        mark.set("uLevelBase", levelBase);
        glUniform2iv(mark.uniformLocation("uWindowOrigin"), kRequestLevels, glm::value_ptr(origins[0]));
    } else {
        std::array<glm::mat4, kCubeFaces> faces{};
        int mask = 0;
        float texelScale = 0.0f; // every face of a light has the same field of view
        for (int face = 0; face < light.faceCount; ++face) {
            const LightProjection& projection = light.faces[static_cast<std::size_t>(face)].face;
            if (projection.valid) {
                faces[static_cast<std::size_t>(face)] = projection.worldToShadow;
                mask |= 1 << face;
                texelScale = projection.texelScale;
            }
        }
        mark.set("uFaces", light.faceCount);
        glUniformMatrix4fv(mark.uniformLocation("uFaceToShadow"), kCubeFaces, GL_FALSE,
                           glm::value_ptr(faces[0]));
        mark.set("uFaceMask", mask);
        mark.set("uFaceLevels", light.levels());
        glUniform3fv(mark.uniformLocation("uLightPosition"), 1, glm::value_ptr(light.position));
        glUniform3fv(mark.uniformLocation("uSpotDirection"), 1, glm::value_ptr(light.direction));
        glUniform1f(mark.uniformLocation("uConeCosine"), light.coneCosine);
        glUniform1f(mark.uniformLocation("uRange"), light.range);
        glUniform1f(mark.uniformLocation("uTexelScale"), texelScale);
    }
    glBindTextureUnit(0, samplesDepth_);
    // The gathers read the texture's own nearest filtering, not a comparison sampler left on the unit.
    glBindSampler(0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, requests_->id());
    // 8x8 invocations a group, each marking a 4x4 block of pixels (pages.comp).
    const glm::ivec2 groups = (size + glm::ivec2(31)) / 32;
    glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

    const auto levelBits = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    std::vector<std::uint32_t> words(requests_->size() / 4);
    glGetNamedBufferSubData(requests_->id(), 0, static_cast<GLsizeiptr>(requests_->size()), words.data());
    PageRequests pages;
    int finest = levelBase + kRequestLevels;
    int coarsest = levelBase - 1;
    std::vector<PageKey> keys;
    for (std::size_t word = 0; word < words.size(); ++word) {
        for (std::uint32_t bits = words[word]; bits != 0u; bits &= bits - 1u) {
            const std::size_t bit = word * 32 + static_cast<std::size_t>(std::countr_zero(bits));
            const int index = static_cast<int>(bit / levelBits);
            const auto local = static_cast<int>(bit % levelBits);
            const glm::ivec2 page(local % side, local / side);
            if (light.faceCount > 0) {
                pages.insert({index % light.levels(), index / light.levels(), page.y, page.x});
                continue;
            }
            const int level = levelBase + index;
            keys.push_back({light.index, level, geometry.windowOrigin(level) + page});
            finest = std::min(finest, level);
            coarsest = std::max(coarsest, level);
        }
    }
    if (light.faceCount > 0) {
        return pages;
    }
    if (keys.empty()) {
        geometry.finestLevel = levelBase;
        return pages;
    }
    // The clipmap spans kClipmapLevels levels up to the coarsest asked for; finer requests read the finest
    // level's page over them.
    geometry.finestLevel = std::max(finest, coarsest - kClipmapLevels + 1);
    for (const PageKey& key : keys) {
        const int shift = std::max(geometry.finestLevel - key.level, 0);
        pages.insert({key.level + shift, 0, key.page.y >> shift, key.page.x >> shift});
    }
    return pages;
}

void VirtualShadowMaps::invalidateMovedCasters(const std::vector<Light>& lights,
                                               const std::map<engine::EntityId, Aabb>& casters) {
    // Every entity whose box appeared, vanished or changed: its old and new footprints hold stale texels.
    std::vector<Aabb> moved;
    for (const auto& [entity, box] : casters) {
        const auto before = casters_.find(entity);
        if (before == casters_.end()) {
            moved.push_back(box);
        } else if (before->second.min != box.min || before->second.max != box.max) {
            Aabb both = before->second;
            both.extend(box);
            // A clipmap's light-space rectangle of the union holds both; a face's projection of it too.
            moved.push_back(both);
        }
    }
    for (const auto& [entity, box] : casters_) {
        if (!casters.contains(entity)) {
            moved.push_back(box);
        }
    }
    for (const Light& light : lights) {
        for (const Aabb& box : moved) {
            if (light.faceCount == 0) {
                stats_.invalidated += pool_.invalidate(light.index, light.geometry,
                                                       lightRect(light.geometry.lightView, box), border_);
                continue;
            }
            // Faces with no visible receiver this frame keep their pages: those under the box go too.
            const LightState& state = lightStates_.at(light.index);
            for (int face = 0; face < light.faceCount; ++face) {
                const std::optional<PerspectiveGeometry>& geometry =
                    state.faces[static_cast<std::size_t>(face)];
                if (!geometry) {
                    continue;
                }
                const std::optional<glm::vec4> rect = shadowRect(geometry->face.worldToShadow, box);
                stats_.invalidated += pool_.invalidateWhere(light.index, [&](const PageKey& key) {
                    if (key.face != face) {
                        return false;
                    }
                    if (!rect) {
                        return true; // the box reaches behind the light: its image is unbounded
                    }
                    const glm::vec4 page = geometry->pageRect(key.level, key.page, border_);
                    return page.x <= rect->z && rect->x <= page.z && page.y <= rect->w && rect->y <= page.w;
                });
            }
        }
    }
    casters_ = casters;
}

std::vector<VirtualShadowMaps::Light>
VirtualShadowMaps::update(const FitView& fit, std::span<const engine::FrameLight> lights,
                          const std::map<engine::EntityId, Aabb>& casters, std::span<const Aabb> boxes,
                          GLuint depth, glm::ivec2 size) {
    stats_ = {};
    toRender_.clear();
    lights_.clear();
    samplesDepth_ = depth;
    const int side = kVirtualResolution / pageSize_;
    const auto levelWords = static_cast<std::size_t>(side) * static_cast<std::size_t>(side) / 32;
    if (!requests_) {
        requests_.emplace(levelWords * kRequestLevels * 4, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    Aabb scene;
    for (const Aabb& box : boxes) {
        scene.extend(box);
    }
    const glm::vec3 extent = scene.empty() ? glm::vec3(1.0f) : scene.max - scene.min;
    const int levelBase = requestLevelBase(std::max({extent.x, extent.y, extent.z}));

    int layer = 0;
    for (const engine::FrameLight& light : lights) {
        if (layer + Light::pageTableLayers(Light::facesOf(light.light.type)) > kPageTableLayers) {
            continue; // no slots to read it by either (ShadowModule warns)
        }
        Light entry = fitLight(light, fit, boxes);
        entry.pageLayer = layer;
        entry.position = light.position;
        entry.direction = light.direction;
        entry.coneCosine =
            light.light.type == engine::LightType::Spot ? std::cos(light.light.outerConeAngle) : -2.0f;
        entry.range = light.light.range;
        layer += entry.layers();
        lights_.push_back(entry);
    }
    if (atlas_ && poolTableLayers_ != layer) {
        atlas_.reset(); // new lights' tables take their share of the budget: the cached pages go
    }
    invalidateMovedCasters(lights_, casters);

    std::vector<PageRequests> requested;
    for (Light& light : lights_) {
        requested.push_back(markPages(light, fit, levelBase, size));
        stats_.requested += static_cast<int>(requested.back().size());
    }
    glUseProgram(0);
    // A tenth of the pool stays free of this frame's pages: a walking camera's requests flicker at the
    // levels' edges, and a page that flickers out is then still resident when it flickers back. The pool
    // grows, by doubling, to hold what one frame asks for beside that tenth, up to the budget.
    const auto usable = [](std::size_t tiles) { return tiles - tiles / 10; };
    const auto asked = static_cast<std::size_t>(std::max(stats_.requested, 1));
    const auto tiles = static_cast<std::size_t>(pool_.tiles());
    if (!atlas_ || (asked > usable(tiles) && tiles < poolLayout(layer).tiles())) {
        allocatePool(layer, std::bit_ceil(asked + asked / 9));
    }
    std::vector<CoarseningLight> coarsening;
    for (const Light& light : lights_) {
        CoarseningLight& hints = coarsening.emplace_back();
        const bool clipmap = light.faceCount == 0;
        hints.light = light.index;
        hints.coarsestLevel = clipmap ? light.geometry.finestLevel + kClipmapLevels - 1 : light.levels() - 1;
        if (clipmap) {
            hints.centre = glm::dvec2(light.geometry.camera) / static_cast<double>(pageSize_);
        }
        hints.pool = &pool_;
    }
    stats_.coarsened = coarsenToFit(requested, coarsening, usable(static_cast<std::size_t>(pool_.tiles())));
    std::vector<PageKey> requests;
    for (std::size_t light = 0; light < lights_.size(); ++light) {
        // Coarse to fine, so that if the pool still runs out, the coarse pages stay.
        for (auto it = requested[light].rbegin(); it != requested[light].rend(); ++it) {
            const auto& [level, face, y, x] = *it;
            requests.push_back({lights_[light].index, level, {x, y}, face});
        }
    }
    PagePool::FrameResult served = pool_.request(requests, ++frame_);
    stats_.cached = served.cached;
    stats_.refused = served.refused;
    stats_.rendered = static_cast<int>(served.render.size());
    stats_.resident = pool_.resident();
    stats_.poolPages = pool_.tiles();
    stats_.texelsRendered =
        served.render.size() * static_cast<std::size_t>(tile_) * static_cast<std::size_t>(tile_);
    toRender_ = std::move(served.render);
    uploadPageTables();
    return lights_;
}

void VirtualShadowMaps::allocate(const AllocationFrame& frame, std::vector<MapSlot>& slots,
                                 std::vector<LightMapsBlock>& lights) {
    std::vector<engine::FrameLight> casting;
    for (const engine::FrameLight& light : frame.frame.lights) {
        if (light.light.castsShadows) {
            casting.push_back(light);
        }
    }
    served_ = !casting.empty();
    if (!served_) {
        return;
    }
    std::map<engine::EntityId, Aabb> casters; // each entity's world box: pages redraw where one moved
    for (std::size_t mesh = 0; mesh < frame.boxes.size(); ++mesh) {
        casters[frame.entities[mesh]].extend(frame.boxes[mesh]);
    }
    samples_.draw(host_, frame.frame, frame.fit);
    const std::vector<Light> served =
        update(frame.fit, casting, casters, frame.boxes, samples_.depthTexture(), samples_.size());
    static_assert(kPageTableLayers == kMaxMaps, "a page-table layer per map slot");
    for (const engine::FrameLight& light : casting) {
        if (std::none_of(served.begin(), served.end(),
                         [&](const Light& entry) { return entry.index == light.index; })) {
            std::cerr << "shadows: light " << light.index << " casts no shadow this frame: its virtual maps' "
                      << "page tables do not fit the " << kPageTableLayers << " layers beside the others\n";
        }
    }
    for (const Light& light : served) {
        LightMapsBlock& maps = lights[static_cast<std::size_t>(light.index)];
        int needed = light.faceCount == 0 ? kClipmapLevels : 0;
        for (int face = 0; face < light.faceCount; ++face) {
            needed += light.faces[static_cast<std::size_t>(face)].face.valid ? 1 : 0;
        }
        if (slots.size() + static_cast<std::size_t>(needed) > static_cast<std::size_t>(kMaxMaps)) {
            std::cerr << "shadows: light " << light.index << " casts no shadow this frame: its " << needed
                      << " virtual maps do not fit the " << kMaxMaps << " map slots beside the others\n";
            continue;
        }
        if (light.faceCount == 0) {
            const int first = static_cast<int>(slots.size());
            for (int level = 0; level < kClipmapLevels; ++level) {
                slots.push_back({light.index,
                                 light.geometry.levelProjection(light.geometry.finestLevel + level),
                                 kVirtualResolution});
            }
            maps.kind =
                glm::ivec4(static_cast<int>(LightMapsKind::Virtual), kClipmapLevels, first, light.pageLayer);
            continue;
        }
        // A spot map or cube faces in the fitted layout's slots; the levels are the mip levels of each.
        for (int face = 0; face < light.faceCount; ++face) {
            const int slot = addSlot(slots, light.index, light.faces[static_cast<std::size_t>(face)].face,
                                     kVirtualResolution);
            setFaceSlot(maps, face, slot);
        }
        maps.kind = glm::ivec4(drawnKind(maps, LightMapsKind::VirtualFaces), light.levels(), light.faceCount,
                               light.pageLayer);
    }
    if ((stats_.coarsened > 0 || stats_.refused > 0) && !warnings_.pageBudget) {
        std::cerr << "shadows: the page budget (virtualBudgetMiB " << budgetMiB_ << ", " << stats_.poolPages
                  << " pages) holds fewer pages than the view asks for: " << stats_.coarsened
                  << " requests moved to coarser levels, " << stats_.refused
                  << " left without texels (lit); the stats count them every frame\n";
        warnings_.pageBudget = true;
    }
}

void VirtualShadowMaps::uploadPageTables() {
    if (lights_.empty()) {
        return;
    }
    const int side = kVirtualResolution / pageSize_;
    const int layers = lights_.back().pageLayer + lights_.back().layers();
    if (!pageTable_ || pageTableLayers_ != layers) {
        // Mip levels for the perspective maps' levels; a clipmap level uses level 0 of its layer.
        levelsPerTable_ = PerspectiveGeometry{{}, pageSize_}.levels();
        pageTable_.emplace(GL_R32UI, glm::ivec2(side), layers, levelsPerTable_);
        glTextureParameteri(pageTable_->id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTextureParameteri(pageTable_->id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        pageTableLayers_ = layers;
        uploaded_.clear();
    }
    // The tables change only with the pool's pages (drawn, evicted, dropped), or a window moving or
    // shifting its levels; the last upload's drawn bits go stale once nothing is drawn.
    std::vector<UploadedTable> current;
    for (const Light& light : lights_) {
        current.push_back(
            {light.index, light.faceCount, light.geometry.finestLevel,
             light.faceCount == 0 ? light.geometry.windowOrigin(light.geometry.finestLevel) : glm::ivec2(0),
             !toRender_.empty()});
    }
    const bool changed = !toRender_.empty() || stats_.invalidated > 0 || current != uploaded_ ||
                         std::any_of(uploaded_.begin(), uploaded_.end(),
                                     [](const UploadedTable& table) { return table.drawnBits; });
    if (!changed) {
        return;
    }
    uploaded_ = current;
    std::vector<bool> drawn(static_cast<std::size_t>(pool_.tiles()), false);
    for (const auto& [tile, key] : toRender_) {
        drawn[static_cast<std::size_t>(tile)] = true;
    }
    const auto markDrawn = [&](std::vector<std::uint32_t>& table) {
        for (std::uint32_t& entry : table) {
            if (entry != 0u && drawn[entry & kPageTileMask]) {
                entry |= kPageDrawnBit;
            }
        }
    };
    for (const Light& light : lights_) {
        if (light.faceCount == 0) {
            std::vector<std::uint32_t> table = buildPageTable(pool_, light.index, light.geometry);
            markDrawn(table);
            glTextureSubImage3D(pageTable_->id(), 0, 0, 0, light.pageLayer, side, side, kClipmapLevels,
                                GL_RED_INTEGER, GL_UNSIGNED_INT, table.data());
            continue;
        }
        const LightState& state = lightStates_.at(light.index);
        for (int face = 0; face < light.faceCount; ++face) {
            const std::optional<PerspectiveGeometry>& geometry = state.faces[static_cast<std::size_t>(face)];
            PerspectiveGeometry empty{{}, pageSize_};
            std::vector<std::uint32_t> table =
                buildPageTable(pool_, light.index, face, geometry ? *geometry : empty);
            markDrawn(table);
            std::size_t offset = 0;
            for (int level = 0; level < light.levels(); ++level) {
                const int levelSide = side >> level;
                glTextureSubImage3D(pageTable_->id(), level, 0, 0, light.pageLayer + face, levelSide,
                                    levelSide, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, table.data() + offset);
                offset += static_cast<std::size_t>(levelSide) * static_cast<std::size_t>(levelSide);
            }
        }
    }
}

void VirtualShadowMaps::blurMoments(const engine::gl::Program& blur, GLuint unit) {
    if (toRender_.empty() || !blurTile_ || !atlas_->moments) {
        return;
    }
    const int perLayer = tilesPerRow_ * tilesPerRow_;
    glEnable(GL_SCISSOR_TEST);
    for (const auto& [tile, key] : toRender_) {
        const int layer = tile / perLayer;
        const glm::ivec2 origin = glm::ivec2(tile % tilesPerRow_, (tile % perLayer) / tilesPerRow_) * tile_;
        // Horizontal, from the tile into the temporary; vertical, back into the tile.
        blurTileFramebuffer_->bind();
        glViewport(0, 0, tile_, tile_);
        glScissor(0, 0, tile_, tile_);
        glBindTextureUnit(unit, atlas_->moments->id());
        blur.set("uLayer", layer);
        blur.set("uDirection", glm::ivec2(1, 0));
        blur.set("uSourceOffset", origin);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        atlas_->framebuffers[static_cast<std::size_t>(layer)].bind();
        glViewport(origin.x, origin.y, tile_, tile_);
        glScissor(origin.x, origin.y, tile_, tile_);
        glBindTextureUnit(unit, blurTile_->id());
        blur.set("uLayer", 0);
        blur.set("uDirection", glm::ivec2(0, 1));
        blur.set("uSourceOffset", -origin);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_SCISSOR_TEST);
}

engine::DrawnMeshes VirtualShadowMaps::render(const engine::Scene& scene, const engine::gl::Program& program,
                                              std::span<const MapSlot>, const CasterOmissions& omissions) {
    engine::DrawnMeshes drawnMeshes;
    if (toRender_.empty()) {
        return drawnMeshes;
    }
    const int perLayer = tilesPerRow_ * tilesPerRow_;
    std::map<int, const Light*> byIndex;
    for (const Light& light : lights_) {
        byIndex[light.index] = &light;
    }
    glEnable(GL_SCISSOR_TEST);
    int boundLayer = -1;
    for (const auto& [tile, key] : toRender_) {
        const int layer = tile / perLayer;
        if (layer != boundLayer) {
            atlas_->framebuffers[static_cast<std::size_t>(layer)].bind();
            boundLayer = layer;
        }
        const glm::ivec2 cell(tile % tilesPerRow_, (tile % perLayer) / tilesPerRow_);
        glViewport(cell.x * tile_, cell.y * tile_, tile_, tile_);
        glScissor(cell.x * tile_, cell.y * tile_, tile_, tile_);
        clearMapTargets(*atlas_, atlas_->framebuffers[static_cast<std::size_t>(layer)].id(), plan_);
        const Light& light = *byIndex.at(key.light);
        accumulate(drawnMeshes,
                   drawCasters(host_, scene, program,
                               light.faceCount == 0
                                   ? light.geometry.pageProjection(key.level, key.page, border_)
                                   : light.faces[static_cast<std::size_t>(key.face)].pageProjection(
                                         key.level, key.page, border_),
                               omissions));
    }
    glDisable(GL_SCISSOR_TEST);
    return drawnMeshes;
}

} // namespace shadows
