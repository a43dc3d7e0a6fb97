#include <shadowbench/SoftShadowMetrics.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace shadowbench {

namespace {

bool receiver(std::span<const PixelClass> classes, std::size_t i) {
    return classes[i] != PixelClass::Ignored;
}

/// `values` bilinearly at `point` (pixel centres at integer + 0.5), nullopt off the image or where one of the
/// four pixels is not a receiver.
std::optional<float> sample(glm::ivec2 size, std::span<const PixelClass> classes,
                            std::span<const float> values, glm::vec2 point) {
    const glm::vec2 p = point - 0.5f;
    const glm::ivec2 base(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
    if (base.x < 0 || base.y < 0 || base.x + 1 >= size.x || base.y + 1 >= size.y) {
        return std::nullopt;
    }
    const glm::vec2 f = p - glm::vec2(base);
    float corners[4];
    for (int c = 0; c < 4; ++c) {
        const std::size_t i = pixelIndex(size, base.x + (c & 1), base.y + (c >> 1));
        if (!receiver(classes, i)) {
            return std::nullopt;
        }
        corners[c] = values[i];
    }
    return glm::mix(glm::mix(corners[0], corners[1], f.x), glm::mix(corners[2], corners[3], f.x), f.y);
}

/// The nearest-rank percentile `q` of `values` (sorted in place).
double percentile(std::vector<double>& values, double q) {
    if (values.empty()) {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
    return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

} // namespace

float penumbraWidth(glm::ivec2 size, std::span<const PixelClass> classes, std::span<const float> visibility,
                    glm::vec2 from, glm::vec2 direction, float reach, float low, float high) {
    constexpr float kStep = 0.25f;
    const auto at = [&](float t) { return sample(size, classes, visibility, from + t * direction); };
    // The profile along the line, sampled every kStep pixels within the reach, until it leaves the receivers.
    const int steps = static_cast<int>(reach / kStep);
    std::vector<float> profile;
    int first = 0;
    for (int k = 0; k >= -steps; --k) {
        if (!at(static_cast<float>(k) * kStep)) {
            break;
        }
        first = k;
    }
    for (int k = first; k <= steps; ++k) {
        const std::optional<float> value = at(static_cast<float>(k) * kStep);
        if (!value) {
            break;
        }
        profile.push_back(*value);
    }
    const auto parameter = [&](std::size_t index) {
        return static_cast<float>(first + static_cast<int>(index)) * kStep;
    };
    // Where the profile crosses `level` between samples a and a + 1, linearly.
    const auto crossing = [&](std::size_t a, float level) {
        const float v0 = profile[a];
        const float v1 = profile[a + 1];
        const float f = v1 != v0 ? (level - v0) / (v1 - v0) : 0.5f;
        return parameter(a) + std::clamp(f, 0.0f, 1.0f) * kStep;
    };
    // The 0.5 crossing nearest `from`.
    std::optional<std::size_t> middle;
    for (std::size_t a = 0; a + 1 < profile.size(); ++a) {
        if ((profile[a] < 0.5f) != (profile[a + 1] < 0.5f) &&
            (!middle || std::abs(parameter(a)) < std::abs(parameter(*middle)))) {
            middle = a;
        }
    }
    if (!middle) {
        return -1.0f;
    }
    // From the 0.5 crossing on, ahead along the line to the first crossing of the level it rises or falls
    // towards, and behind it to the other.
    const bool rising = profile[*middle + 1] > profile[*middle];
    const float aheadLevel = rising ? high : low;
    const float behindLevel = rising ? low : high;
    const auto beyond = [&](float value, float level, bool above) {
        return above ? value >= level : value <= level;
    };
    std::optional<float> ahead;
    std::optional<float> behind;
    for (std::size_t a = *middle; a + 1 < profile.size() && !ahead; ++a) {
        if (beyond(profile[a + 1], aheadLevel, rising)) {
            ahead = crossing(a, aheadLevel);
        }
    }
    for (std::size_t a = *middle + 1; a-- > 0 && !behind;) {
        if (beyond(profile[a], behindLevel, !rising)) {
            behind = crossing(a, behindLevel);
        }
    }
    if (!ahead || !behind) {
        return -1.0f;
    }
    return std::abs(*ahead - *behind);
}

SoftShadowMetrics softShadowMetrics(glm::ivec2 size, std::span<const PixelClass> classes,
                                    std::span<const float> truth, std::span<const float> visibility,
                                    float minimumWidth) {
    SoftShadowMetrics metrics;
    // The penumbra mask: receivers between 0.02 and 0.98, dilated over the receivers.
    std::vector<std::uint8_t> penumbra(truth.size(), 0);
    const int reach = static_cast<int>(std::ceil(kPenumbraDilation));
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = pixelIndex(size, x, y);
            if (!receiver(classes, i) || !(truth[i] > 0.02f && truth[i] < 0.98f)) {
                continue;
            }
            for (int dy = -reach; dy <= reach; ++dy) {
                for (int dx = -reach; dx <= reach; ++dx) {
                    const int px = x + dx;
                    const int py = y + dy;
                    if (px >= 0 && py >= 0 && px < size.x && py < size.y &&
                        static_cast<float>(dx * dx + dy * dy) <= kPenumbraDilation * kPenumbraDilation) {
                        penumbra[pixelIndex(size, px, py)] = 1;
                    }
                }
            }
        }
    }
    double squared = 0.0;
    double absolute = 0.0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!receiver(classes, i)) {
            continue;
        }
        if (penumbra[i]) {
            const double error = static_cast<double>(visibility[i]) - truth[i];
            squared += error * error;
            absolute += std::abs(error);
            ++metrics.penumbraPixels;
        } else if (truth[i] <= 0.02f) {
            ++metrics.umbraPixels;
            metrics.falseLit += visibility[i] > 0.5f;
        } else {
            ++metrics.litPixels;
            metrics.falseShadow += visibility[i] < 0.5f;
        }
    }
    if (metrics.penumbraPixels > 0) {
        metrics.penumbraRmse = std::sqrt(squared / static_cast<double>(metrics.penumbraPixels));
        metrics.penumbraMae = absolute / static_cast<double>(metrics.penumbraPixels);
    }
    // Width samples: receivers on the truth's 0.5 iso-line (at or above it, with a 4-neighbour below), the
    // line along its gradient (central differences).
    std::vector<double> errors;
    for (int y = 1; y + 1 < size.y; ++y) {
        for (int x = 1; x + 1 < size.x; ++x) {
            const std::size_t i = pixelIndex(size, x, y);
            const std::size_t left = pixelIndex(size, x - 1, y);
            const std::size_t right = pixelIndex(size, x + 1, y);
            const std::size_t down = pixelIndex(size, x, y - 1);
            const std::size_t up = pixelIndex(size, x, y + 1);
            if (!receiver(classes, i) || truth[i] < 0.5f) {
                continue;
            }
            bool edge = false;
            for (const std::size_t n : {left, right, down, up}) {
                edge = edge || (receiver(classes, n) && truth[n] < 0.5f);
            }
            if (!edge || !receiver(classes, left) || !receiver(classes, right) || !receiver(classes, down) ||
                !receiver(classes, up)) {
                continue;
            }
            const glm::vec2 gradient(truth[right] - truth[left], truth[up] - truth[down]);
            const float length = glm::length(gradient);
            if (!(length > 0.0f)) {
                continue;
            }
            const glm::vec2 from = glm::vec2(x, y) + 0.5f;
            const glm::vec2 direction = gradient / length;
            const float searchReach = 64.0f;
            const float trueWidth = penumbraWidth(size, classes, truth, from, direction, searchReach);
            if (trueWidth < minimumWidth) {
                continue; // narrower than measured, or its profile leaves the receivers
            }
            const float renderedWidth =
                penumbraWidth(size, classes, visibility, from, direction, searchReach);
            if (renderedWidth < 0.0f) {
                ++metrics.widthMissing;
                continue;
            }
            errors.push_back(std::abs(static_cast<double>(renderedWidth) - trueWidth));
            metrics.widths.emplace_back(trueWidth, renderedWidth);
            metrics.widthPixels.emplace_back(x, y);
        }
    }
    metrics.widthSamples = errors.size();
    metrics.widthErrorMedian = percentile(errors, 0.5);
    metrics.widthErrorP95 = percentile(errors, 0.95);
    std::vector<double> ratios;
    for (const glm::vec2& width : metrics.widths) {
        ratios.push_back(static_cast<double>(width.y) /
                         static_cast<double>(width.x)); // true widths >= minimum
    }
    metrics.widthRatioMedian = percentile(ratios, 0.5);
    return metrics;
}

