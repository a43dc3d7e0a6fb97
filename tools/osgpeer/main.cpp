// gs-osgshadow: renders a content scene with one of OpenSceneGraph's osgShadow techniques, with the scene's
// own camera and first directional light, and writes frame times, the shadowed frame and its shadow
// visibility so the benchmark can compare our techniques against a widely used peer.
#include "OsgScene.h"
#include "PeerOutputs.h"

#include <cli/ContentFolder.h>
#include <cli/OptionValues.h>
#include <content/GltfLoader.h>
#include <engine/Error.h>
#include <engine/GlContext.h>
#include <engine/Image.h>

#include <nlohmann/json.hpp>

#include <osg/Camera>
#include <osg/GL>
#include <osg/GraphicsContext>
#include <osg/Notify>
#include <osg/State>
#include <osg/Version>
#include <osgShadow/LightSpacePerspectiveShadowMap>
#include <osgShadow/ParallelSplitShadowMap>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowSettings>
#include <osgShadow/ShadowedScene>
#include <osgShadow/SoftShadowMap>
#include <osgShadow/ViewDependentShadowMap>
#include <osgViewer/Viewer>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr const char* kProgram = "gs-osgshadow";

// OpenSceneGraph 3.6's ViewDependentShadowMap::cull renders at most two maps per light: it notices a larger
// ShadowSettings::setNumShadowMapsPerLight and falls back to two, so more would be mislabelled runs.
constexpr int kVdsmMaxMapsPerLight = 2;

struct Options {
    std::string scene;
    std::filesystem::path contentFolder = cli::defaultContentFolder();
    std::string technique = "vdsm";
    // ParallelSplitShadowMap's settings; an unset one keeps OSG's default.
    int splits = 3;
    std::string splitScheme = "exp";
    std::optional<float> maxFar;
    std::optional<float> splitMinNear;
    std::optional<float> moveBehind;
    std::optional<glm::vec2> polygonOffset;
    /// An option given that only pssm reads, to reject it with another technique.
    std::string pssmOption;
    /// ViewDependentShadowMap's maps per light; unset keeps OSG's defaults (one map).
    std::optional<int> cascades;
    glm::ivec2 size{640, 480};
    int mapSize = 2048;
    int frames = 20;
    int warmup = 5;
    std::string outPrefix;
    std::string surface = "auto";
    /// Raise glibc's thresholds on a CPU rasteriser as our engine does (engine::raiseAllocatorThresholds).
    bool tuneAllocator = true;
    bool verbose = false;
};

constexpr const char* kUsage = R"(usage: gs-osgshadow --scene FILE.gltf --out PREFIX [options]
  --scene FILE     .gltf/.glb path, or a scene name (content/scenes/NAME.gltf, else corpus/NAME.glb)
  --out PREFIX     writes PREFIX.json, PREFIX.png (shadowed frame) and PREFIX.visibility.pfm
  --technique T    vdsm (ViewDependentShadowMap), sm (ShadowMap), lispsm (LightSpacePerspectiveShadowMapVB),
                   ssm (SoftShadowMap), pssm (ParallelSplitShadowMap) [vdsm]
  --cascades N     vdsm: maps per light, 1..2 (OSG 3.6's maximum), cascaded hint [OSG's: one map]
  --splits N       pssm: splits of the view frustum, one map each, 1..4  [3]
  --split-scheme S pssm: exp or linear split distances             [exp]
  --max-far D      pssm: shadows end at this view distance (setMaxFarDistance) [the camera's far]
  --split-min-near D  pssm: casters up to D beyond a split, towards the light, still cast
                   (setMinNearDistanceForSplits)                   [5]
  --move-behind D  pssm: split frusta start D scene units behind the camera
                   (setMoveVCamBehindRCamFactor)                   [0]
  --polygon-offset F,U  pssm: glPolygonOffset(F, U) while rendering its maps [none]
  --size WxH       image size in pixels, 1..16384 each             [640x480]
  --map-size N     shadow map resolution, 16..16384                [2048]
  --frames N       timed frames per pass, 1..1000                  [20]
  --warmup N       untimed frames before each pass, 0..1000        [5]
  --content DIR    folder that scene names resolve in              [installed or source content/]
  --surface S      auto (pbuffer, else window), pbuffer or window  [auto]
  --allocator A    tuned (mallopt on CPU rasterisers, as gs-render does) or default [tuned]
  --verbose        pass OpenSceneGraph's warnings through to stderr
  --help           this text
Needs an X display with GLX (e.g. xvfb-run -a -s "-screen 0 1280x1024x24").)";

