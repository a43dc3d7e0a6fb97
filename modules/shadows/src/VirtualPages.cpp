#include <shadows/VirtualPages.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace shadows {

namespace {

/// Light-space [left, right] × [bottom, top] and z range [low, high] (z towards the light) → shadow texture
/// space, computed in double: at fine levels far from the light-space origin the bounds are large and close,
/// and a float ortho loses the fraction of a texel the pages' borders must agree on.
glm::dmat4 lightToShadow(glm::dvec2 low, glm::dvec2 high, glm::dvec2 depth) {
    glm::dmat4 m(1.0);
    m[0][0] = 1.0 / (high.x - low.x);
    m[1][1] = 1.0 / (high.y - low.y);
    m[3][0] = -low.x / (high.x - low.x);
    m[3][1] = -low.y / (high.y - low.y);
    // Depth 0 at the top (nearest the light), 1 at the bottom, as glm::ortho(…, -top, -bottom) then [0,1].
    m[2][2] = -1.0 / (depth.y - depth.x);
    m[3][2] = depth.y / (depth.y - depth.x);
    return m;
}

} // namespace

int virtualPageBorderTexels(const ShadowPlan& plan) {
    // The kernel's reach, a texel for bilinear and central-difference neighbours, and one for the receiver's
    // offsets, which move the lookup before its page is read.
    return static_cast<int>(std::ceil(plan.kernelReachTexels)) + 2;
}

std::size_t virtualTileBytes(const ShadowPlan& plan, int pageSize) {
    const auto side = static_cast<std::size_t>(pageSize + 2 * virtualPageBorderTexels(plan));
    // A tile's share of the moments' mip chain: each level a quarter of the one before.
    std::size_t momentTexels = 0;
    for (int level = 0; level < std::max(plan.momentLevels, 1); ++level) {
        momentTexels += (side * side) >> (2 * level);
    }
    const std::size_t perTexel = plan.depthBytesPerTexel + (plan.storesGradient ? 8 : 0);
    return side * side * perTexel + (plan.momentsFormat != 0 ? momentTexels * plan.momentBytesPerTexel : 0);
}

std::size_t virtualOverheadBytes(int pageSize, int tableLayers) {
    const auto side = static_cast<std::size_t>(kVirtualResolution / std::max(pageSize, 1));
    const std::size_t requests = side * side * kRequestLevels / 8;
    std::size_t chain = 0;
    for (std::size_t level = side; level >= 1; level /= 2) {
        chain += level * level * 4;
    }
    return requests + chain * static_cast<std::size_t>(std::max(tableLayers, 0));
}

std::size_t PageKeyHash::operator()(const PageKey& key) const {
    std::uint64_t h = static_cast<std::uint32_t>(key.light);
    h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(key.level);
    h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(key.page.x);
    h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(key.page.y);
    h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(key.face);
    return static_cast<std::size_t>(h ^ (h >> 29));
}

double ClipmapGeometry::texelSize(int level) {
    return std::ldexp(1.0, level);
}

glm::ivec2 ClipmapGeometry::windowOrigin(int level) const {
    const double pageWorld = texelSize(level) * pageSize;
    // Clamped so that a level far finer than the camera's distance from the light-space origin can hold
    // (whose pages no pixel asks for) still has an integer window.
    constexpr double kLimit = 1 << 28;
    const glm::dvec2 page = glm::clamp(glm::floor(glm::dvec2(camera) / pageWorld), -kLimit, kLimit);
    return glm::ivec2(page) - glm::ivec2(pagesPerSide() / 2);
}

LightProjection ClipmapGeometry::levelProjection(int level) const {
    const double pageWorld = texelSize(level) * pageSize;
    const glm::dvec2 low = glm::dvec2(windowOrigin(level)) * pageWorld;
    return projectionOver(low, low + glm::dvec2(pageWorld * pagesPerSide()), level);
}

glm::vec4 ClipmapGeometry::pageRect(int level, glm::ivec2 page, int borderTexels) const {
    const double texel = texelSize(level);
    const double pageWorld = texel * pageSize;
    const glm::dvec2 low = glm::dvec2(page) * pageWorld - texel * borderTexels;
    const glm::dvec2 high = glm::dvec2(page + 1) * pageWorld + texel * borderTexels;
    return {low.x, low.y, high.x, high.y};
}

