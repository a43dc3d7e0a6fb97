#include <shadows/ShadowSettings.h>
#include <shadows/TapPattern.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace shadows {

namespace {

std::vector<glm::vec2> gridOffsets(int n, float radius) {
    if (n < 2 || n > 8) {
        throw std::invalid_argument("pcf grid size " + std::to_string(n) + " is outside [2, 8]");
    }
    std::vector<glm::vec2> offsets;
    const float step = 2.0f * radius / static_cast<float>(n - 1);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            offsets.emplace_back(-radius + step * static_cast<float>(x),
                                 -radius + step * static_cast<float>(y));
        }
    }
    return offsets;
}

/// Dart throwing with a fixed-seed linear congruential generator, shrinking the exclusion distance until the
/// requested count fits, so every run (and the CPU tests) sees the same pattern.
std::vector<glm::vec2> poissonOffsets(int count, float radius) {
    if (count < 8 || count > TapPattern::kMaxTaps) {
        throw std::invalid_argument("poisson tap count " + std::to_string(count) + " is outside [8, 64]");
    }
    std::uint32_t state = 0x9E3779B9u;
    auto random = [&state] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    // Ideal spacing for `count` points in a unit disk is about sqrt(pi / count); start a bit above it.
    float spacing = 1.2f * std::sqrt(glm::pi<float>() / static_cast<float>(count));
    std::vector<glm::vec2> points;
    while (static_cast<int>(points.size()) < count) {
        points.clear();
        for (int attempt = 0; attempt < 20000 && static_cast<int>(points.size()) < count; ++attempt) {
            const glm::vec2 candidate(2.0f * random() - 1.0f, 2.0f * random() - 1.0f);
            if (glm::dot(candidate, candidate) > 1.0f) {
                continue;
            }
            bool farEnough = true;
            for (const glm::vec2& p : points) {
                farEnough = farEnough && glm::distance(p, candidate) >= spacing;
            }
            if (farEnough) {
                points.push_back(candidate);
            }
        }
        spacing *= 0.95f;
    }
    for (glm::vec2& p : points) {
        p *= radius;
    }
    return points;
}

std::vector<glm::vec2> circular8Offsets(float radius) {
    // The reference uses d = 0.5 texel; `radius` scales the pattern so its axial taps sit at `radius`.
    const float d = radius / std::sqrt(2.0f);
    const float l = radius;
    return {{-l, 0}, {l, 0}, {0, -l}, {0, l}, {-d, -d}, {d, -d}, {-d, d}, {d, d}};
}

/// Solves the 6x6 normal equations by Gauss-Jordan elimination with partial pivoting; false when singular.
bool invert6(std::array<std::array<double, 6>, 6>& m) {
    std::array<std::array<double, 12>, 6> a{};
    double largest = 0.0;
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) {
            a[r][c] = m[r][c];
            largest = std::max(largest, std::abs(m[r][c]));
        }
        a[r][6 + r] = 1.0;
    }
    for (int c = 0; c < 6; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 6; ++r) {
            if (std::abs(a[r][c]) > std::abs(a[pivot][c])) {
                pivot = r;
            }
        }
        if (std::abs(a[pivot][c]) <= 1e-9 * largest) {
            return false;
        }
        std::swap(a[c], a[pivot]);
        const double inverse = 1.0 / a[c][c];
        for (double& value : a[c]) {
            value *= inverse;
        }
        for (int r = 0; r < 6; ++r) {
            if (r != c && a[r][c] != 0.0) {
                const double factor = a[r][c];
                for (int k = 0; k < 12; ++k) {
                    a[r][k] -= factor * a[c][k];
                }
            }
        }
    }
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) {
            m[r][c] = a[r][6 + c];
        }
    }
    return true;
}

void precomputeLinks(TapPattern& pattern) {
    const std::vector<glm::vec2>& offsets = pattern.offsets;
    pattern.nearestFirst.resize(offsets.size());
    std::iota(pattern.nearestFirst.begin(), pattern.nearestFirst.end(), 0);
    std::stable_sort(pattern.nearestFirst.begin(), pattern.nearestFirst.end(),
                     [&](int a, int b) { return glm::length(offsets[a]) < glm::length(offsets[b]); });
    float widestGap = 0.0f;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        float nearest = std::numeric_limits<float>::max();
        for (std::size_t j = 0; j < offsets.size(); ++j) {
            if (j != i) {
                nearest = std::min(nearest, glm::length(offsets[i] - offsets[j]));
            }
        }
        if (nearest < std::numeric_limits<float>::max()) {
            widestGap = std::max(widestGap, nearest);
        }
    }
    pattern.linkDistance = 1.5f * widestGap;
}