constexpr cli::Tool kTool{kProgram, kUsage};

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
        } else if (arg == "--content") {
            options.contentFolder = value();
        } else if (arg == "--technique") {
            options.technique = value();
            if (options.technique != "vdsm" && options.technique != "sm" && options.technique != "lispsm" &&
                options.technique != "ssm" && options.technique != "pssm") {
                usageError("--technique: unknown technique '" + options.technique +
                           "' (vdsm, sm, lispsm, ssm, pssm)");
            }
        } else if (arg == "--cascades") {
            const int cascades = cli::integerIn(arg, value(), 1, 4);
            if (cascades > kVdsmMaxMapsPerLight) {
                usageError("--cascades: OpenSceneGraph 3.6's ViewDependentShadowMap renders at most " +
                           std::to_string(kVdsmMaxMapsPerLight) + " maps per light (it would draw " +
                           std::to_string(kVdsmMaxMapsPerLight) + ", not " + std::to_string(cascades) +
                           "); for more splits use --technique pssm --splits " + std::to_string(cascades));
            }
            options.cascades = cascades;
        } else if (arg == "--splits") {
            options.splits = cli::integerIn(arg, value(), 1, 4);
            options.pssmOption = arg;
        } else if (arg == "--split-scheme") {
            options.splitScheme = value();
            if (options.splitScheme != "exp" && options.splitScheme != "linear") {
                usageError("--split-scheme: unknown scheme '" + options.splitScheme + "' (exp, linear)");
            }
            options.pssmOption = arg;
        } else if (arg == "--max-far") {
            options.maxFar = cli::numberIn(arg, value(), 1e-3f, 1e9f);
            options.pssmOption = arg;
        } else if (arg == "--split-min-near") {
            options.splitMinNear = cli::numberIn(arg, value(), 0.0f, 1e9f);
            options.pssmOption = arg;
        } else if (arg == "--move-behind") {
            options.moveBehind = cli::numberIn(arg, value(), 0.0f, 1e6f);
            options.pssmOption = arg;
        } else if (arg == "--polygon-offset") {
            const std::string text = value();
            const auto comma = text.find(',');
            if (comma == std::string::npos) {
                usageError("--polygon-offset: '" + text + "' is not FACTOR,UNITS");
            }
            options.polygonOffset = glm::vec2(cli::numberIn(arg, text.substr(0, comma), -1e4f, 1e4f),
                                              cli::numberIn(arg, text.substr(comma + 1), -1e4f, 1e4f));
            options.pssmOption = arg;
        } else if (arg == "--size") {
            options.size = cli::sizeIn("--size", value(), 1, 16384);
        } else if (arg == "--map-size") {
            options.mapSize = cli::integerIn("--map-size", value(), 16, 16384);
        } else if (arg == "--frames") {
            options.frames = cli::integerIn("--frames", value(), 1, 1000);
        } else if (arg == "--warmup") {
            options.warmup = cli::integerIn("--warmup", value(), 0, 1000);
        } else if (arg == "--out") {
            options.outPrefix = value();
            if (options.outPrefix.empty()) {
                usageError("--out: the prefix is empty");
            }
        } else if (arg == "--surface") {
            options.surface = value();
            if (options.surface != "auto" && options.surface != "pbuffer" && options.surface != "window") {
                usageError("--surface: unknown surface '" + options.surface + "' (auto, pbuffer, window)");
            }
        } else if (arg == "--allocator") {
            const std::string name = value();
            if (name != "tuned" && name != "default") {
                usageError("--allocator: '" + name + "' is not tuned or default");
            }
            options.tuneAllocator = name == "tuned";
        } else if (arg == "--verbose") {
            options.verbose = true;
        } else {
            usageError("unknown option '" + arg + "'");
        }
    }
    if (options.scene.empty()) {
        usageError("--scene is required");
    }
    if (options.outPrefix.empty()) {
        usageError("--out is required");
    }
    if (!options.pssmOption.empty() && options.technique != "pssm") {
        usageError(options.pssmOption + " applies to --technique pssm only");
    }
    if (options.cascades && options.technique != "vdsm") {
        usageError("--cascades applies to --technique vdsm only");
    }
    return options;
}

