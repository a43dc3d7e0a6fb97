#include <contactsheet/ContactSheet.h>

#include <engine/Error.h>

#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace contactsheet {

struct Font::Face {
    std::vector<unsigned char> data;
    stbtt_fontinfo info{};
    float scale = 1.0f;
    int ascent = 0;
};

namespace {

/// The codepoint drawn for byte `c`: ASCII as is, anything else as '?'.
int codepoint(char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte >= 0x20 && byte < 0x7f ? byte : '?';
}

} // namespace

Font::Font(const std::filesystem::path& path, float pixelHeight) : face_(std::make_unique<Face>()) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw engine::IoError(path.string() + ": cannot read the font" +
                              (path == kDefaultFont
                                   ? " (Debian package fonts-dejavu-core; tools/setup.sh installs it)"
                                   : std::string()));
    }
    face_->data.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    const int offset = stbtt_GetFontOffsetForIndex(face_->data.data(), 0);
    if (face_->data.size() < 12 || offset < 0 || !stbtt_InitFont(&face_->info, face_->data.data(), offset)) {
        throw engine::Error(path.string() + ": not a TrueType font");
    }
    face_->scale = stbtt_ScaleForPixelHeight(&face_->info, pixelHeight);
    int descent = 0;
    int lineGap = 0;
    stbtt_GetFontVMetrics(&face_->info, &face_->ascent, &descent, &lineGap);
    lineHeight_ =
        static_cast<int>(std::ceil(static_cast<float>(face_->ascent - descent + lineGap) * face_->scale));
}

Font::~Font() = default;

int Font::textWidth(std::string_view text) const {
    float width = 0.0f;
    for (std::size_t i = 0; i < text.size(); ++i) {
        int advance = 0;
        int bearing = 0;
        stbtt_GetCodepointHMetrics(&face_->info, codepoint(text[i]), &advance, &bearing);
        width += static_cast<float>(advance) * face_->scale;
        if (i + 1 < text.size()) {
            width += static_cast<float>(stbtt_GetCodepointKernAdvance(&face_->info, codepoint(text[i]),
                                                                      codepoint(text[i + 1]))) *
                     face_->scale;
        }
    }
    return static_cast<int>(std::ceil(width));
}

void Font::draw(engine::Image& image, glm::ivec2 topLeft, std::string_view text, glm::u8vec3 color,
                int maxWidth) const {
    const int right = maxWidth > image.size.x - topLeft.x ? image.size.x : topLeft.x + maxWidth;
    const int baseline =
        topLeft.y + static_cast<int>(std::round(static_cast<float>(face_->ascent) * face_->scale));
    float x = static_cast<float>(topLeft.x);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const int glyph = codepoint(text[i]);
        int width = 0;
        int height = 0;
        int offsetX = 0;
        int offsetY = 0;
        unsigned char* coverage = stbtt_GetCodepointBitmap(&face_->info, face_->scale, face_->scale, glyph,
                                                           &width, &height, &offsetX, &offsetY);
        const int left = static_cast<int>(std::round(x)) + offsetX;
        for (int gy = 0; gy < height; ++gy) {
            for (int gx = 0; gx < width; ++gx) {
                const int px = left + gx;
                const int py = baseline + offsetY + gy;
                if (px < 0 || py < 0 || px >= right || py >= image.size.y) {
                    continue;
                }
                const float alpha = static_cast<float>(coverage[gy * width + gx]) / 255.0f;
                std::uint8_t* pixel =
                    &image.pixels[(static_cast<std::size_t>(py) * static_cast<std::size_t>(image.size.x) +
                                   static_cast<std::size_t>(px)) *
                                  4];
                for (int c = 0; c < 3; ++c) {
                    pixel[c] =
                        static_cast<std::uint8_t>(std::lround(static_cast<float>(pixel[c]) * (1.0f - alpha) +
                                                              static_cast<float>(color[c]) * alpha));
                }
            }
        }
        stbtt_FreeBitmap(coverage, nullptr);
        int advance = 0;
        int bearing = 0;
        stbtt_GetCodepointHMetrics(&face_->info, glyph, &advance, &bearing);
        x += static_cast<float>(advance) * face_->scale;
        if (i + 1 < text.size()) {
            x += static_cast<float>(
                     stbtt_GetCodepointKernAdvance(&face_->info, glyph, codepoint(text[i + 1]))) *
                 face_->scale;
        }
    }
}

glm::ivec2 SheetGeometry::tileOrigin(std::size_t index) const {
    const int column = static_cast<int>(index) % columns;
    const int row = static_cast<int>(index) / columns;
    return {padding + column * (tileSize.x + padding),
            titleHeight + padding + row * (tileSize.y + labelHeight + padding)};
}

SheetGeometry sheetGeometry(std::size_t tileCount, glm::ivec2 tileSize, std::size_t labelLines,
                            int lineHeight, const SheetLayout& layout) {
    SheetGeometry geometry;
    geometry.columns = std::clamp(layout.columns, 1, static_cast<int>(std::max<std::size_t>(tileCount, 1)));
    geometry.padding = layout.padding;
    geometry.tileSize = tileSize;
    geometry.titleHeight = layout.padding + lineHeight;
    geometry.labelHeight = static_cast<int>(labelLines) * lineHeight + layout.padding / 2;
    const int rows = (static_cast<int>(tileCount) + geometry.columns - 1) / geometry.columns;
    geometry.sheetSize = {layout.padding + geometry.columns * (tileSize.x + layout.padding),
                          geometry.titleHeight + layout.padding +
                              rows * (tileSize.y + geometry.labelHeight + layout.padding)};
    return geometry;
}

