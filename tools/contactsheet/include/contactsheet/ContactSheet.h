#pragma once

#include <engine/Image.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace contactsheet {

/// @brief The font labels are set in unless --font says otherwise (Debian's fonts-dejavu-core).
inline const std::filesystem::path kDefaultFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// @brief A TrueType font rasterised by stb_truetype at one pixel height, for ASCII labels (other bytes are
/// drawn as '?').
class Font {
public:
    /// @brief Loads `path`. Throws engine::IoError naming the path when it cannot be read (a missing font
    /// says which package provides the default), engine::Error when it is not a TrueType font.
    Font(const std::filesystem::path& path, float pixelHeight);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    /// @brief Baseline-to-baseline distance in pixels.
    [[nodiscard]] int lineHeight() const { return lineHeight_; }
    /// @brief Advance width of `text` in pixels, kerning included.
    [[nodiscard]] int textWidth(std::string_view text) const;
    /// @brief Blends `text` onto `image` in `color` by glyph coverage, the top of its line at `topLeft`;
    /// clipped to the image and to `maxWidth` pixels right of `topLeft.x`.
    void draw(engine::Image& image, glm::ivec2 topLeft, std::string_view text, glm::u8vec3 color,
              int maxWidth = std::numeric_limits<int>::max()) const;

private:
    struct Face;
    std::unique_ptr<Face> face_;
    int lineHeight_ = 0;
};

/// @brief One image of a sheet with the lines of text set under it.
struct Tile {
    engine::Image image;
    std::vector<std::string> label;
};

/// @brief How a sheet is laid out: tiles in rows of `columns`, `padding` pixels around and between tiles.
struct SheetLayout {
    int columns = 4;
    int padding = 8;
    glm::u8vec3 background{28, 28, 32};
    glm::u8vec3 text{235, 235, 235};
};

/// @brief Where things sit on a sheet of `tileCount` tiles of `tileSize` with `labelLines` lines under each,
/// a title line above them all.
struct SheetGeometry {
    glm::ivec2 sheetSize{0};
    int titleHeight = 0;
    int labelHeight = 0;
    int columns = 1;
    int padding = 0;
    glm::ivec2 tileSize{0};

    /// @brief Top-left pixel of tile `index`'s image; its label starts right under it.
    [[nodiscard]] glm::ivec2 tileOrigin(std::size_t index) const;
};
SheetGeometry sheetGeometry(std::size_t tileCount, glm::ivec2 tileSize, std::size_t labelLines,
                            int lineHeight, const SheetLayout& layout);

/// @brief `title` above `tiles` (all of one size) with their labels, each label clipped to its tile's width.
/// Throws engine::Error when there are no tiles or their sizes differ.
engine::Image composeSheet(const std::string& title, const std::vector<Tile>& tiles, const Font& font,
                           const SheetLayout& layout);

/// @brief What the labels say of one configuration of a bench run, as its results.json row has it.
struct Scores {
    double acne = 0.0;      ///< fraction of lit receivers drawn shadowed
    double leak = 0.0;      ///< fraction of shadowed receivers drawn lit
    double darkening = 0.0; ///< mean visibility lost over lit receivers
    double frameMs = -1.0;  ///< median whole frame; negative when the run was not timed
    /// Pixels from a true shadow edge to the nearest drawn one, 95th percentile (edges missed or moved).
    double edgeTrueToDrawnP95 = 0.0;
    /// Pixels from a drawn shadow edge to the nearest true one, 95th percentile (edges that are not there).
    double edgeDrawnToTrueP95 = 0.0;
};

/// @brief `fraction` as a percentage: two decimals from 1 % up ("12.50 %"), two significant digits below
/// with four decimals at most ("0.38 %", "0.0014 %", "0.0003 %"), "<0.0001 %" below that, "0 %" for none.
std::string percent(double fraction);
/// @brief The label under a configuration's shaded frame: `name`; acne, leak and darkening; frame time and
/// edge p95 both ways ("frame 12.3 ms  edge p95 1.0 / 4.1 px", or "frame not timed ...").
std::vector<std::string> shadedLabel(const std::string& name, const Scores& scores);
/// @brief The label under a configuration's error classes: `name`; acne (red) and leak (blue); the same frame
/// time and edge line as shadedLabel.
std::vector<std::string> errorLabel(const std::string& name, const Scores& scores);

/// @brief `image` at 1/`factor` of its size (each pixel the mean of a factor × factor block; a partial block
/// at the right or bottom edge is dropped). Throws engine::Error for a factor below 1 or above the size.
engine::Image downsample(const engine::Image& image, int factor);

} // namespace contactsheet