/// A failure at run time (no display, no context, no frame): the message is the whole error line.
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// OSG prints notices and warnings straight to the console; errors must stay one clear line, so its messages
// are held back (and counted) unless --verbose asks for them.
class OsgMessages : public osg::NotifyHandler {
public:
    explicit OsgMessages(bool verbose) : verbose_(verbose) {}
    void notify(osg::NotifySeverity severity, const char* message) override {
        if (severity <= osg::WARN) {
            ++warnings;
        }
        if (verbose_) {
            std::cerr << kProgram << ": osg: " << message;
        }
    }
    int warnings = 0;

private:
    bool verbose_;
};

/// What the final-draw callback does and found; the callback itself must be const.
struct FrameEnd {
    GLenum readBuffer = GL_BACK;
    glm::ivec2 size{0};
    std::string renderer;
    bool captureNext = false;
    std::optional<osgpeer::RgbFrame> captured;
    /// The projection the captured frame's last drawables were drawn with: the main view's.
    osg::Matrixd drawnProjection;
};

// Runs after everything the camera drew, shadow passes included: glFinish makes the timed frame include the
// GPU work, and the read-back happens before a window's buffer swap.
class FinishAndCapture : public osg::Camera::DrawCallback {
public:
    explicit FinishAndCapture(FrameEnd& state) : state_(state) {}
    void operator()(osg::RenderInfo& renderInfo) const override {
        glFinish();
        if (state_.renderer.empty()) {
            const GLubyte* renderer = glGetString(GL_RENDERER);
            state_.renderer = renderer ? reinterpret_cast<const char*>(renderer) : "unknown";
        }
        if (state_.captureNext) {
            osgpeer::RgbFrame frame;
            frame.size = state_.size;
            frame.rgb.resize(static_cast<std::size_t>(state_.size.x) *
                             static_cast<std::size_t>(state_.size.y) * 3);
            glReadBuffer(state_.readBuffer);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, state_.size.x, state_.size.y, GL_RGB, GL_UNSIGNED_BYTE, frame.rgb.data());
            if (glGetError() == GL_NO_ERROR) {
                state_.captured = std::move(frame);
            }
            state_.drawnProjection = renderInfo.getState()->getProjectionMatrix();
            state_.captureNext = false;
        }
    }

private:
    FrameEnd& state_;
};

struct Context {
    osg::ref_ptr<osg::GraphicsContext> context;
    bool pbuffer = false;
};

// A pbuffer keeps the surface exactly WxH with nothing on screen; a window is the fallback for GLX servers
// without pbuffer configurations.
Context createContext(glm::ivec2 size, const std::string& surface) {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        throw RunError(
            "no X display: DISPLAY is not set (run under xvfb-run -a -s \"-screen 0 1280x1024x24\")");
    }
    for (const bool pbuffer : {true, false}) {
        if ((pbuffer && surface == "window") || (!pbuffer && surface == "pbuffer")) {
            continue;
        }
        osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
        traits->readDISPLAY();
        traits->setUndefinedScreenDetailsToDefaultScreen();
        traits->x = 0;
        traits->y = 0;
        traits->width = size.x;
        traits->height = size.y;
        traits->red = traits->green = traits->blue = 8;
        traits->alpha = 0;
        traits->depth = 24;
        traits->samples = 0; // our renderer does not multisample either
        traits->pbuffer = pbuffer;
        traits->doubleBuffer = !pbuffer;
        traits->windowDecoration = false;
        traits->vsync = false;
        osg::ref_ptr<osg::GraphicsContext> context = osg::GraphicsContext::createGraphicsContext(traits);
        if (context && context->valid()) {
            return {context, pbuffer};
        }
    }
    const std::string tried = surface == "auto" ? "neither a GLX pbuffer nor a window" : "no GLX " + surface;
    throw RunError(std::string("cannot create an OpenGL context on X display '") + display + "' (" + tried +
                   "; is the X server running with GLX?)");
}