LightProjection ClipmapGeometry::pageProjection(int level, glm::ivec2 page, int borderTexels) const {
    const double texel = texelSize(level);
    const double pageWorld = texel * pageSize;
    const glm::dvec2 low = glm::dvec2(page) * pageWorld - texel * borderTexels;
    return projectionOver(low, glm::dvec2(page + 1) * pageWorld + texel * borderTexels, level);
}

LightProjection ClipmapGeometry::projectionOver(glm::dvec2 low, glm::dvec2 high, int level) const {
    LightProjection result;
    result.view = lightView;
    const glm::dmat4 toShadow = lightToShadow(low, high, glm::dvec2(depth));
    // Clip space from texture space: x, y, z of [0,1] → [-1,1].
    const glm::dmat4 textureToClip(glm::dvec4(2, 0, 0, 0), glm::dvec4(0, 2, 0, 0), glm::dvec4(0, 0, 2, 0),
                                   glm::dvec4(-1, -1, -1, 1));
    result.projection = glm::mat4(textureToClip * toShadow);
    result.worldToShadow = glm::mat4(toShadow * glm::dmat4(lightView));
    result.texelScale = static_cast<float>(texelSize(level));
    result.valid = true;
    return result;
}

int PerspectiveGeometry::levels() const {
    return std::bit_width(static_cast<unsigned>(std::max(pagesPerSide(), 1)));
}

glm::vec4 PerspectiveGeometry::pageRect(int level, glm::ivec2 page, int borderTexels) const {
    const double texel = std::ldexp(1.0, level) / kVirtualResolution;
    const glm::dvec2 low = glm::dvec2(page) * (texel * pageSize) - texel * borderTexels;
    const glm::dvec2 high = glm::dvec2(page + 1) * (texel * pageSize) + texel * borderTexels;
    return {low.x, low.y, high.x, high.y};
}

LightProjection PerspectiveGeometry::pageProjection(int level, glm::ivec2 page, int borderTexels) const {
    const glm::dvec4 rect(pageRect(level, page, borderTexels));
    const glm::dvec2 low(rect.x, rect.y);
    const glm::dvec2 size = glm::dvec2(rect.z, rect.w) - low;
    const glm::dmat4 clipToTexture(glm::dvec4(0.5, 0, 0, 0), glm::dvec4(0, 0.5, 0, 0),
                                   glm::dvec4(0, 0, 0.5, 0), glm::dvec4(0.5, 0.5, 0.5, 1));
    LightProjection result = face;
    const glm::dmat4 projection = textureRectClip(low, size) * glm::dmat4(face.projection);
    result.projection = glm::mat4(projection);
    result.worldToShadow = glm::mat4(clipToTexture * projection * glm::dmat4(face.view));
    result.texelScale = face.texelScale * std::ldexp(1.0f, level);
    return result;
}

LightProjection virtualPerspective(const glm::mat4& view, float fov, glm::vec2 depthRange) {
    LightProjection result;
    if (!(depthRange.x > 0.0f && depthRange.y > depthRange.x && std::isfinite(depthRange.y) && fov > 0.0f &&
          fov < 3.1f)) {
        return result;
    }
    const float near = std::exp2(std::floor(4.0f * std::log2(depthRange.x)) / 4.0f);
    const float far = std::exp2(std::ceil(4.0f * std::log2(depthRange.y)) / 4.0f);
    result.view = view;
    result.perspective = true;
    result.projection = glm::perspective(fov, 1.0f, near, far);
    result.depthRange = {near, far};
    const glm::mat4 clipToTexture(glm::vec4(0.5f, 0, 0, 0), glm::vec4(0, 0.5f, 0, 0),
                                  glm::vec4(0, 0, 0.5f, 0), glm::vec4(0.5f, 0.5f, 0.5f, 1));
    result.worldToShadow = clipToTexture * result.projection * view;
    result.texelScale = 2.0f * std::tan(0.5f * fov) / static_cast<float>(kVirtualResolution);
    result.valid = true;
    return result;
}

glm::vec2 depthRangeFor(const glm::mat4& lightView, std::span<const Aabb> boxes) {
    glm::vec2 range(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest());
    for (const Aabb& box : boxes) {
        if (box.empty()) {
            continue;
        }
        const Aabb light = box.transformed(lightView);
        range.x = std::min(range.x, light.min.z);
        range.y = std::max(range.y, light.max.z);
    }
    if (!(range.y >= range.x) || !std::isfinite(range.x) || !std::isfinite(range.y)) {
        return {0.0f, 1.0f};
    }
    const float span = std::max(range.y - range.x, 1e-6f * std::max(std::abs(range.x), std::abs(range.y)));
    const float step = std::ldexp(1.0f, static_cast<int>(std::ceil(std::log2(std::max(span, 1e-30f)))) - 3);
    return {std::floor(range.x / step) * step - step, std::ceil(range.y / step) * step + step};
}

