#include <shadowbench/ShadowBench.h>

#include <shadows/ShadowModule.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace shadowbench {

namespace {

/// How far along its path the camera moves, in units of the distance to what it looks at, and how far it
/// turns right: a few percent and degrees, so the view keeps the scene while both move it across the image
/// (turning left would cancel the move's shift near the centre, and pixels there would barely move).
constexpr float kPathDistanceFraction = 0.04f;
constexpr float kPathYawDegrees = 3.0f;
/// A receiver's point and the previous frame's nearest pixel are the same surface within this many pixel
/// sizes: the nearest pixel is up to 0.7 pixels off, more on a slanted surface; a hidden surface or the
/// other side of a silhouette lies much further.
constexpr float kSameSurfacePixels = 1.5f;

/// One frame of the camera path: where each pixel's surface is, which pixels are receivers, the truth's and
/// the technique's visibility there, and how the frame's camera projects the world.
struct PathFrame {
    glm::mat4 viewProjection{1.0f};
    std::vector<glm::vec3> positions;
    std::vector<float> pixelSizes;
    std::vector<std::uint8_t> receivers;
    std::vector<float> truth;
    std::vector<float> visibility;
};

/// The camera's world pose `fraction` of the way along its path from the pose `start`: moved `distance`
/// along its right + forward direction and turned `yawRadians` right about the world's up axis at its eye.
engine::Transform pathPose(const glm::mat4& start, float distance, float yawRadians, float fraction) {
    const glm::vec3 scale(glm::length(glm::vec3(start[0])), glm::length(glm::vec3(start[1])),
                          glm::length(glm::vec3(start[2])));
    const glm::mat3 axes{glm::vec3(start[0]) / scale.x, glm::vec3(start[1]) / scale.y,
                         glm::vec3(start[2]) / scale.z};
    const glm::vec3 along = glm::normalize(axes[0] - axes[2]); // right + forward (the camera looks down -Z)
    engine::Transform pose;
    pose.translation = glm::vec3(start[3]) + along * (distance * fraction);
    pose.rotation =
        glm::angleAxis(-yawRadians * fraction, glm::vec3(0.0f, 1.0f, 0.0f)) * glm::quat_cast(axes);
    pose.scale = scale;
    return pose;
}

/// The distance from `eye` to the surface at the image's centre, or where that is background, the mean
/// distance to the covered pixels; 0 when none is.
float lookDistance(const glm::vec3& eye, glm::ivec2 size, const std::vector<glm::vec3>& positions,
                   const std::vector<Surface>& surfaces) {
    const auto centre = static_cast<std::size_t>(size.y / 2) * static_cast<std::size_t>(size.x) +
                        static_cast<std::size_t>(size.x / 2);
    if (surfaces[centre] != Surface::None) {
        return glm::length(positions[centre] - eye);
    }
    double sum = 0.0;
    std::size_t covered = 0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (surfaces[i] != Surface::None) {
            sum += glm::length(positions[i] - eye);
            ++covered;
        }
    }
    return covered ? static_cast<float>(sum / static_cast<double>(covered)) : 0.0f;
}

/// The pixel of an image of `size` (rows top to bottom) nearest to where `viewProjection` puts `position`;
/// nullopt off the image or behind the camera.
std::optional<std::size_t> nearestPixel(const glm::mat4& viewProjection, const glm::vec3& position,
                                        glm::ivec2 size) {
    const glm::vec4 clip = viewProjection * glm::vec4(position, 1.0f);
    if (!(clip.w > 0.0f)) {
        return std::nullopt;
    }
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const float column = std::floor((0.5f * ndc.x + 0.5f) * static_cast<float>(size.x));
    const float row = std::floor((0.5f - 0.5f * ndc.y) * static_cast<float>(size.y));
    if (!(column >= 0.0f && row >= 0.0f && column < static_cast<float>(size.x) &&
          row < static_cast<float>(size.y))) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(size.x) +
           static_cast<std::size_t>(column);
}