struct Technique {
    osg::ref_ptr<osgShadow::ShadowTechnique> technique;
    std::string osgClass;
    /// Shadow maps rendered per frame.
    int shadowMaps = 1;
    /// The settings that shape the result, as the report records them.
    nlohmann::ordered_json settings;
};

const char* toString(osgShadow::ShadowSettings::ShadowMapProjectionHint hint) {
    return hint == osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP ? "orthographic" : "perspective";
}

const char* toString(osgShadow::ShadowSettings::MultipleShadowMapHint hint) {
    return hint == osgShadow::ShadowSettings::CASCADED ? "cascaded" : "parallel split";
}

Technique makeParallelSplit(const Options& options, const osgpeer::OsgScene& scene,
                            const std::string& sceneName) {
    // ParallelSplitShadowMap reads field of view, aspect, near and far back from the main camera's
    // projection with osg::Matrixd::getPerspective, which fails for an orthographic one and leaves them
    // unset.
    double fovy = 0.0;
    double aspect = 0.0;
    double zNear = 0.0;
    double zFar = 0.0;
    if (!scene.projection.getPerspective(fovy, aspect, zNear, zFar)) {
        throw osgpeer::PeerError(sceneName + ": --technique pssm needs a perspective camera "
                                             "(ParallelSplitShadowMap splits a perspective view frustum)");
    }
    osg::ref_ptr<osgShadow::ParallelSplitShadowMap> pssm =
        new osgShadow::ParallelSplitShadowMap(nullptr, options.splits);
    pssm->setTextureResolution(static_cast<unsigned int>(options.mapSize));
    // The user light is read in world space, as the scene's light is given; without one, PSSM would take
    // the last light the cull found.
    pssm->setUserLight(scene.light->getLight());
    // Its shader: colour = lit * (1 + bias.x) * (1 - bias.y * (1 - shadow)). OSG's (0.1, 0.3) brightens lit
    // surfaces by 10% and leaves the umbra at 77%; (0, 1) gives lit * shadow, so shadowed/unshadowed is the
    // shadow term.
    pssm->setAmbientBias(osg::Vec2(0.0f, 1.0f));
    pssm->setSplitCalculationMode(options.splitScheme == "linear"
                                      ? osgShadow::ParallelSplitShadowMap::SPLIT_LINEAR
                                      : osgShadow::ParallelSplitShadowMap::SPLIT_EXP);
    if (options.maxFar) {
        pssm->setMaxFarDistance(*options.maxFar);
    }
    if (options.splitMinNear) {
        pssm->setMinNearDistanceForSplits(*options.splitMinNear);
    }
    if (options.moveBehind) {
        pssm->setMoveVCamBehindRCamFactor(*options.moveBehind);
    }
    if (options.polygonOffset) {
        pssm->setPolygonOffset(osg::Vec2f(options.polygonOffset->x, options.polygonOffset->y));
    }
    const nlohmann::ordered_json record = {
        {"splits", options.splits},
        {"splitCalculationMode", options.splitScheme == "linear" ? "linear" : "exponential"},
        // OSG's exponential scheme has a fixed exponent: split i of N ends at near + (far - near) (i/N)^1.66.
        {"splitDistances",
         options.splitScheme == "linear" ? "near + (far - near) i/N" : "near + (far - near) (i/N)^1.66"},
        {"maxFarDistance", options.maxFar ? std::min<double>(*options.maxFar, zFar) : zFar},
        {"minNearDistanceForSplits", pssm->getMinNearDistanceForSplits()},
        {"moveVCamBehindRCamFactor", pssm->getMoveVCamBehindRCamFactor()},
        // null: OSG applies no polygon offset unless one is set.
        {"polygonOffset", options.polygonOffset
                              ? nlohmann::ordered_json{options.polygonOffset->x, options.polygonOffset->y}
                              : nlohmann::ordered_json()},
        {"textureResolution", pssm->getTextureResolution()},
        {"ambientBias", {pssm->getAmbientBias().x(), pssm->getAmbientBias().y()}},
        {"shadowedColour", "gl_Color * (1 + ambientBias.x) * (1 - ambientBias.y * (1 - shadow)) (gl_Color * "
                           "shadow here)"}};
    return {pssm, "osgShadow::ParallelSplitShadowMap", options.splits, record};
}