int levelForTexelSize(double texelSize, int base) {
    if (!(texelSize > 0.0)) {
        return base;
    }
    const double level = std::floor(std::log2(std::min(texelSize, 1e300)));
    return static_cast<int>(
        std::clamp(level, static_cast<double>(base), static_cast<double>(base + kRequestLevels - 1)));
}

int requestLevelBase(float sceneExtent) {
    const float extent = std::isfinite(sceneExtent) && sceneExtent > 0.0f ? sceneExtent : 1.0f;
    return static_cast<int>(std::floor(std::log2(extent))) - 24;
}

std::uint32_t pageTableEntry(int levelIndex, int tile) {
    return kPageResidentBit | (static_cast<std::uint32_t>(levelIndex & 63) << 24) |
           (static_cast<std::uint32_t>(tile) & kPageTileMask);
}

PagePool::PagePool(int tiles) : tiles_(static_cast<std::size_t>(std::max(tiles, 0))) {
    free_.reserve(tiles_.size());
    for (int tile = static_cast<int>(tiles_.size()) - 1; tile >= 0; --tile) {
        free_.push_back(tile);
    }
}

void PagePool::grow(int tiles) {
    const int before = this->tiles();
    if (tiles <= before) {
        return;
    }
    tiles_.resize(static_cast<std::size_t>(tiles));
    // Free tiles are taken from the back: the new ones after those free already, lowest first.
    std::vector<int> added;
    for (int tile = tiles - 1; tile >= before; --tile) {
        added.push_back(tile);
    }
    free_.insert(free_.begin(), added.begin(), added.end());
}

void PagePool::release(int tile) {
    Tile& record = tiles_[static_cast<std::size_t>(tile)];
    if (!record.used) {
        return;
    }
    residents_.erase(record.key);
    record.used = false;
    free_.push_back(tile);
}

PagePool::FrameResult PagePool::request(std::span<const PageKey> requests, std::uint64_t frame) {
    FrameResult result;
    // Every resident page asked for is touched first, so that no new page evicts one a later request needs.
    for (const PageKey& key : requests) {
        if (const auto found = residents_.find(key); found != residents_.end()) {
            Tile& record = tiles_[static_cast<std::size_t>(found->second)];
            if (record.lastUsed != frame) {
                record.lastUsed = frame;
                ++result.cached;
            }
        }
    }
    // Tiles no request of this frame has touched, least recently used first: the eviction order.
    std::vector<int> evictable;
    std::size_t nextEvictable = 0;
    bool evictableSorted = false;
    for (const PageKey& key : requests) {
        if (residents_.contains(key)) {
            continue;
        }
        int tile = -1;
        if (!free_.empty()) {
            tile = free_.back();
            free_.pop_back();
        } else {
            if (!evictableSorted) {
                for (int t = 0; t < static_cast<int>(tiles_.size()); ++t) {
                    if (tiles_[static_cast<std::size_t>(t)].lastUsed != frame) {
                        evictable.push_back(t);
                    }
                }
                std::sort(evictable.begin(), evictable.end(), [&](int a, int b) {
                    return tiles_[static_cast<std::size_t>(a)].lastUsed <
                           tiles_[static_cast<std::size_t>(b)].lastUsed;
                });
                evictableSorted = true;
            }
            if (nextEvictable == evictable.size()) {
                ++result.refused;
                continue;
            }
            tile = evictable[nextEvictable++];
            release(tile);
            free_.pop_back(); // release pushed it
        }
        Tile& record = tiles_[static_cast<std::size_t>(tile)];
        record = {key, frame, true};
        residents_[key] = tile;
        result.render.emplace_back(tile, key);
    }
    return result;
}

int PagePool::invalidateLight(int light) {
    return invalidateWhere(light, [](const PageKey&) { return true; });
}

int PagePool::invalidate(int light, const ClipmapGeometry& geometry, glm::vec4 rect, int borderTexels) {
    return invalidateWhere(light, [&](const PageKey& key) {
        const glm::vec4 page = geometry.pageRect(key.level, key.page, borderTexels);
        return page.x <= rect.z && rect.x <= page.z && page.y <= rect.w && rect.y <= page.w;
    });
}