engine::Image composeSheet(const std::string& title, const std::vector<Tile>& tiles, const Font& font,
                           const SheetLayout& layout) {
    if (tiles.empty()) {
        throw engine::Error("contact sheet: no images");
    }
    const glm::ivec2 tileSize = tiles.front().image.size;
    std::size_t labelLines = 0;
    for (const Tile& tile : tiles) {
        if (tile.image.size != tileSize) {
            throw engine::Error("contact sheet: images of different sizes (" + std::to_string(tileSize.x) +
                                "x" + std::to_string(tileSize.y) + " and " +
                                std::to_string(tile.image.size.x) + "x" + std::to_string(tile.image.size.y) +
                                ")");
        }
        labelLines = std::max(labelLines, tile.label.size());
    }
    const SheetGeometry geometry =
        sheetGeometry(tiles.size(), tileSize, labelLines, font.lineHeight(), layout);
    engine::Image sheet;
    sheet.size = geometry.sheetSize;
    sheet.pixels.resize(static_cast<std::size_t>(sheet.size.x) * static_cast<std::size_t>(sheet.size.y) * 4);
    for (std::size_t i = 0; i < sheet.pixels.size(); i += 4) {
        sheet.pixels[i] = layout.background.r;
        sheet.pixels[i + 1] = layout.background.g;
        sheet.pixels[i + 2] = layout.background.b;
        sheet.pixels[i + 3] = 255;
    }
    font.draw(sheet, {layout.padding, layout.padding / 2}, title, layout.text);
    for (std::size_t n = 0; n < tiles.size(); ++n) {
        const glm::ivec2 origin = geometry.tileOrigin(n);
        const std::size_t rowBytes = static_cast<std::size_t>(tileSize.x) * 4;
        for (int y = 0; y < tileSize.y; ++y) {
            std::copy_n(tiles[n].image.pixels.begin() +
                            static_cast<std::ptrdiff_t>(rowBytes * static_cast<std::size_t>(y)),
                        rowBytes,
                        sheet.pixels.begin() +
                            static_cast<std::ptrdiff_t>((static_cast<std::size_t>(origin.y + y) *
                                                             static_cast<std::size_t>(sheet.size.x) +
                                                         static_cast<std::size_t>(origin.x)) *
                                                        4));
        }
        for (std::size_t line = 0; line < tiles[n].label.size(); ++line) {
            font.draw(sheet, {origin.x, origin.y + tileSize.y + static_cast<int>(line) * font.lineHeight()},
                      tiles[n].label[line], layout.text, tileSize.x);
        }
    }
    return sheet;
}

std::string percent(double fraction) {
    const double value = 100.0 * fraction;
    if (value == 0.0) {
        return "0 %";
    }
    // Two significant digits below 1 %, down to 0.0001 %: on a view every technique nearly meets, two pixels
    // of acne must read apart from twenty, and from none. Four decimals at most keep the three rates within a
    // 320-pixel tile (one pixel of 640x480 is 0.0003 %).
    if (std::abs(value) < 0.00005) {
        return "<0.0001 %";
    }
    const int decimals =
        std::abs(value) >= 1.0
            ? 2
            : std::clamp(1 - static_cast<int>(std::floor(std::log10(std::abs(value)))), 2, 4);
    char text[32];
    std::snprintf(text, sizeof text, "%.*f %%", decimals, value);
    return text;
}

namespace {

/// The speed and edge-placement line both sheets share: what a technique costs beside how far its edges
/// stray.
std::string timeAndEdges(const Scores& scores) {
    char frame[32] = "frame not timed";
    if (scores.frameMs >= 0.0) {
        std::snprintf(frame, sizeof frame, "frame %.1f ms", scores.frameMs);
    }
    char edges[64];
    std::snprintf(edges, sizeof edges, "  edge p95 %.1f / %.1f px", scores.edgeTrueToDrawnP95,
                  scores.edgeDrawnToTrueP95);
    return std::string(frame) + edges;
}

} // namespace

std::vector<std::string> shadedLabel(const std::string& name, const Scores& scores) {
    return {name,
            "acne " + percent(scores.acne) + "  leak " + percent(scores.leak) + "  darkening " +
                percent(scores.darkening),
            timeAndEdges(scores)};
}

std::vector<std::string> errorLabel(const std::string& name, const Scores& scores) {
    return {name, "acne (red) " + percent(scores.acne) + "  leak (blue) " + percent(scores.leak),
            timeAndEdges(scores)};
}

engine::Image downsample(const engine::Image& image, int factor) {
    if (factor < 1 || factor > image.size.x || factor > image.size.y) {
        throw engine::Error("downsample: factor " + std::to_string(factor) + " for a " +
                            std::to_string(image.size.x) + "x" + std::to_string(image.size.y) + " image");
    }
    engine::Image small;
    small.size = image.size / factor;
    small.pixels.resize(static_cast<std::size_t>(small.size.x) * static_cast<std::size_t>(small.size.y) * 4);
    for (int y = 0; y < small.size.y; ++y) {
        for (int x = 0; x < small.size.x; ++x) {
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int dy = 0; dy < factor; ++dy) {
                    for (int dx = 0; dx < factor; ++dx) {
                        sum += image.at(x * factor + dx, y * factor + dy)[c];
                    }
                }
                small.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(small.size.x) +
                              static_cast<std::size_t>(x)) *
                                 4 +
                             static_cast<std::size_t>(c)] =
                    static_cast<std::uint8_t>((sum + factor * factor / 2) / (factor * factor));
            }
        }
    }
    return small;
}

} // namespace contactsheet
