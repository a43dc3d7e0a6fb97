#include "VirtualShadowMaps.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
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

glm::vec4 unite(const glm::vec4& a, const glm::vec4& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.z, b.z), std::max(a.w, b.w)};
}

} // namespace

VirtualShadowMaps::VirtualShadowMaps(const ShadowSettings& settings, const ShadowPlan& plan)
    : plan_(plan), pageSize_(settings.virtualPageSize), border_(virtualPageBorderTexels(plan)),
      tile_(settings.virtualPageSize + 2 * virtualPageBorderTexels(plan)),
      texelPixels_(settings.virtualTexelPixels), pool_(0) {
    const std::size_t budget = static_cast<std::size_t>(settings.virtualBudgetMiB) << 20;
    const std::size_t tiles = budget / virtualTileBytes(plan, pageSize_);
    if (tiles < 1) {
        throw std::invalid_argument("shadow settings: virtualBudgetMiB " +
                                    std::to_string(settings.virtualBudgetMiB) + " holds no page of " +
                                    std::to_string(tile_) + "² texels");
    }
    GLint maxSize = 0;
    GLint maxLayers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    const int perRowLimit = std::max(maxSize / tile_, 1);
    tilesPerRow_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(tiles))), 1, perRowLimit);
    const auto perLayer = static_cast<std::size_t>(tilesPerRow_) * static_cast<std::size_t>(tilesPerRow_);
    layers_ = static_cast<int>(
        std::clamp<std::size_t>(tiles / perLayer, 1, static_cast<std::size_t>(std::max(maxLayers, 1))));
    pool_ = PagePool(static_cast<int>(perLayer) * layers_);
    ShadowPlan atlasPlan = plan;
    atlasPlan.blursMoments = false; // pages are not blurred (ShadowSettings::validate refuses a blur radius)
    atlas_ = std::make_unique<ShadowMapArray>(tilesPerRow_ * tile_, layers_, atlasPlan);
}

std::size_t VirtualShadowMaps::bytes() const {
    std::size_t total = atlas_->bytes(plan_);
    if (pageTable_) {
        const auto side = static_cast<std::size_t>(kVirtualResolution / pageSize_);
        total += side * side * static_cast<std::size_t>(pageTable_->layers()) * 4;
    }
    if (requests_) {
        total += requests_->size();
    }
    return total;
}

glm::ivec4 VirtualShadowMaps::pagesUniform() const {
    return {kVirtualResolution / pageSize_, tilesPerRow_, tilesPerRow_ * tile_, 0};
}

glm::vec4 VirtualShadowMaps::pageUniform() const {
    return {static_cast<float>(pageSize_), static_cast<float>(tile_), static_cast<float>(border_),
            1.0f / static_cast<float>(tilesPerRow_ * tile_)};
}

std::vector<PageKey> VirtualShadowMaps::requestedPages(int light, ClipmapGeometry& geometry, int levelBase) {
    const int side = geometry.pagesPerSide();
    const auto levelBits = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    std::vector<std::uint32_t> words(requests_->size() / 4);
    glGetNamedBufferSubData(requests_->id(), 0, static_cast<GLsizeiptr>(requests_->size()), words.data());
    std::vector<PageKey> pages;
    int finest = levelBase + kRequestLevels;
    int coarsest = levelBase - 1;
    for (std::size_t word = 0; word < words.size(); ++word) {
        for (std::uint32_t bits = words[word]; bits != 0u; bits &= bits - 1u) {
            const std::size_t bit = word * 32 + static_cast<std::size_t>(std::countr_zero(bits));
            const int level = levelBase + static_cast<int>(bit / levelBits);
            const auto local = static_cast<int>(bit % levelBits);
            pages.push_back(
                {light, level, geometry.windowOrigin(level) + glm::ivec2(local % side, local / side)});
            finest = std::min(finest, level);
            coarsest = std::max(coarsest, level);
        }
    }
    if (pages.empty()) {
        geometry.finestLevel = levelBase;
        return pages;
    }
    // The clipmap spans kClipmapLevels levels up to the coarsest asked for; finer requests read the finest
    // level's page over them.
    geometry.finestLevel = std::max(finest, coarsest - kClipmapLevels + 1);
    std::set<std::tuple<int, int, int>> unique; // level, y, x
    for (const PageKey& page : pages) {
        const int shift = std::max(geometry.finestLevel - page.level, 0);
        unique.insert({page.level + shift, page.page.y >> shift, page.page.x >> shift});
    }
    // Over budget, the finest level's requests give way to their parents until the pool holds them all.
    const auto tiles = static_cast<std::size_t>(pool_.tiles());
    const std::size_t asked = unique.size();
    while (unique.size() > tiles) {
        const int level = std::get<0>(*unique.begin());
        if (level >= geometry.finestLevel + kClipmapLevels - 1) {
            break; // the coarsest level alone exceeds the pool: the rest is refused (and reported)
        }
        std::set<std::tuple<int, int, int>> coarser;
        for (const auto& [l, y, x] : unique) {
            coarser.insert(l == level ? std::tuple{l + 1, y >> 1, x >> 1} : std::tuple{l, y, x});
        }
        unique.swap(coarser);
    }
    stats_.coarsened += static_cast<int>(asked - unique.size());
    pages.clear();
    // Coarse to fine, so that if the pool still runs out, the coarse pages stay.
    for (auto it = unique.rbegin(); it != unique.rend(); ++it) {
        const auto& [level, y, x] = *it;
        pages.push_back({light, level, {x, y}});
    }
    return pages;
}

