// gs-contactsheet: labelled sheets of a gs-shadowbench run, for people comparing techniques by eye: every
// configuration's shaded frame with its acne, leak and darkening against the ray-traced truth, its frame time
// and how far its shadow edges stray (p95 both ways), and the truth's classes beside every configuration's
// error classes.
#include <contactsheet/ContactSheet.h>

#include <cli/OptionValues.h>
#include <engine/Error.h>
#include <engine/Image.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

namespace {

constexpr const char* kUsage = R"(usage: gs-contactsheet BENCH_DIR [options]
  BENCH_DIR        a gs-shadowbench --out folder: results.json, <scene>/<label>.png, <label>-classes.png
                   and <scene>/truth.png (OpenSceneGraph peer rows are left out)
  --scene NAME     the scene whose rows to show                    [the first in results.json]
  --out DIR        where contact-sheet.png and truth-sheet.png go  [BENCH_DIR]
  --font TTF       TrueType font of the labels                     [/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf]
  --font-size PX   label height in pixels, 6..72                   [14]
  --columns N      tiles per row, 1..64                            [5]
  --downsample N   tiles at 1/N of the bench's image size, 1..16   [1]
exit status: 0 written; 1 unreadable input or unwritable output; 2 bad options)";

struct Options {
    std::filesystem::path bench;
    std::optional<std::string> scene;
    std::optional<std::filesystem::path> out;
    std::filesystem::path font = contactsheet::kDefaultFont;
    int fontSize = 14;
    int columns = 5;
    int downsample = 1;
};

constexpr cli::Tool kTool{"gs-contactsheet", kUsage};

[[noreturn]] void usageError(const std::string& message) {
    kTool.fail(message);
}

Options parse(int argc, char** argv) {
    Options options;
    for (cli::ArgumentList arguments(argc, argv, kTool); arguments.next();) {
        const std::string arg = arguments.current();
        const auto value = [&] { return arguments.value(); };
        if (arg == "--scene") {
            options.scene = value();
        } else if (arg == "--out") {
            options.out = value();
        } else if (arg == "--font") {
            options.font = value();
        } else if (arg == "--font-size") {
            options.fontSize = cli::integerIn(arg, value(), 6, 72);
        } else if (arg == "--columns") {
            options.columns = cli::integerIn(arg, value(), 1, 64);
        } else if (arg == "--downsample") {
            options.downsample = cli::integerIn(arg, value(), 1, 16);
        } else if (arg.starts_with("--") || !options.bench.empty()) {
            usageError("unknown option '" + arg + "'");
        } else {
            options.bench = arg;
        }
    }
    if (options.bench.empty()) {
        usageError("no BENCH_DIR given");
    }
    return options;
}

/// One configuration of the bench run, as results.json has it.
struct Row {
    std::string label;
    std::string technique;
    contactsheet::Scores scores;
};

nlohmann::json readJson(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) {
        throw engine::IoError(path.string() + ": cannot read (run gs-shadowbench --out first)");
    }
    try {
        return nlohmann::json::parse(file);
    } catch (const nlohmann::json::exception& error) {
        throw engine::Error(path.string() + ": " + error.what());
    }
}

} // namespace

int main(int argc, char** argv) {
    const Options options = kTool.parse(parse, argc, argv);
    try {
        const std::filesystem::path resultsPath = options.bench / "results.json";
        const nlohmann::json results = readJson(resultsPath);
        std::vector<Row> rows;
        std::string scene;
        try {
            for (const nlohmann::json& result : results.at("results")) {
                if (!result.at("peer").is_null()) {
                    continue;
                }
                const std::string rowScene = result.at("scene").get<std::string>();
                scene = scene.empty() ? options.scene.value_or(rowScene) : scene;
                if (rowScene != scene) {
                    continue;
                }
                const nlohmann::json& edges = result.at("edges");
                rows.push_back(
                    {result.at("label").get<std::string>(),
                     result.at("settings").at("technique").get<std::string>(),
                     {result.at("acneRate").get<double>(), result.at("leakRate").get<double>(),
                      result.at("darkening").get<double>(), result.at("frameMs").at("median").get<double>(),
                      edges.at("trueToRendered").at("p95").get<double>(),
                      edges.at("renderedToTrue").at("p95").get<double>()}});
            }
        } catch (const nlohmann::json::exception& error) {
            throw engine::Error(resultsPath.string() + ": " + error.what());
        }
        if (rows.empty()) {
            throw engine::Error(resultsPath.string() + ": no rows of scene '" + scene + "'");
        }
        // A technique that ran once is named by itself; several runs of one (a tap or size sweep) by label.
        std::map<std::string, int> runsOfTechnique;
        for (const Row& row : rows) {
            ++runsOfTechnique[row.technique];
        }
        const contactsheet::Font font(options.font, static_cast<float>(options.fontSize));
        const std::filesystem::path folder = options.bench / scene;
        const auto tileImage = [&](const std::string& file) {
            return contactsheet::downsample(engine::readPng(folder / file), options.downsample);
        };
        std::vector<contactsheet::Tile> shaded;
        std::vector<contactsheet::Tile> errors{
            {tileImage("truth.png"),
             {"ray-traced truth (Embree)", "white lit, grey shadowed, ochre edge band"}}};
        for (const Row& row : rows) {
            const std::string name = runsOfTechnique[row.technique] == 1 ? row.technique : row.label;
            shaded.push_back({tileImage(row.label + ".png"), contactsheet::shadedLabel(name, row.scores)});
            errors.push_back(
                {tileImage(row.label + "-classes.png"), contactsheet::errorLabel(name, row.scores)});
        }
        contactsheet::SheetLayout layout;
        layout.columns = options.columns;
        const int width = results.value("width", 0);
        const int height = results.value("height", 0);
        const std::string size = std::to_string(width) + "x" + std::to_string(height);
        // The labels' third line, explained once per sheet rather than under every tile.
        const std::string timeAndEdges = "; frame = median whole frame; edge p95 = true edges to the nearest "
                                         "drawn / drawn to the nearest true";
        const std::filesystem::path out = options.out.value_or(options.bench);
        engine::writePng(out / "contact-sheet.png",
                         contactsheet::composeSheet(scene + ", " + size +
                                                        ", against the ray-traced truth: acne = lit drawn "
                                                        "shadowed, leak = shadowed drawn lit, darkening = "
                                                        "light lost where lit" +
                                                        timeAndEdges,
                                                    shaded, font, layout));
        engine::writePng(out / "truth-sheet.png",
                         contactsheet::composeSheet(scene + ", " + size +
                                                        ": the truth's classes, then each technique's errors "
                                                        "(red acne, blue leak)" +
                                                        timeAndEdges,
                                                    errors, font, layout));
        std::cout << "wrote " << (out / "contact-sheet.png").string() << " and "
                  << (out / "truth-sheet.png").string() << " (" << rows.size() << " configurations of "
                  << scene << ")\n";
        return 0;
    } catch (const engine::Error& error) {
        std::cerr << "gs-contactsheet: " << error.what() << "\n";
        return 1;
    }
}