void precomputeFits(TapPattern& pattern) {
    const auto n = pattern.offsets.size();
    glm::dvec2 mean(0.0);
    for (const glm::vec2& o : pattern.offsets) {
        mean += glm::dvec2(o);
    }
    mean /= static_cast<double>(n);
    glm::dmat2 covariance(0.0);
    for (const glm::vec2& o : pattern.offsets) {
        const glm::dvec2 d = glm::dvec2(o) - mean;
        covariance += glm::outerProduct(d, d);
    }
    const double det = glm::determinant(covariance);
    const double trace = covariance[0][0] + covariance[1][1];
    pattern.inverseCovariance =
        det > 1e-9 * trace * trace ? glm::mat2(glm::inverse(covariance)) : glm::mat2(0.0f);

    // Quadric design rows (1, x, y, x²/2, xy, y²/2): solve (AᵀA) c = Aᵀd once for the pseudo-inverse.
    auto basis = [](const glm::vec2& o) {
        const double x = o.x;
        const double y = o.y;
        return std::array<double, 6>{1.0, x, y, 0.5 * x * x, x * y, 0.5 * y * y};
    };
    std::array<std::array<double, 6>, 6> normal{};
    for (const glm::vec2& o : pattern.offsets) {
        const auto row = basis(o);
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 6; ++c) {
                normal[r][c] += row[r] * row[c];
            }
        }
    }
    pattern.quadraticFitRows.fill(0.0f);
    pattern.quadraticValid = n >= 6 && invert6(normal);
    if (pattern.quadraticValid) {
        for (std::size_t i = 0; i < n; ++i) {
            const auto row = basis(pattern.offsets[i]);
            for (int r = 0; r < 6; ++r) {
                double value = 0.0;
                for (int c = 0; c < 6; ++c) {
                    value += normal[r][c] * row[c];
                }
                pattern.quadraticFitRows[static_cast<std::size_t>(r * TapPattern::kMaxTaps) + i] =
                    static_cast<float>(value);
            }
        }
        return;
    }
    // Degenerate for a quadric: fall back to the plane fit (a = mean depth - g.mean offset, g by least
    // squares).
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 centred = glm::vec2(glm::dvec2(pattern.offsets[i]) - mean);
        const glm::vec2 gradientWeight = pattern.inverseCovariance * centred;
        pattern.quadraticFitRows[TapPattern::kMaxTaps + i] = gradientWeight.x;
        pattern.quadraticFitRows[2 * TapPattern::kMaxTaps + i] = gradientWeight.y;
        pattern.quadraticFitRows[i] =
            static_cast<float>(1.0 / static_cast<double>(n)) - glm::dot(glm::vec2(mean), gradientWeight);
    }
}

} // namespace

TapPattern TapPattern::make(TapLayout layout, int taps, float radius) {
    if (!(radius > 0.0f) || !std::isfinite(radius)) {
        throw std::invalid_argument("pcf radius " + std::to_string(radius) +
                                    " must be a positive number of texels");
    }
    TapPattern pattern;
    pattern.layout = layout;
    switch (layout) {
    case TapLayout::Grid:
        pattern.offsets = gridOffsets(taps, radius);
        break;
    case TapLayout::Poisson:
        pattern.offsets = poissonOffsets(taps, radius);
        break;
    case TapLayout::Circular8:
        pattern.offsets = circular8Offsets(radius);
        break;
    }
    precomputeFits(pattern);
    precomputeLinks(pattern);
    return pattern;
}

std::string toString(TapLayout layout) {
    return std::string(nameOf(layout));
}

} // namespace shadows

namespace shadows {

namespace {

glm::ivec2 strataGrid(int taps) {
    int columns = static_cast<int>(std::sqrt(static_cast<double>(taps)));
    while (taps % columns != 0) {
        --columns;
    }
    return {taps / columns, columns};
}

/// A stride coprime with `taps` near taps·0.618, so consecutive taps land far apart.
int coprimeStride(int taps) {
    for (int stride = static_cast<int>(static_cast<double>(taps) * 0.618) | 1; stride < taps; stride += 2) {
        int a = stride;
        int b = taps;
        while (b != 0) {
            const int t = a % b;
            a = b;
            b = t;
        }
        if (a == 1) {
            return stride;
        }
    }
    return 1;
}

} // namespace

glm::ivec2 jitterStratum(int tap, int taps, glm::ivec2& grid) {
    grid = strataGrid(taps);
    const int cell = static_cast<int>((static_cast<long long>(tap) * coprimeStride(taps)) % taps);
    return {cell % grid.x, cell / grid.x};
}

JitterTexels makeJitterTexels(int taps, int size) {
    if (taps < 2 || taps % 2 != 0 || taps > TapPattern::kMaxTaps) {
        throw std::invalid_argument("jitter taps " + std::to_string(taps) + " must be even and in [2, 64]");
    }
    JitterTexels result;
    result.size = size;
    result.pairs = taps / 2;
    result.texels.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) *
                         static_cast<std::size_t>(result.pairs));
    std::uint32_t state = 0x2545F491u;
    auto random = [&state] {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    auto encode = [](float unit) {
        return static_cast<std::uint16_t>(std::lround(std::clamp(unit, 0.0f, 1.0f) * 65535.0f));
    };
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            for (int tap = 0; tap < taps; ++tap) {
                glm::ivec2 grid;
                const glm::ivec2 stratum = jitterStratum(tap, taps, grid);
                // A uniform point inside the stratum, in [0,1]² (stored as unorm; the shader maps it to
                // [-1,1]²).
                const glm::vec2 point((static_cast<float>(stratum.x) + random()) / static_cast<float>(grid.x),
                                      (static_cast<float>(stratum.y) + random()) /
                                          static_cast<float>(grid.y));
                const std::size_t index =
                    (static_cast<std::size_t>(tap / 2) * static_cast<std::size_t>(size) +
                     static_cast<std::size_t>(y)) *
                        static_cast<std::size_t>(size) +
                    static_cast<std::size_t>(x);
                glm::u16vec4& texel = result.texels[index];
                if (tap % 2 == 0) {
                    texel.x = encode(point.x);
                    texel.y = encode(point.y);
                } else {
                    texel.z = encode(point.x);
                    texel.w = encode(point.y);
                }
            }
        }
    }
    return result;
}

} // namespace shadows