void seamWidthJumps(glm::ivec2 size, std::span<const float> slots, SoftShadowMetrics& metrics) {
    // The samples by pixel, to find each one's neighbours.
    std::vector<int> sampleAt(slots.size(), -1);
    for (std::size_t k = 0; k < metrics.widthPixels.size(); ++k) {
        sampleAt[pixelIndex(size, metrics.widthPixels[k].x, metrics.widthPixels[k].y)] = static_cast<int>(k);
    }
    std::vector<double> jumps;
    for (std::size_t k = 0; k < metrics.widthPixels.size(); ++k) {
        const glm::ivec2 a = metrics.widthPixels[k];
        const float slotA = slots[pixelIndex(size, a.x, a.y)];
        if (slotA < 0.0f) {
            continue;
        }
        for (int dy = -kSeamPairReach; dy <= kSeamPairReach; ++dy) {
            for (int dx = -kSeamPairReach; dx <= kSeamPairReach; ++dx) {
                const glm::ivec2 b = a + glm::ivec2(dx, dy);
                if (b.x < 0 || b.y < 0 || b.x >= size.x || b.y >= size.y) {
                    continue;
                }
                const int other = sampleAt[pixelIndex(size, b.x, b.y)];
                const float slotB = slots[pixelIndex(size, b.x, b.y)];
                // Each pair once (the later sample's), across a seam only.
                if (other <= static_cast<int>(k) || slotB < 0.0f || slotB == slotA) {
                    continue;
                }
                const glm::vec2 wa = metrics.widths[k];
                const glm::vec2 wb = metrics.widths[static_cast<std::size_t>(other)];
                jumps.push_back(std::abs(static_cast<double>((wa.y - wb.y) - (wa.x - wb.x))));
            }
        }
    }
    metrics.seamPairs = jumps.size();
    metrics.seamJumpMax = jumps.empty() ? 0.0 : *std::max_element(jumps.begin(), jumps.end());
    metrics.seamJumpMedian = percentile(jumps, 0.5);
}

} // namespace shadowbench
