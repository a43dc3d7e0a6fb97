#include <shadowbench/ShadowMetrics.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowbench {

namespace {
/// Exact squared Euclidean distance of a sampled function along one line, in place (Felzenszwalb &
/// Huttenlocher, "Distance Transforms of Sampled Functions", ToC 2012, section 2.1: the lower envelope of the
/// parabolas rooted at each sample).
void distanceTransform1d(std::vector<double>& f) {
    const int n = static_cast<int>(f.size());
    std::vector<double> out(f.size());
    std::vector<int> roots(f.size());
    std::vector<double> bounds(f.size() + 1);
    int k = -1;
    for (int q = 0; q < n; ++q) {
        if (!std::isfinite(f[static_cast<std::size_t>(q)])) {
            continue; // no sample here: its parabola lies at infinity
        }
        double s = -std::numeric_limits<double>::infinity();
        while (k >= 0) {
            const int r = roots[static_cast<std::size_t>(k)];
            s = ((f[static_cast<std::size_t>(q)] + q * q) - (f[static_cast<std::size_t>(r)] + r * r)) /
                (2.0 * (q - r));
            if (s > bounds[static_cast<std::size_t>(k)]) {
                break;
            }
            --k;
        }
        ++k;
        roots[static_cast<std::size_t>(k)] = q;
        bounds[static_cast<std::size_t>(k)] = k == 0 ? -std::numeric_limits<double>::infinity() : s;
        bounds[static_cast<std::size_t>(k) + 1] = std::numeric_limits<double>::infinity();
    }
    if (k < 0) {
        return; // nothing on this line
    }
    int j = 0;
    for (int q = 0; q < n; ++q) {
        while (bounds[static_cast<std::size_t>(j) + 1] < q) {
            ++j;
        }
        const int r = roots[static_cast<std::size_t>(j)];
        out[static_cast<std::size_t>(q)] =
            (q - r) * static_cast<double>(q - r) + f[static_cast<std::size_t>(r)];
    }
    f = std::move(out);
}

/// Squared distance from every pixel to the nearest set pixel of `mask` (infinite when none is set).
std::vector<double> squaredDistanceTo(glm::ivec2 size, const std::vector<std::uint8_t>& mask) {
    std::vector<double> distance(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i) {
        distance[i] = mask[i] ? 0.0 : std::numeric_limits<double>::infinity();
    }
    std::vector<double> line;
    for (int x = 0; x < size.x; ++x) {
        line.resize(static_cast<std::size_t>(size.y));
        for (int y = 0; y < size.y; ++y) {
            line[static_cast<std::size_t>(y)] = distance[pixelIndex(size, x, y)];
        }
        distanceTransform1d(line);
        for (int y = 0; y < size.y; ++y) {
            distance[pixelIndex(size, x, y)] = line[static_cast<std::size_t>(y)];
        }
    }
    for (int y = 0; y < size.y; ++y) {
        line.assign(distance.begin() + static_cast<std::ptrdiff_t>(pixelIndex(size, 0, y)),
                    distance.begin() + static_cast<std::ptrdiff_t>(pixelIndex(size, 0, y) +
                                                                   static_cast<std::size_t>(size.x)));
        distanceTransform1d(line);
        std::copy(line.begin(), line.end(),
                  distance.begin() + static_cast<std::ptrdiff_t>(pixelIndex(size, 0, y)));
    }
    return distance;
}

EdgeDistances distancesFrom(glm::ivec2 size, const std::vector<std::uint8_t>& from,
                            const std::vector<std::uint8_t>& to) {
    const std::vector<double> squared = squaredDistanceTo(size, to);
    const double diagonal = std::hypot(static_cast<double>(size.x), static_cast<double>(size.y));
    std::vector<double> distances;
    for (std::size_t i = 0; i < from.size(); ++i) {
        if (from[i]) {
            distances.push_back(std::isfinite(squared[i]) ? std::sqrt(squared[i]) : diagonal);
        }
    }
    EdgeDistances result;
    result.count = distances.size();
    if (distances.empty()) {
        return result;
    }
    double sum = 0.0;
    for (const double d : distances) {
        sum += d;
    }
    result.mean = sum / static_cast<double>(distances.size());
    // Nearest-rank percentile: the smallest distance at least 95 % of the edge pixels do not exceed.
    const std::size_t rank =
        static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(distances.size())));
    std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(rank - 1),
                     distances.end());
    result.percentile95 = distances[rank - 1];
    return result;
}
} // namespace