void VirtualShadowMaps::invalidateMovedCasters(const std::vector<Light>& lights,
                                               const std::map<engine::EntityId, Aabb>& casters) {
    // Every entity whose box appeared, vanished or changed: its old and new footprints hold stale texels.
    std::vector<std::pair<std::optional<Aabb>, std::optional<Aabb>>> moved;
    for (const auto& [entity, box] : casters) {
        const auto before = casters_.find(entity);
        if (before == casters_.end()) {
            moved.emplace_back(std::nullopt, box);
        } else if (before->second.min != box.min || before->second.max != box.max) {
            moved.emplace_back(before->second, box);
        }
    }
    for (const auto& [entity, box] : casters_) {
        if (!casters.contains(entity)) {
            moved.emplace_back(box, std::nullopt);
        }
    }
    for (const Light& light : lights) {
        for (const auto& [before, after] : moved) {
            const glm::mat4& view = light.geometry.lightView;
            glm::vec4 rect = before ? lightRect(view, *before) : lightRect(view, *after);
            if (before && after) {
                rect = unite(rect, lightRect(view, *after));
            }
            stats_.invalidated += pool_.invalidate(light.index, light.geometry, rect, border_);
        }
    }
    casters_ = casters;
}

std::vector<VirtualShadowMaps::Light>
VirtualShadowMaps::update(const engine::gl::Program& mark, const FitView& fit,
                          std::span<const engine::FrameLight> lights,
                          const std::map<engine::EntityId, Aabb>& casters, std::span<const Aabb> boxes,
                          GLuint depth, glm::ivec2 size) {
    stats_ = {};
    toRender_.clear();
    lights_.clear();
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
    const glm::mat4 cameraWorld = glm::inverse(fit.view);
    const glm::vec3 camera(cameraWorld[3]);

    for (const engine::FrameLight& light : lights) {
        Light entry;
        entry.index = light.index;
        entry.pageLayer = static_cast<int>(lights_.size()) * kClipmapLevels;
        ClipmapGeometry& geometry = entry.geometry;
        geometry.lightView = lightView(light.direction);
        geometry.pageSize = pageSize_;
        geometry.camera = glm::vec2(geometry.lightView * glm::vec4(camera, 1.0f));
        geometry.depth = depthRangeFor(geometry.lightView, boxes);
        // A turned light or a new depth range changes every texel of the light's pages.
        LightState& state = lightStates_[light.index];
        if (state.direction != light.direction || state.depth != geometry.depth) {
            stats_.invalidated += pool_.invalidateLight(light.index);
            state = {light.direction, geometry.depth};
        }
        lights_.push_back(entry);
    }
    invalidateMovedCasters(lights_, casters);

    const glm::mat4 clipToWorld = glm::inverse(fit.projection * fit.view);
    std::vector<PageKey> requests;
    for (Light& light : lights_) {
        ClipmapGeometry& geometry = light.geometry;
        std::array<glm::ivec2, kRequestLevels> origins{};
        for (int level = 0; level < kRequestLevels; ++level) {
            origins[static_cast<std::size_t>(level)] = geometry.windowOrigin(levelBase + level);
        }
        const std::uint32_t zero = 0;
        glClearNamedBufferData(requests_->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        mark.use();
        mark.set("uDepth", 0);
        mark.set("uSize", size);
        mark.set("uClipToWorld", clipToWorld);
        mark.set("uWorldToLight", geometry.lightView);
        const glm::vec3 toLight =
            -glm::normalize(glm::vec3(glm::inverse(geometry.lightView) * glm::vec4(0, 0, -1, 0)));
        glUniform3fv(mark.uniformLocation("uToLight"), 1, glm::value_ptr(toLight));
        glUniform3fv(mark.uniformLocation("uCamera"), 1, glm::value_ptr(camera));
        mark.set("uLevelBase", levelBase);
        mark.set("uPageSize", pageSize_);
        mark.set("uPagesPerSide", side);
        glUniform1f(mark.uniformLocation("uReach"), static_cast<float>(border_));
        glUniform1f(mark.uniformLocation("uTexelPixels"), texelPixels_);
        glUniform2iv(mark.uniformLocation("uWindowOrigin"), kRequestLevels, glm::value_ptr(origins[0]));
        glBindTextureUnit(0, depth);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, requests_->id());
        // 8x8 invocations a group, each marking a 4x4 block of pixels (pages.comp).
        const glm::ivec2 groups = (size + glm::ivec2(31)) / 32;
        glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y), 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        const std::vector<PageKey> pages = requestedPages(light.index, geometry, levelBase);
        requests.insert(requests.end(), pages.begin(), pages.end());
    }
    glUseProgram(0);
    stats_.requested = static_cast<int>(requests.size());
    PagePool::FrameResult served = pool_.request(requests, ++frame_);
    stats_.cached = served.cached;
    stats_.refused = served.refused;
    stats_.rendered = static_cast<int>(served.render.size());
    stats_.resident = pool_.resident();
    stats_.poolPages = pool_.tiles();
    stats_.texelsRendered =
        served.render.size() * static_cast<std::size_t>(tile_) * static_cast<std::size_t>(tile_);
    toRender_ = std::move(served.render);

    if (!lights_.empty()) {
        const auto layers = static_cast<int>(lights_.size()) * kClipmapLevels;
        if (!pageTable_ || pageTableLights_ != static_cast<int>(lights_.size())) {
            pageTable_.emplace(GL_R32UI, glm::ivec2(side), layers);
            glTextureParameteri(pageTable_->id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(pageTable_->id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            pageTableLights_ = static_cast<int>(lights_.size());
            uploaded_.clear();
        }
        // The tables change only with the pool's pages (drawn, evicted, dropped), or a window moving or
        // shifting its levels; the last upload's drawn bits go stale once nothing is drawn.
        std::vector<UploadedTable> current;
        for (const Light& light : lights_) {
            current.push_back({light.index, light.geometry.finestLevel,
                               light.geometry.windowOrigin(light.geometry.finestLevel), !toRender_.empty()});
        }
        const bool changed = !toRender_.empty() || stats_.invalidated > 0 || current != uploaded_ ||
                             std::any_of(uploaded_.begin(), uploaded_.end(),
                                         [](const UploadedTable& table) { return table.drawnBits; });
        if (!changed) {
            return lights_;
        }
        uploaded_ = current;
        for (const Light& light : lights_) {
            std::vector<std::uint32_t> table = buildPageTable(pool_, light.index, light.geometry);
            std::vector<bool> drawn(static_cast<std::size_t>(pool_.tiles()), false);
            for (const auto& [tile, key] : toRender_) {
                drawn[static_cast<std::size_t>(tile)] = true;
            }
            for (std::uint32_t& entry : table) {
                if (entry != 0u && drawn[entry & kPageTileMask]) {
                    entry |= kPageDrawnBit;
                }
            }
            glTextureSubImage3D(pageTable_->id(), 0, 0, 0, light.pageLayer, side, side, kClipmapLevels,
                                GL_RED_INTEGER, GL_UNSIGNED_INT, table.data());
        }
    }
    return lights_;
}

void VirtualShadowMaps::render(engine::ModuleHost& host, const engine::Scene& scene,
                               const engine::gl::Program& program, const glm::vec4& clearMoments) {
    if (toRender_.empty()) {
        return;
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
        const GLuint framebuffer = atlas_->framebuffers[static_cast<std::size_t>(layer)].id();
        if (atlas_->gradient) {
            const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, zero);
        } else if (atlas_->moments) {
            glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, glm::value_ptr(clearMoments));
        }
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        const LightProjection projection =
            byIndex.at(key.light)->geometry.pageProjection(key.level, key.page, border_);
        const glm::mat4 viewProjection = projection.projection * projection.view;
        program.set("uLightViewProjection", viewProjection);
        program.set("uDepthRange", glm::vec2(0.0f));
        host.drawMeshes(scene, viewProjection, [&](engine::EntityId, const glm::mat4& model) {
            program.set("uModel", model);
            return true;
        });
    }
    glDisable(GL_SCISSOR_TEST);
}

} // namespace shadows