int PagePool::tileOf(const PageKey& key) const {
    const auto found = residents_.find(key);
    return found == residents_.end() ? -1 : found->second;
}

std::vector<std::uint32_t> buildPageTable(const PagePool& pool, int light, const ClipmapGeometry& geometry) {
    const int side = geometry.pagesPerSide();
    const auto layerSize = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    std::vector<std::uint32_t> table(layerSize * kClipmapLevels, 0u);
    std::vector<glm::ivec2> origins(kClipmapLevels);
    for (int index = 0; index < kClipmapLevels; ++index) {
        origins[static_cast<std::size_t>(index)] = geometry.windowOrigin(geometry.finestLevel + index);
    }
    pool.forEachResident([&](const PageKey& key, int tile) {
        const int index = key.level - geometry.finestLevel;
        if (key.light != light || index < 0 || index >= kClipmapLevels) {
            return;
        }
        const glm::ivec2 local = key.page - origins[static_cast<std::size_t>(index)];
        if (glm::any(glm::lessThan(local, glm::ivec2(0))) ||
            glm::any(glm::greaterThanEqual(local, glm::ivec2(side)))) {
            return;
        }
        table[static_cast<std::size_t>(index) * layerSize +
              static_cast<std::size_t>(local.y * side + local.x)] = pageTableEntry(index, tile);
    });
    // Coarse to fine: a page with no texels of its own takes its parent's entry (the parent page of absolute
    // page p is floor(p / 2): the grids are anchored at the origin, so each page lies inside one parent).
    for (int index = kClipmapLevels - 2; index >= 0; --index) {
        const glm::ivec2 origin = origins[static_cast<std::size_t>(index)];
        const glm::ivec2 parentOrigin = origins[static_cast<std::size_t>(index + 1)];
        std::uint32_t* layer = table.data() + static_cast<std::size_t>(index) * layerSize;
        const std::uint32_t* parentLayer = layer + layerSize;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                std::uint32_t& entry = layer[static_cast<std::size_t>(y * side + x)];
                if (entry != 0u) {
                    continue;
                }
                // >> 1 floors negative pages too (C++20 defines it as arithmetic).
                const glm::ivec2 absolute = origin + glm::ivec2(x, y);
                const glm::ivec2 parent = glm::ivec2(absolute.x >> 1, absolute.y >> 1) - parentOrigin;
                if (glm::all(glm::greaterThanEqual(parent, glm::ivec2(0))) &&
                    glm::all(glm::lessThan(parent, glm::ivec2(side)))) {
                    entry = parentLayer[static_cast<std::size_t>(parent.y * side + parent.x)];
                }
            }
        }
    }
    return table;
}

std::vector<std::uint32_t> buildPageTable(const PagePool& pool, int light, int face,
                                          const PerspectiveGeometry& geometry) {
    const int levels = geometry.levels();
    // Level m's (pagesPerSide >> m)² entries start where the finer levels' end.
    std::vector<std::size_t> offsets(static_cast<std::size_t>(levels) + 1, 0);
    for (int level = 0; level < levels; ++level) {
        const auto side = static_cast<std::size_t>(geometry.pagesPerSide() >> level);
        offsets[static_cast<std::size_t>(level) + 1] = offsets[static_cast<std::size_t>(level)] + side * side;
    }
    std::vector<std::uint32_t> table(offsets.back(), 0u);
    const auto at = [&](int level, glm::ivec2 page) -> std::uint32_t& {
        const int side = geometry.pagesPerSide() >> level;
        return table[offsets[static_cast<std::size_t>(level)] +
                     static_cast<std::size_t>(page.y * side + page.x)];
    };
    pool.forEachResident([&](const PageKey& key, int tile) {
        if (key.light != light || key.face != face || key.level < 0 || key.level >= levels ||
            glm::any(glm::lessThan(key.page, glm::ivec2(0))) ||
            glm::any(glm::greaterThanEqual(key.page, glm::ivec2(geometry.pagesPerSide() >> key.level)))) {
            return;
        }
        at(key.level, key.page) = pageTableEntry(key.level, tile);
    });
    // Coarse to fine: a page with no texels of its own takes its parent's entry (page p's parent is p / 2).
    for (int level = levels - 2; level >= 0; --level) {
        const int side = geometry.pagesPerSide() >> level;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                std::uint32_t& entry = at(level, {x, y});
                if (entry == 0u) {
                    entry = at(level + 1, {x >> 1, y >> 1});
                }
            }
        }
    }
    return table;
}