float LightPlane::texelsBetween(std::size_t i, std::size_t j) const {
    const float texel = texelSizes[i];
    if (!(texel > 0.0f)) {
        return std::numeric_limits<float>::infinity();
    }
    if (directional) {
        const glm::vec3 offset = positions[j] - positions[i];
        return glm::length(offset - glm::dot(offset, direction) * direction) / texel;
    }
    // Both points seen from the light: j's offset from i's ray, scaled back to i's distance.
    const glm::vec3 toI = positions[i] - position;
    const float distance = glm::length(toI);
    if (!(distance > 0.0f)) {
        return std::numeric_limits<float>::infinity();
    }
    const glm::vec3 ray = toI / distance;
    const glm::vec3 toJ = positions[j] - position;
    const float along = glm::dot(toJ, ray);
    if (!(along > 0.0f)) {
        return std::numeric_limits<float>::infinity();
    }
    return glm::length(toJ - along * ray) * (distance / along) / texel;
}

std::vector<PixelClass> classify(glm::ivec2 size, std::span<const float> truth,
                                 std::span<const Surface> surfaces, const LightPlane& plane, float bandTexels,
                                 int windowPixels) {
    const std::size_t count = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
    const auto lit = [&](std::size_t j) { return surfaces[j] == Surface::Receiver && truth[j] >= 0.5f; };
    const auto dark = [&](std::size_t j) {
        return surfaces[j] == Surface::FacingAway || (surfaces[j] == Surface::Receiver && truth[j] < 0.5f);
    };
    // Which pixels have a lit and a dark one anywhere in their window (a square-window test done separably:
    // first along each row, then down the columns); only those are searched pixel by pixel.
    std::vector<std::uint8_t> nearLit(count, 0);
    std::vector<std::uint8_t> nearDark(count, 0);
    std::vector<std::uint8_t> rowLit(count, 0);
    std::vector<std::uint8_t> rowDark(count, 0);
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            for (int nx = std::max(x - windowPixels, 0); nx <= std::min(x + windowPixels, size.x - 1); ++nx) {
                const std::size_t j = pixelIndex(size, nx, y);
                rowLit[pixelIndex(size, x, y)] |= static_cast<std::uint8_t>(lit(j));
                rowDark[pixelIndex(size, x, y)] |= static_cast<std::uint8_t>(dark(j));
            }
        }
    }
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            for (int ny = std::max(y - windowPixels, 0); ny <= std::min(y + windowPixels, size.y - 1); ++ny) {
                nearLit[pixelIndex(size, x, y)] |= rowLit[pixelIndex(size, x, ny)];
                nearDark[pixelIndex(size, x, y)] |= rowDark[pixelIndex(size, x, ny)];
            }
        }
    }
    // Whether a pixel of the other truth lies within the band of receiver (x, y): rings outwards, so that
    // most band pixels stop at their first ring.
    const auto inBand = [&](int x, int y) {
        const std::size_t i = pixelIndex(size, x, y);
        const bool iLit = lit(i);
        for (int ring = 1; ring <= windowPixels; ++ring) {
            for (int dy = -ring; dy <= ring; ++dy) {
                const int ny = y + dy;
                if (ny < 0 || ny >= size.y) {
                    continue;
                }
                const bool edgeRow = dy == -ring || dy == ring;
                for (int dx = -ring; dx <= ring; dx += edgeRow ? 1 : 2 * ring) {
                    const int nx = x + dx;
                    if (nx < 0 || nx >= size.x) {
                        continue;
                    }
                    const std::size_t j = pixelIndex(size, nx, ny);
                    if ((iLit ? dark(j) : lit(j)) && (ring == 1 || plane.texelsBetween(i, j) <= bandTexels)) {
                        return true;
                    }
                }
            }
        }
        return false;
    };
    std::vector<PixelClass> classes(count, PixelClass::Ignored);
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = pixelIndex(size, x, y);
            if (surfaces[i] != Surface::Receiver) {
                continue;
            }
            const bool candidate = nearLit[i] && nearDark[i];
            const bool edgeNearby = !plane.edgeWithinBand.empty() && plane.edgeWithinBand[i];
            classes[i] = edgeNearby || (candidate && inBand(x, y)) ? PixelClass::Band
                         : lit(i)                                  ? PixelClass::Lit
                                                                   : PixelClass::Shadowed;
        }
    }
    return classes;
}