Technique makeTechnique(const Options& options, const osgpeer::OsgScene& scene, const std::string& sceneName,
                        osgShadow::ShadowedScene& shadowed) {
    const std::string& name = options.technique;
    const auto side = static_cast<short>(options.mapSize);
    if (name == "pssm") {
        return makeParallelSplit(options, scene, sceneName);
    }
    if (name == "vdsm") {
        osgShadow::ShadowSettings* settings = shadowed.getShadowSettings();
        settings->setTextureSize(osg::Vec2s(side, side));
        settings->setLightNum(static_cast<int>(scene.light->getLight()->getLightNum()));
        if (options.cascades) {
            settings->setMultipleShadowMapHint(osgShadow::ShadowSettings::CASCADED);
            settings->setNumShadowMapsPerLight(static_cast<unsigned int>(*options.cascades));
        }
        // Its shader shades shadowed fragments with gl_FrontLightModelProduct.sceneColor (emission +
        // ambient), which our zero ambient and emission make black: no bias to undo.
        const nlohmann::ordered_json record = {
            {"shadowMapProjectionHint", toString(settings->getShadowMapProjectionHint())},
            {"numShadowMapsPerLight", settings->getNumShadowMapsPerLight()},
            {"multipleShadowMapHint", toString(settings->getMultipleShadowMapHint())},
            {"minimumShadowMapNearFarRatio", settings->getMinimumShadowMapNearFarRatio()},
            {"shadowedColour", "gl_FrontLightModelProduct.sceneColor (0 here)"}};
        return {new osgShadow::ViewDependentShadowMap, "osgShadow::ViewDependentShadowMap",
                static_cast<int>(settings->getNumShadowMapsPerLight()), record};
    }
    if (name == "sm" || name == "ssm") {
        osg::ref_ptr<osgShadow::ShadowMap> map;
        if (name == "sm") {
            map = new osgShadow::ShadowMap;
        } else {
            map = new osgShadow::SoftShadowMap;
        }
        map->setTextureSize(osg::Vec2s(side, side));
        map->setLight(scene.light.get());
        // Colour = lit * (bias.x + shadow * bias.y); the default (0.5, 0.5) leaves shadow at half brightness,
        // (0, 1) makes the shadowed/unshadowed ratio the shadow term itself.
        map->setAmbientBias(osg::Vec2(0.0f, 1.0f));
        nlohmann::ordered_json record = {
            {"ambientBias", {map->getAmbientBias().x(), map->getAmbientBias().y()}},
            {"polygonOffset", {map->getPolygonOffset().x(), map->getPolygonOffset().y()}}};
        if (const auto* soft = dynamic_cast<const osgShadow::SoftShadowMap*>(map.get())) {
            record["softnessWidth"] = soft->getSoftnessWidth();
            record["jitteringScale"] = soft->getJitteringScale();
        }
        return {map, name == "sm" ? "osgShadow::ShadowMap" : "osgShadow::SoftShadowMap", 1, record};
    }
    osg::ref_ptr<osgShadow::LightSpacePerspectiveShadowMapVB> lispsm =
        new osgShadow::LightSpacePerspectiveShadowMapVB;
    lispsm->setTextureSize(osg::Vec2s(side, side));
    lispsm->setLight(scene.light->getLight());
    // StandardShadowMap's shader shades shadowed fragments with scene ambient + light 0 ambient: both zero
    // here.
    const nlohmann::ordered_json record = {
        {"minLightMargin", lispsm->getMinLightMargin()},
        {"maxFarPlane", lispsm->getMaxFarPlane()},
        {"shadowedColour",
         "gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].ambient (0 here)"}};
    return {lispsm, "osgShadow::LightSpacePerspectiveShadowMapVB", 1, record};
}

double milliseconds(std::chrono::steady_clock::duration duration) {
    return std::chrono::duration<double, std::milli>(duration).count();
}

bool nearlyEqual(const osg::Matrixd& a, const osg::Matrixd& b) {
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 4; ++column) {
            const double scale = std::max({1.0, std::abs(a(row, column)), std::abs(b(row, column))});
            if (std::abs(a(row, column) - b(row, column)) > 1e-9 * scale) {
                return false;
            }
        }
    }
    return true;
}

