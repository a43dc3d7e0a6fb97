// gs-contactsheet's layout and labels on synthetic images: tiles where the geometry says, labels drawn in the
// label band under their tile and nowhere else, the labels' text (accuracy, frame time, edge p95) fitting the
// demo's tiles, box downsampling, and clear errors for a missing or bogus font.
#include <contactsheet/ContactSheet.h>

#include <engine/Error.h>

#include <gtest/gtest.h>

#include <fstream>

namespace {

using contactsheet::Font;
using contactsheet::kDefaultFont;

engine::Image solid(glm::ivec2 size, glm::u8vec4 colour) {
    engine::Image image;
    image.size = size;
    for (int i = 0; i < size.x * size.y; ++i) {
        image.pixels.insert(image.pixels.end(), {colour.r, colour.g, colour.b, colour.a});
    }
    return image;
}

/// Pixels in [from, to) that are not `background`.
int marked(const engine::Image& image, glm::ivec2 from, glm::ivec2 to, glm::u8vec4 background) {
    int count = 0;
    for (int y = from.y; y < to.y; ++y) {
        for (int x = from.x; x < to.x; ++x) {
            count += image.at(x, y) != background;
        }
    }
    return count;
}

TEST(ContactSheetTest, MissingFontNamesThePathAndThePackage) {
    try {
        const Font font("/nonexistent/font.ttf", 14.0f);
        FAIL() << "no error";
    } catch (const engine::IoError& error) {
        EXPECT_STREQ(error.what(), "/nonexistent/font.ttf: cannot read the font");
    }
    const std::filesystem::path notAFont =
        std::filesystem::temp_directory_path() / "gs-contactsheet-not-a-font.ttf";
    std::ofstream(notAFont) << "plain text, not a font";
    EXPECT_THROW(Font(notAFont, 14.0f), engine::Error);
}

TEST(ContactSheetTest, TextIsDrawnWithinItsLineAndWidth) {
    const Font font(kDefaultFont, 14.0f);
    EXPECT_GE(font.lineHeight(), 14);
    EXPECT_LE(font.lineHeight(), 20);
    EXPECT_GT(font.textWidth("WWWW"), font.textWidth("iiii"));
    EXPECT_EQ(font.textWidth(""), 0);

    const glm::u8vec4 black{0, 0, 0, 255};
    engine::Image image = solid({120, 40}, black);
    const glm::ivec2 at{10, 8};
    font.draw(image, at, "acne 1.5 %", {255, 255, 255});
    const glm::ivec2 end = at + glm::ivec2(font.textWidth("acne 1.5 %") + 1, font.lineHeight());
    const int inside = marked(image, at, end, black);
    EXPECT_GT(inside, 40); // glyph coverage, not a speck
    EXPECT_EQ(marked(image, {0, 0}, image.size, black), inside) << "ink outside the text's box";
    // Clipped to the width it is given, and to the image when it runs off it.
    engine::Image clipped = solid({120, 40}, black);
    font.draw(clipped, at, "acne 1.5 %", {255, 255, 255}, 12);
    EXPECT_GT(marked(clipped, at, at + glm::ivec2(12, font.lineHeight()), black), 5);
    EXPECT_EQ(marked(clipped, {at.x + 12, 0}, clipped.size, black), 0);
    font.draw(image, {100, 30}, "off the edge", {255, 255, 255});
}

TEST(ContactSheetTest, TilesAndLabelsSitWhereTheGeometrySays) {
    const Font font(kDefaultFont, 12.0f);
    const glm::ivec2 tileSize{40, 30};
    const std::vector<glm::u8vec4> colours{{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
    std::vector<contactsheet::Tile> tiles;
    for (const glm::u8vec4& colour : colours) {
        tiles.push_back({solid(tileSize, colour), {"name", "acne 0.00 %"}});
    }
    tiles[2].label.clear(); // an unlabelled tile leaves its label band empty
    contactsheet::SheetLayout layout;
    layout.columns = 2;
    const engine::Image sheet = contactsheet::composeSheet("title", tiles, font, layout);
    const contactsheet::SheetGeometry geometry =
        contactsheet::sheetGeometry(tiles.size(), tileSize, 2, font.lineHeight(), layout);
    ASSERT_EQ(sheet.size, geometry.sheetSize);
    EXPECT_EQ(geometry.sheetSize.x, 3 * layout.padding + 2 * tileSize.x);
    const glm::u8vec4 background{layout.background, 255};
    for (std::size_t n = 0; n < tiles.size(); ++n) {
        const glm::ivec2 origin = geometry.tileOrigin(n);
        EXPECT_EQ(sheet.at(origin.x, origin.y), colours[n]) << "tile " << n;
        EXPECT_EQ(sheet.at(origin.x + tileSize.x - 1, origin.y + tileSize.y - 1), colours[n]) << "tile " << n;
        EXPECT_EQ(sheet.at(origin.x + tileSize.x, origin.y), background) << "tile " << n << " overran";
        const glm::ivec2 labelFrom{origin.x, origin.y + tileSize.y};
        const int ink =
            marked(sheet, labelFrom, labelFrom + glm::ivec2(tileSize.x, geometry.labelHeight), background);
        EXPECT_EQ(ink > 20, n != 2) << "label band of tile " << n;
    }
    EXPECT_EQ(geometry.tileOrigin(2).x, geometry.tileOrigin(0).x); // third tile starts the second row
    EXPECT_GT(marked(sheet, {0, 0}, {sheet.size.x, geometry.titleHeight}, background), 20); // the title

    tiles[1].image = solid({41, 30}, colours[1]);
    EXPECT_THROW(contactsheet::composeSheet("t", tiles, font, layout), engine::Error);
    EXPECT_THROW(contactsheet::composeSheet("t", {}, font, layout), engine::Error);
}

TEST(ContactSheetTest, LabelsCarryAccuracyFrameTimeAndEdgesBothWays) {
    const contactsheet::Scores scores{0.0004, 0.0791, 0.00383, 36.94, 8.26, 4.0};
    EXPECT_EQ(contactsheet::shadedLabel("slope-scaled", scores),
              (std::vector<std::string>{"slope-scaled", "acne 0.040 %  leak 7.91 %  darkening 0.38 %",
                                        "frame 36.9 ms  edge p95 8.3 / 4.0 px"}));
    EXPECT_EQ(contactsheet::errorLabel("slope-scaled", scores),
              (std::vector<std::string>{"slope-scaled", "acne (red) 0.040 %  leak (blue) 7.91 %",
                                        "frame 36.9 ms  edge p95 8.3 / 4.0 px"}));
    // gs-shadowbench --accuracy-only writes -1 for its times.
    contactsheet::Scores untimed = scores;
    untimed.frameMs = -1.0;
    EXPECT_EQ(contactsheet::shadedLabel("gsm", untimed).back(), "frame not timed  edge p95 8.3 / 4.0 px");
}

TEST(ContactSheetTest, SmallRatesKeepTwoSignificantDigits) {
    // Two pixels of acne among 140 000 receivers is not the same as none, nor as twenty.
    EXPECT_EQ(contactsheet::percent(2.0 / 140000.0), "0.0014 %");
    EXPECT_EQ(contactsheet::percent(20.0 / 140000.0), "0.014 %");
    EXPECT_EQ(contactsheet::percent(0.0), "0 %");
    EXPECT_EQ(contactsheet::percent(1.0 / (640.0 * 480.0)), "0.0003 %"); // one pixel of the demo's view
    EXPECT_EQ(contactsheet::percent(1e-7), "<0.0001 %");
    EXPECT_EQ(contactsheet::percent(0.00383), "0.38 %");
    EXPECT_EQ(contactsheet::percent(0.0999), "9.99 %");
    EXPECT_EQ(contactsheet::percent(1.0), "100.00 %");
}

TEST(ContactSheetTest, WidestLabelsFitTheDemosTiles) {
    // The demo's tiles: a 640x480 bench at --downsample 2, labels at the default 14 px.
    const Font font(kDefaultFont, 14.0f);
    // The longest numbers: whole rates, and one pixel among all 640x480 as receivers (0.0003 %).
    const double onePixel = 1.0 / (640.0 * 480.0);
    for (const contactsheet::Scores& worst :
         {contactsheet::Scores{1.0, 1.0, 1.0, 9999.9, 800.0, 800.0},
          contactsheet::Scores{onePixel, onePixel, onePixel, 9999.9, 800.0, 800.0}}) {
        for (const auto& label : {contactsheet::shadedLabel("pcf-gsm-quadratic", worst),
                                  contactsheet::errorLabel("pcf-gsm-quadratic", worst)}) {
            for (const std::string& line : label) {
                EXPECT_LE(font.textWidth(line), 320) << line;
            }
        }
    }
}

TEST(ContactSheetTest, DownsampleAveragesBlocks) {
    engine::Image image = solid({5, 4}, {0, 0, 0, 255});
    // Left 2x2 block: one white pixel of four; the fifth column is a partial block and is dropped.
    image.pixels[0] = image.pixels[1] = image.pixels[2] = 255;
    const engine::Image small = contactsheet::downsample(image, 2);
    ASSERT_EQ(small.size, glm::ivec2(2, 2));
    EXPECT_EQ(small.at(0, 0), glm::u8vec4(64, 64, 64, 255));
    EXPECT_EQ(small.at(1, 1), glm::u8vec4(0, 0, 0, 255));
    EXPECT_EQ(contactsheet::downsample(image, 1).pixels, image.pixels);
    EXPECT_THROW(contactsheet::downsample(image, 0), engine::Error);
    EXPECT_THROW(contactsheet::downsample(image, 5), engine::Error);
}

} // namespace