/// Puts the tracer's viewer back where the scene's view has it, however the measurement ends: the band
/// of later measurements offsets its rays by it.
class ViewerRestorer {
public:
    ViewerRestorer(RayTracedVisibility& tracer, const glm::vec3& eye) : tracer_(tracer), eye_(eye) {}
    ~ViewerRestorer() { tracer_.setViewer(eye_); }
    ViewerRestorer(const ViewerRestorer&) = delete;
    ViewerRestorer& operator=(const ViewerRestorer&) = delete;

private:
    RayTracedVisibility& tracer_;
    glm::vec3 eye_;
};

} // namespace

double ShadowBench::measureShimmer(const BenchScene& scene, const shadows::ShadowSettings& settings) const {
    engine::Engine engine;
    shadows::ShadowSettings visibilityOnly = settings;
    visibilityOnly.debugView = shadows::ShadowDebugView::Visibility;
    auto& module = static_cast<shadows::ShadowModule&>(
        engine.addModule(std::make_unique<shadows::ShadowModule>(visibilityOnly)));
    engine::RenderTarget target(options_.size, engine::ColorFormat::Rgba32F);
    const engine::Entity& camera = scene.scene_.entity(scene.camera_);
    const shadows::FitView start{glm::inverse(scene.scene_.worldMatrix(scene.camera_)),
                                 camera.camera->projectionMatrix(static_cast<float>(options_.size.x) /
                                                                 static_cast<float>(options_.size.y))};
    // An oblique direction, so the step has a component along both of the map's axes whatever the light.
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 0.37f, 0.61f));
    float step = 0.0f;
    std::vector<float> previous;
    std::size_t changes = 0;
    std::size_t compared = 0;
    for (int frame = 0; frame <= options_.shimmerFrames; ++frame) {
        shadows::FitView moved = start;
        moved.view = glm::translate(start.view, -direction * (step * static_cast<float>(frame)));
        module.setFitView(moved);
        engine.renderFrame(scene.scene_, scene.camera_, target);
        if (frame == 0) {
            const auto projection = module.lightProjection(scene.light_.index);
            if (!projection) {
                return 0.0; // no map, nothing to shimmer
            }
            // A third of a texel: a perspective map's texel at the camera's distance from the light.
            const glm::vec3 eye(scene.scene_.worldMatrix(scene.camera_)[3]);
            const float distance = projection->perspective ? glm::length(eye - scene.light_.position) : 1.0f;
            step = projection->texelScale * distance / 3.0f;
        }
        std::vector<float> pixels = target.readPixelsFloat();
        if (!previous.empty()) {
            for (std::size_t i = 0; i < scene.surfaces_.size(); ++i) {
                if (scene.surfaces_[i] == Surface::Receiver) {
                    changes += std::abs(pixels[4 * i] - previous[4 * i]) > 0.5f;
                    ++compared;
                }
            }
        }
        previous = std::move(pixels);
    }
    return compared ? static_cast<double>(changes) / static_cast<double>(compared) : 0.0;
}