/// Renders `graph` for `warmup` + `frames` frames (timing the latter) and one more that is read back, which
/// must have been drawn with `projection`.
std::vector<double> runPass(osgViewer::Viewer& viewer, osg::Node* graph, const Options& options,
                            FrameEnd& end, osgpeer::RgbFrame& frame, const char* pass,
                            const osg::Matrixd& projection) {
    viewer.setSceneData(graph);
    for (int i = 0; i < options.warmup; ++i) {
        viewer.frame();
    }
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(options.frames));
    for (int i = 0; i < options.frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        viewer.frame(); // the final-draw callback's glFinish ends inside this call
        times.push_back(milliseconds(std::chrono::steady_clock::now() - start));
    }
    end.captured.reset();
    end.captureNext = true;
    viewer.frame();
    if (!end.captured) {
        throw RunError(std::string("the ") + pass +
                       " frame could not be read back (glReadPixels failed or the "
                       "camera did not draw)");
    }
    // Shadow techniques cull with near/far planes of their own; the main view must keep the scene camera's
    // projection, or depth precision and clipping would differ from our renderer's.
    if (!nearlyEqual(end.drawnProjection, projection)) {
        throw RunError(std::string("the ") + pass +
                       " frame was drawn with a projection other than the scene camera's (OpenSceneGraph "
                       "changed its near/far planes)");
    }
    frame = std::move(*end.captured);
    end.captured.reset();
    return times;
}

nlohmann::ordered_json toJson(const osgpeer::FrameTimes& times) {
    return {{"median", times.median}, {"min", times.min}, {"max", times.max}};
}

/// The main view's projection kind and near/far planes, as every pass was drawn with them.
nlohmann::ordered_json cameraRecord(const osg::Matrixd& projection) {
    double left = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    double top = 0.0;
    double zNear = 0.0;
    double zFar = 0.0;
    const bool perspective = projection(3, 3) == 0.0;
    if (perspective) {
        projection.getFrustum(left, right, bottom, top, zNear, zFar);
    } else {
        projection.getOrtho(left, right, bottom, top, zNear, zFar);
    }
    return {{"projection", perspective ? "perspective" : "orthographic"}, {"near", zNear}, {"far", zFar}};
}

} // namespace