std::vector<PixelClass> classifyByScreenBand(glm::ivec2 size, std::span<const float> truth,
                                             std::span<const Surface> surfaces, float bandPixels,
                                             std::span<const std::uint8_t> edgeWithinBand) {
    const auto lit = [&](std::size_t j) { return surfaces[j] == Surface::Receiver && truth[j] >= 0.5f; };
    const auto dark = [&](std::size_t j) {
        return surfaces[j] == Surface::FacingAway || (surfaces[j] == Surface::Receiver && truth[j] < 0.5f);
    };
    // The disc of the band's reach, without its centre; the 8 neighbours even for a band under 1.5 pixels.
    const int reach = std::max(static_cast<int>(std::floor(bandPixels)), 1);
    std::vector<glm::ivec2> disc;
    for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
            const bool neighbour = std::max(std::abs(dx), std::abs(dy)) == 1;
            if ((dx != 0 || dy != 0) &&
                (neighbour || static_cast<float>(dx * dx + dy * dy) <= bandPixels * bandPixels)) {
                disc.emplace_back(dx, dy);
            }
        }
    }
    std::vector<PixelClass> classes(truth.size(), PixelClass::Ignored);
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = pixelIndex(size, x, y);
            if (surfaces[i] != Surface::Receiver) {
                continue;
            }
            const bool iLit = lit(i);
            bool band = !edgeWithinBand.empty() && edgeWithinBand[i];
            for (std::size_t k = 0; k < disc.size() && !band; ++k) {
                const int nx = x + disc[k].x;
                const int ny = y + disc[k].y;
                if (nx >= 0 && ny >= 0 && nx < size.x && ny < size.y) {
                    const std::size_t j = pixelIndex(size, nx, ny);
                    band = iLit ? dark(j) : lit(j);
                }
            }
            classes[i] = band ? PixelClass::Band : iLit ? PixelClass::Lit : PixelClass::Shadowed;
        }
    }
    return classes;
}

SeamErrors seamErrors(std::span<const PixelClass> classes, std::span<const float> truth,
                      std::span<const float> visibility, std::span<const float> pageEdges,
                      float reachTexels) {
    SeamErrors seams;
    std::size_t seamErrors = 0;
    std::size_t interiorErrors = 0;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        if ((classes[i] != PixelClass::Lit && classes[i] != PixelClass::Shadowed) ||
            !(pageEdges[i] >= 0.0f)) {
            continue;
        }
        const bool wrong = std::abs(visibility[i] - truth[i]) > 0.5f;
        if (pageEdges[i] < reachTexels) {
            ++seams.pixels;
            seamErrors += wrong;
        } else {
            ++seams.interiorPixels;
            interiorErrors += wrong;
        }
    }
    const auto rate = [](std::size_t errors, std::size_t pixels) {
        return pixels ? static_cast<double>(errors) / static_cast<double>(pixels) : 0.0;
    };
    seams.errorRate = rate(seamErrors, seams.pixels);
    seams.interiorErrorRate = rate(interiorErrors, seams.interiorPixels);
    return seams;
}

TexelDensity texelDensity(std::span<const PixelClass> classes, std::span<const float> truth,
                          std::span<const float> footprints) {
    std::vector<float> values;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const bool lit =
            (classes[i] == PixelClass::Lit || classes[i] == PixelClass::Band) && truth[i] >= 0.5f;
        if (lit && footprints[i] >= 0.0f) {
            values.push_back(footprints[i]);
        }
    }
    TexelDensity density;
    density.pixels = values.size();
    if (values.empty()) {
        return density;
    }
    density.atMostOnePixel =
        static_cast<double>(std::count_if(values.begin(), values.end(), [](float m) { return m <= 1.0f; })) /
        static_cast<double>(values.size());
    const auto nearestRank = [&](double fraction) {
        const std::size_t rank = std::max<std::size_t>(
            static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size()))), 1);
        std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank - 1),
                         values.end());
        return static_cast<double>(values[rank - 1]);
    };
    density.median = nearestRank(0.5);
    density.percentile99 = nearestRank(0.99);
    density.percentile999 = nearestRank(0.999);
    return density;
}

ShadowMetrics computeMetrics(std::span<const PixelClass> classes, std::span<const float> truth,
                             std::span<const float> visibility, std::span<const std::uint8_t> concave) {
    ShadowMetrics m;
    double darkeningSum = 0.0;
    double concaveSum = 0.0;
    double absoluteSum = 0.0;
    double squareSum = 0.0;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        if (classes[i] == PixelClass::Ignored) {
            continue;
        }
        ++m.receivers;
        const double error = static_cast<double>(visibility[i]) - static_cast<double>(truth[i]);
        absoluteSum += std::abs(error);
        squareSum += error * error;
        switch (classes[i]) {
        case PixelClass::Band:
            ++m.band;
            break;
        case PixelClass::Lit:
            ++m.lit;
            m.acne += visibility[i] < 0.5f;
            darkeningSum += 1.0 - static_cast<double>(visibility[i]);
            if (!concave.empty() && concave[i]) {
                ++m.concave;
                concaveSum += 1.0 - static_cast<double>(visibility[i]);
            }
            break;
        case PixelClass::Shadowed:
            ++m.shadowed;
            m.leak += visibility[i] > 0.5f;
            break;
        case PixelClass::Ignored:
            break;
        }
    }
    auto ratio = [](double a, std::size_t b) { return b ? a / static_cast<double>(b) : 0.0; };
    m.acneRate = ratio(static_cast<double>(m.acne), m.lit);
    m.leakRate = ratio(static_cast<double>(m.leak), m.shadowed);
    m.darkening = ratio(darkeningSum, m.lit);
    m.concaveDarkening = ratio(concaveSum, m.concave);
    m.meanAbsoluteError = ratio(absoluteSum, m.receivers);
    m.rootMeanSquareError = std::sqrt(ratio(squareSum, m.receivers));
    return m;
}

