// gs-corpus: turns real models into benchmark scenes (a ground plane, a camera and a sun placed from the
// model's bounds) and makes the large generated ones. tools/corpus.sh drives it over the real-model corpus.
#include "ApronScene.h"
#include "SceneStaging.h"
#include "TerragenReader.h"

#include <cli/OptionValues.h>
#include <content/ContentError.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr const char* kUsage = R"(usage:
  gs-corpus stage MODEL.gltf OUT.glb [options]   a converted model on a ground, with camera and sun
  gs-corpus terrain TERRAIN.ter OUT.glb [options] a Terragen heightfield, camera near the ground
  gs-corpus tessellation TRIANGLES OUT.glb [options]  generated hills of about TRIANGLES triangles
  gs-corpus apron OUT.glb [options]              a generated 300 m airport apron, camera 8 m up
options:
  --up [-]x|y|z             the model's up axis (stage)                          [y]
  --subdivide SCHEME:LEVEL  refine the model at load (catmull-clark|loop, 0..4) (stage)
  --sun-elevation DEG       sun above the horizon, 1..90                         [40; terrain 20; apron 8]
  --sun-azimuth DEG         sun around +Y, relative to the camera side            [110; apron 75]
  --camera-elevation DEG    camera above the horizon, 0..89 (not apron)           [25]
  --camera-height UNITS     terrain, tessellation: the camera this high above the ground inside the near
                            edge, looking level across (instead of from above the edge)
  --merged                  every object in one mesh on one node (apron))";

[[noreturn]] void usageError(const std::string& message) {
    std::cerr << "gs-corpus: " << message << "\n" << kUsage << "\n";
    std::exit(2);
}

corpus::StagingOptions parseOptions(const std::vector<std::string>& args, std::size_t first, bool terrain) {
    corpus::StagingOptions options;
    if (terrain) {
        options.sunElevation = 20.0f;
    }
    for (std::size_t i = first; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (i + 1 >= args.size()) {
            usageError("option '" + arg + "' needs a value (or is unknown)");
        }
        const std::string& value = args[++i];
        if (arg == "--up") {
            static const std::vector<std::pair<std::string, glm::vec3>> axes = {
                {"x", {1, 0, 0}},   {"-x", {-1, 0, 0}}, {"y", {0, 1, 0}},
                {"-y", {0, -1, 0}}, {"z", {0, 0, 1}},   {"-z", {0, 0, -1}}};
            const auto axis =
                std::find_if(axes.begin(), axes.end(), [&](const auto& a) { return a.first == value; });
            if (axis == axes.end()) {
                usageError("--up: '" + value + "' is not one of x, -x, y, -y, z, -z");
            }
            options.up = axis->second;
        } else if (arg == "--subdivide") {
            const auto colon = value.find(':');
            const std::string scheme = value.substr(0, colon);
            if (colon == std::string::npos || (scheme != "catmull-clark" && scheme != "loop")) {
                usageError("--subdivide: '" + value + "' is not catmull-clark:LEVEL or loop:LEVEL");
            }
            options.subdivision = content::SubdivisionTag{
                scheme, cli::integerIn("--subdivide", value.substr(colon + 1), 0, 4), ""};
        } else if (arg == "--sun-elevation") {
            options.sunElevation = cli::numberIn(arg, value, 1.0f, 90.0f);
        } else if (arg == "--sun-azimuth") {
            options.sunAzimuth = cli::numberIn(arg, value, -360.0f, 360.0f);
        } else if (arg == "--camera-elevation") {
            options.cameraElevation = cli::numberIn(arg, value, 0.0f, 89.0f);
        } else if (arg == "--camera-height") {
            options.cameraHeight = cli::numberIn(arg, value, 0.01f, 1e6f);
        } else {
            usageError("unknown option '" + arg + "'");
        }
    }
    return options;
}

corpus::ApronOptions parseApronOptions(const std::vector<std::string>& args, std::size_t first) {
    corpus::ApronOptions options;
    for (std::size_t i = first; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--merged") {
            options.merged = true;
            continue;
        }
        if (i + 1 >= args.size()) {
            usageError("option '" + arg + "' needs a value (or is unknown)");
        }
        const std::string& value = args[++i];
        if (arg == "--sun-elevation") {
            options.sunElevation = cli::numberIn(arg, value, 1.0f, 90.0f);
        } else if (arg == "--sun-azimuth") {
            options.sunAzimuth = cli::numberIn(arg, value, -360.0f, 360.0f);
        } else {
            usageError("unknown option '" + arg + "' (apron)");
        }
    }
    return options;
}

/// Rolling hills of about `triangles` triangles over a 100 m square: a tessellation sweep whose shadows do
/// not change with the triangle count.
engine::MeshData hills(int triangles) {
    corpus::Heightfield field;
    const int cells = std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
    field.columns = field.rows = cells + 1;
    field.spacing = 100.0f / static_cast<float>(cells);
    for (int y = 0; y <= cells; ++y) {
        for (int x = 0; x <= cells; ++x) {
            const float u = glm::two_pi<float>() * static_cast<float>(x) / static_cast<float>(cells);
            const float v = glm::two_pi<float>() * static_cast<float>(y) / static_cast<float>(cells);
            field.elevations.push_back(6.0f * std::sin(2.0f * u) * std::cos(3.0f * v) +
                                       2.5f * std::sin(7.0f * u + 5.0f * v));
        }
    }
    engine::MeshData mesh = corpus::heightfieldMesh(field);
    mesh.name = "hills";
    return mesh;
}

void writeAndReport(const content::LoadedScene& scene, const std::filesystem::path& out) {
    content::GltfWriter::save(scene.scene, out, scene.subdivided);
    const content::LoadedScene check = content::GltfLoader::load(out); // never emit what the engine rejects
    std::size_t triangles = 0;
    check.scene.forEach([&](engine::EntityId, const engine::Entity& entity) {
        triangles += entity.mesh && entity.mesh->mesh ? entity.mesh->mesh->triangleCount() : 0;
    });
    std::cout << "gs-corpus: wrote " << out.string() << " (" << triangles << " triangles)\n";
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help") {
        std::cout << kUsage << "\n";
        return args.empty() ? 2 : 0;
    }
    const std::string& command = args[0];
    // The apron is generated from nothing; every other command reads an input.
    if (command == "apron" ? args.size() < 2 : args.size() < 3) {
        usageError("'" + command + "' needs " +
                   (command == "apron" ? "an output" : "an input and an output"));
    }
    try {
        if (command == "stage") {
            const corpus::StagingOptions options = parseOptions(args, 3, false);
            const content::LoadedScene model = content::GltfLoader::load(args[1]);
            writeAndReport(corpus::stageModel(model, options, args[1]), args[2]);
        } else if (command == "terrain") {
            const corpus::StagingOptions options = parseOptions(args, 3, true);
            writeAndReport(
                corpus::stageSurface(corpus::heightfieldMesh(corpus::readTerragen(args[1])), options),
                args[2]);
        } else if (command == "tessellation") {
            const int triangles = cli::integerIn("TRIANGLES", args[1], 2, 20'000'000);
            const corpus::StagingOptions options = parseOptions(args, 3, false);
            writeAndReport(corpus::stageSurface(hills(triangles), options), args[2]);
        } else if (command == "apron") {
            const corpus::ApronOptions options = parseApronOptions(args, 2);
            writeAndReport(corpus::apronScene(options), args[1]);
        } else {
            usageError("unknown command '" + command + "'");
        }
    } catch (const std::invalid_argument& error) {
        usageError(error.what());
    } catch (const std::exception& error) {
        std::cerr << "gs-corpus: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