int main(int argc, char** argv) {
    const Options options = kTool.parse(parse, argc, argv);
    osg::ref_ptr<OsgMessages> messages = new OsgMessages(options.verbose);
    osg::setNotifyHandler(messages.get());
    osg::setNotifyLevel(options.verbose ? osg::NOTICE : osg::WARN);

    try {
        const std::filesystem::path path = cli::scenePath(options.scene, options.contentFolder);
        const content::LoadedScene loaded = content::GltfLoader::load(path);
        for (const std::string& warning : loaded.warnings) {
            std::cerr << kProgram << ": warning: " << warning << "\n";
        }
        const osgpeer::OsgScene scene = osgpeer::buildOsgScene(loaded.scene, path.string(), options.size);

        osg::ref_ptr<osg::Group> unshadowed = osgpeer::unshadowedGraph(scene);
        osg::ref_ptr<osgShadow::ShadowedScene> shadowedScene = new osgShadow::ShadowedScene;
        const Technique technique = makeTechnique(options, scene, path.string(), *shadowedScene);
        shadowedScene->setShadowTechnique(technique.technique.get());
        shadowedScene->addChild(scene.light);
        shadowedScene->addChild(scene.meshes);
        osg::ref_ptr<osg::Group> shadowed = new osg::Group;
        shadowed->setStateSet(scene.lighting);
        shadowed->addChild(shadowedScene);

        const Context context = createContext(options.size, options.surface);
        FrameEnd end;
        end.size = options.size;
        end.readBuffer = context.pbuffer ? GL_FRONT : GL_BACK;

        osgViewer::Viewer viewer;
        viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
        // No headlight or sky light: the scene's light is the only one.
        viewer.setLightingMode(osg::View::NO_LIGHT);
        viewer.setReleaseContextAtEndOfFrameHint(false);
        osg::Camera* camera = viewer.getCamera();
        camera->setGraphicsContext(context.context.get());
        camera->setViewport(0, 0, options.size.x, options.size.y);
        camera->setDrawBuffer(end.readBuffer);
        camera->setReadBuffer(end.readBuffer);
        camera->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
        // Exactly the scene's projection: OSG would otherwise tighten near/far to the scene's bounds.
        camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        // Small-feature culling would drop distant thin geometry our renderer draws.
        camera->setCullingMode(camera->getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
        camera->setProjectionMatrix(scene.projection);
        camera->setViewMatrix(scene.view);
        camera->setFinalDrawCallback(new FinishAndCapture(end));
        viewer.setSceneData(unshadowed);
        viewer.realize();
        if (!viewer.isRealized()) {
            throw RunError("the OpenGL context could not be realized on X display '" +
                           std::string(std::getenv("DISPLAY")) + "'");
        }
        // Before the first frame, so that both passes run on the allocator our renderer's frames run on: with
        // glibc's own, the pass that runs first pays llvmpipe's per-frame buffers as fresh mappings until the
        // dynamic threshold has grown past them.
        bool allocatorTuned = false;
        if (options.tuneAllocator && context.context->makeCurrent()) {
            const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
            allocatorTuned =
                renderer && engine::isSoftwareRendererName(renderer) && engine::raiseAllocatorThresholds();
        }

        osgpeer::RgbFrame unshadowedFrame;
        osgpeer::RgbFrame shadowedFrame;
        const osgpeer::FrameTimes unshadowedTimes = osgpeer::summarize(
            runPass(viewer, unshadowed.get(), options, end, unshadowedFrame, "unshadowed", scene.projection));
        const osgpeer::FrameTimes shadowedTimes = osgpeer::summarize(
            runPass(viewer, shadowed.get(), options, end, shadowedFrame, "shadowed", scene.projection));

        const std::string prefix = options.outPrefix;
        const std::vector<float> visibility = osgpeer::visibility(shadowedFrame, unshadowedFrame);
        osgpeer::writePfm(prefix + ".visibility.pfm", options.size, visibility);
        engine::writePng(prefix + ".png", osgpeer::toImage(shadowedFrame));

        const nlohmann::ordered_json report = {
            {"technique", options.technique},
            {"osgClass", technique.osgClass},
            {"renderer", end.renderer},
            {"timingMethod", "glFinish + steady clock"},
            {"size", {options.size.x, options.size.y}},
            {"mapSize", options.mapSize},
            {"shadowMaps", technique.shadowMaps},
            {"camera", cameraRecord(scene.projection)},
            {"frames", options.frames},
            {"warmup", options.warmup},
            {"unshadowedMs", toJson(unshadowedTimes)},
            {"shadowedMs", toJson(shadowedTimes)},
            {"triangles", scene.triangles},
            {"drawables", scene.drawables},
            {"scene", path.string()},
            {"surface", context.pbuffer ? "pbuffer" : "window"},
            {"allocatorTuned", allocatorTuned},
            {"osgVersion", osgGetVersion()},
            {"osgSettings", technique.settings},
        };
        engine::writeTextFile(prefix + ".json", report.dump(2) + "\n");

        if (messages->warnings > 0 && !options.verbose) {
            std::cerr << kProgram << ": warning: OpenSceneGraph reported " << messages->warnings
                      << " warning(s); rerun with --verbose to see them\n";
        }
        std::ostringstream summary;
        summary << kProgram << ": " << options.technique << " (" << technique.osgClass << ") "
                << path.filename().string() << " " << options.size.x << "x" << options.size.y << " map "
                << options.mapSize;
        if (technique.shadowMaps > 1) {
            summary << " x" << technique.shadowMaps;
        }
        summary << ": median " << unshadowedTimes.median << " ms unshadowed, " << shadowedTimes.median
                << " ms shadowed (" << end.renderer << ", " << (context.pbuffer ? "pbuffer" : "window")
                << "); wrote " << prefix << ".json, .png, "
                << ".visibility.pfm\n";
        std::cout << summary.str();
        return 0;
    } catch (const engine::Error& error) { // ContentError (the glTF) and IoError (outputs) included
        std::cerr << kProgram << ": " << error.what() << "\n";
    } catch (const osgpeer::PeerError& error) {
        std::cerr << kProgram << ": " << error.what() << "\n";
    } catch (const RunError& error) {
        std::cerr << kProgram << ": " << error.what() << "\n";
    } catch (const std::exception& error) {
        std::cerr << kProgram << ": unexpected error: " << error.what() << "\n";
    }
    return 1;
}