std::vector<std::uint8_t> edgePixels(glm::ivec2 size, std::span<const PixelClass> classes,
                                     std::span<const float> visibility) {
    std::vector<std::uint8_t> edges(classes.size(), 0);
    const auto litReceiver = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= size.x || y >= size.y) {
            return false;
        }
        const std::size_t j = pixelIndex(size, x, y);
        return classes[j] != PixelClass::Ignored && visibility[j] >= 0.5f;
    };
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = pixelIndex(size, x, y);
            if (classes[i] == PixelClass::Ignored || visibility[i] >= 0.5f) {
                continue;
            }
            edges[i] = litReceiver(x - 1, y) || litReceiver(x + 1, y) || litReceiver(x, y - 1) ||
                       litReceiver(x, y + 1);
        }
    }
    return edges;
}

EdgePlacement edgePlacement(glm::ivec2 size, std::span<const PixelClass> classes,
                            std::span<const float> truth, std::span<const float> visibility) {
    const std::vector<std::uint8_t> trueEdges = edgePixels(size, classes, truth);
    const std::vector<std::uint8_t> renderedEdges = edgePixels(size, classes, visibility);
    return {distancesFrom(size, trueEdges, renderedEdges), distancesFrom(size, renderedEdges, trueEdges)};
}

std::vector<std::uint8_t> concaveMask(glm::ivec2 size, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals,
                                      std::span<const std::uint8_t> covered, float threshold) {
    std::vector<std::uint8_t> mask(positions.size(), 0);
    for (int y = 1; y + 1 < size.y; ++y) {
        for (int x = 1; x + 1 < size.x; ++x) {
            const std::size_t i = pixelIndex(size, x, y);
            if (!covered[i]) {
                continue;
            }
            for (const glm::ivec2 axis : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
                const std::size_t a = pixelIndex(size, x - axis.x, y - axis.y);
                const std::size_t b = pixelIndex(size, x + axis.x, y + axis.y);
                if (!covered[a] || !covered[b]) {
                    continue;
                }
                const glm::vec3 dp = positions[b] - positions[a];
                const float length2 = glm::dot(dp, dp);
                // Second fundamental form along dp: negative where the surface curves towards its normal
                // side.
                if (length2 > 0.0f && glm::dot(normals[b] - normals[a], dp) < -threshold * length2) {
                    mask[i] = 1;
                }
            }
        }
    }
    return mask;
}

engine::Image classificationImage(glm::ivec2 size, std::span<const PixelClass> classes,
                                  std::span<const float> visibility) {
    engine::Image image;
    image.size = size;
    image.pixels.reserve(classes.size() * 4);
    for (std::size_t i = 0; i < classes.size(); ++i) {
        glm::u8vec3 color(0);
        switch (classes[i]) {
        case PixelClass::Ignored:
            color = {0, 0, 0};
            break;
        case PixelClass::Band:
            color = {150, 140, 90};
            break;
        case PixelClass::Lit:
            color = visibility[i] < 0.5f ? glm::u8vec3(230, 40, 40) : glm::u8vec3(235, 235, 235);
            break;
        case PixelClass::Shadowed:
            color = visibility[i] > 0.5f ? glm::u8vec3(40, 80, 240) : glm::u8vec3(70, 70, 70);
            break;
        }
        image.pixels.insert(image.pixels.end(), {color.r, color.g, color.b, 255});
    }
    return image;
}

engine::Image errorHeatMap(glm::ivec2 size, std::span<const PixelClass> classes, std::span<const float> truth,
                           std::span<const float> visibility) {
    engine::Image image;
    image.size = size;
    image.pixels.reserve(classes.size() * 4);
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const float e = classes[i] == PixelClass::Ignored
                            ? 0.0f
                            : std::clamp(std::abs(visibility[i] - truth[i]), 0.0f, 1.0f);
        // Black → red → yellow → white as the error goes 0 → 1.
        const auto channel = [](float v) {
            return static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f)));
        };
        image.pixels.insert(image.pixels.end(),
                            {channel(3.0f * e), channel(3.0f * e - 1.0f), channel(3.0f * e - 2.0f), 255});
    }
    return image;
}

} // namespace shadowbench