double ShadowBench::measurePathShimmer(const BenchScene& scene,
                                       const shadows::ShadowSettings& settings) const {
    const glm::mat4 startPose = scene.scene_.worldMatrix(scene.camera_);
    const glm::vec3 startEye(startPose[3]);
    const float distance =
        kPathDistanceFraction * lookDistance(startEye, options_.size, scene.positions_, scene.surfaces_);
    if (!(distance > 0.0f) || options_.pathFrames <= 0) {
        return 0.0; // nothing in view, or no frame pairs
    }
    // The path moves the camera of a copy at the root, so its pose is its world pose whatever its parents.
    engine::Scene moving = scene.scene_;
    moving.setParent(scene.camera_, engine::kNoEntity);
    const engine::CameraComponent& lens = *moving.entity(scene.camera_).camera;
    const float aspect = static_cast<float>(options_.size.x) / static_cast<float>(options_.size.y);

    engine::Engine gbuffer;
    engine::Engine technique;
    shadows::ShadowSettings visibilityOnly = settings;
    visibilityOnly.debugView = shadows::ShadowDebugView::Visibility;
    technique.addModule(std::make_unique<shadows::ShadowModule>(visibilityOnly));
    engine::RenderTarget target(options_.size, engine::ColorFormat::Rgba32F);
    RayTracedVisibility& tracer = *scene.tracer_;
    const ViewerRestorer restorer(tracer, startEye);
    const std::size_t pixels =
        static_cast<std::size_t>(options_.size.x) * static_cast<std::size_t>(options_.size.y);

    PathFrame previous;
    std::size_t flips = 0;
    std::size_t compared = 0;
    for (int step = 0; step <= options_.pathFrames; ++step) {
        const float fraction = static_cast<float>(step) / static_cast<float>(options_.pathFrames);
        moving.entity(scene.camera_).transform =
            pathPose(startPose, distance, glm::radians(kPathYawDegrees), fraction);
        const glm::mat4 pose = moving.worldMatrix(scene.camera_);
        const glm::vec3 eye(pose[3]);

        PathFrame frame;
        frame.viewProjection = lens.projectionMatrix(aspect) * glm::inverse(pose);
        gbuffer.renderer().output = engine::OutputMode::WorldPosition;
        gbuffer.renderFrame(moving, scene.camera_, target);
        const std::vector<float> positionRgba = target.readPixelsFloat();
        gbuffer.renderer().output = engine::OutputMode::WorldNormal;
        gbuffer.renderFrame(moving, scene.camera_, target);
        const std::vector<float> normalRgba = target.readPixelsFloat();
        frame.positions.resize(pixels);
        std::vector<glm::vec3> normals(pixels);
        std::vector<std::uint8_t> covered(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            frame.positions[i] = {positionRgba[4 * i], positionRgba[4 * i + 1], positionRgba[4 * i + 2]};
            normals[i] = {normalRgba[4 * i], normalRgba[4 * i + 1], normalRgba[4 * i + 2]};
            covered[i] = positionRgba[4 * i + 3] > 0.5f;
        }
        frame.pixelSizes =
            BenchScene::viewPixelSizes(moving, scene.camera_, frame.positions, covered, options_.size);
        // The facet normals, and the truth's ray offsets, are taken on the side this frame's eye sees.
        tracer.setViewer(eye);
        frame.receivers.resize(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            frame.receivers[i] =
                covered[i] && BenchScene::surfaceFacing(tracer, scene.light_, frame.positions[i],
                                                        normals[i]) == Surface::Receiver;
        }
        frame.truth.resize(pixels);
        tracer.hardVisibility(frame.positions, normals, covered, scene.light_, frame.truth);
        technique.renderFrame(moving, scene.camera_, target);
        const std::vector<float> visibilityRgba = target.readPixelsFloat();
        frame.visibility.resize(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            frame.visibility[i] = visibilityRgba[4 * i];
        }

        if (step > 0) {
            for (std::size_t i = 0; i < pixels; ++i) {
                if (!frame.receivers[i]) {
                    continue;
                }
                const auto before = nearestPixel(previous.viewProjection, frame.positions[i], options_.size);
                if (!before || !previous.receivers[*before] ||
                    glm::length(previous.positions[*before] - frame.positions[i]) >
                        kSameSurfacePixels * frame.pixelSizes[i]) {
                    continue; // off the previous image, or hidden there: nothing to compare with
                }
                ++compared;
                flips += std::abs(frame.visibility[i] - previous.visibility[*before]) > 0.5f &&
                         std::abs(frame.truth[i] - previous.truth[*before]) <= 0.5f;
            }
        }
        previous = std::move(frame);
    }
    return compared ? static_cast<double>(flips) / static_cast<double>(compared) : 0.0;
}

} // namespace shadowbench