int coarsenToFit(std::vector<PageRequests>& requests, std::span<const CoarseningLight> lights,
                 std::size_t capacity) {
    std::size_t count = 0;
    for (const PageRequests& pages : requests) {
        count += pages.size();
    }
    const std::size_t asked = count;
    // The light asking for the most pages that still has a coarser level to give way to.
    const auto largest = [&]() -> std::optional<std::size_t> {
        std::optional<std::size_t> found;
        for (std::size_t light = 0; light < requests.size(); ++light) {
            const PageRequests& pages = requests[light];
            if (!pages.empty() && std::get<0>(*pages.begin()) < lights[light].coarsestLevel &&
                (!found || pages.size() > requests[*found].size())) {
                found = light;
            }
        }
        return found;
    };
    using Parent = std::tuple<int, int, int>; // face, parent page y, parent page x
    while (count > capacity) {
        const std::optional<std::size_t> light = largest();
        if (!light) {
            break; // the coarsest levels alone exceed the capacity
        }
        PageRequests& pages = requests[*light];
        const int level = std::get<0>(*pages.begin());
        std::map<Parent, int> children;
        for (auto it = pages.begin(); it != pages.end() && std::get<0>(*it) == level; ++it) {
            const auto& [l, face, y, x] = *it;
            ++children[{face, y >> 1, x >> 1}];
        }
        // Among the groups that free a page: a clipmap's farthest from the camera first (its finest region
        // then shrinks around the camera), else those freeing the most per page they coarsen (1 with the
        // parent asked for already, else (n - 1) / n). A group whose pages are all drawn already goes last
        // unless it is √2 times farther than the others: a walking camera's requests flicker at the levels'
        // edges, and over a full pool each page that flickers back in would be drawn again. Ties in page
        // order.
        const CoarseningLight& hints = lights[*light];
        const auto drawn = [&](const Parent& parent) {
            const auto& [face, y, x] = parent;
            bool any = false;
            for (int child = 0; child < 4; ++child) {
                const std::tuple key{level, face, 2 * y + (child >> 1), 2 * x + (child & 1)};
                if (pages.contains(key)) {
                    const PageKey page{hints.light, level, {std::get<3>(key), std::get<2>(key)}, face};
                    if (!hints.pool || hints.pool->tileOf(page) < 0) {
                        return false;
                    }
                    any = true;
                }
            }
            return any;
        };
        struct Group {
            bool frees = false;
            bool drawn = false;
            double distance = 0.0;
            double ratio = 0.0;
            Parent parent;
        };
        const glm::dvec2 centre = hints.centre * std::ldexp(1.0, -(level + 1));
        const bool central = std::isfinite(centre.x) && std::isfinite(centre.y);
        std::vector<Group> ranked;
        for (const auto& [parent, n] : children) {
            const auto& [face, y, x] = parent;
            const int freed = pages.contains({level + 1, face, y, x}) ? n : n - 1;
            const bool isDrawn = drawn(parent);
            const glm::dvec2 offset = glm::dvec2(x, y) + 0.5 - centre;
            const double distance = central ? glm::dot(offset, offset) * (isDrawn ? 0.5 : 1.0) : 0.0;
            ranked.push_back(
                {freed > 0, isDrawn, distance, static_cast<double>(freed) / static_cast<double>(n), parent});
        }
        std::stable_sort(ranked.begin(), ranked.end(), [&](const Group& a, const Group& b) {
            if (a.frees != b.frees) {
                return a.frees;
            }
            if (central) {
                return a.distance > b.distance;
            }
            return a.drawn != b.drawn ? b.drawn : a.ratio > b.ratio;
        });
        const auto merge = [&](const Parent& parent) {
            const auto& [face, y, x] = parent;
            for (int child = 0; child < 4; ++child) {
                count -= pages.erase({level, face, 2 * y + (child >> 1), 2 * x + (child & 1)});
            }
            count += pages.insert({level + 1, face, y, x}).second ? 1 : 0;
        };
        if (!ranked.front().frees) {
            // No group frees a page: the level moves up whole, and its parents may pair up there.
            for (const Group& group : ranked) {
                merge(group.parent);
            }
            continue;
        }
        for (const Group& group : ranked) {
            if (count <= capacity || !group.frees) {
                break;
            }
            merge(group.parent);
            if (largest() != light) {
                break; // another light asks for more now: it gives way next
            }
        }
    }
    return static_cast<int>(asked - count);
}

} // namespace shadows
