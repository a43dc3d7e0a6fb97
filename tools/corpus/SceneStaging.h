#pragma once

#include <content/GltfLoader.h>

#include <optional>
#include <string>

namespace corpus {

/// @brief How a model is turned into a benchmark scene.
struct StagingOptions {
    /// The model's up axis (a coordinate axis, either sign), rotated to +Y. Default +Y (glTF's).
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    /// Refine every mesh of the model as this subdivision surface at load time (our OpenSubdiv path); the
    /// written mesh is the cage. Empty = none.
    std::optional<content::SubdivisionTag> subdivision;
    /// Sun elevation above the horizon and azimuth around +Y from the camera's side, degrees.
    float sunElevation = 40.0f;
    float sunAzimuth = 110.0f;
    /// Camera elevation above the horizon, degrees, looking at the model's centre from a 3/4 view.
    float cameraElevation = 25.0f;
    /// stageSurface: when set, the camera stands this many world units above the surface inside its near
    /// edge and looks across it, as a person on the ground does, instead of from above the near edge.
    std::optional<float> cameraHeight;
};

/// @brief Puts `loaded` (a converted model) on a ground plane with a camera and a directional light, all
/// placed from the model's world bounds: the model stands on y = 0, centred on the origin; the ground is four
/// times its footprint; the camera frames its bounding sphere. Cameras and lights of the source are dropped.
/// Throws content::ContentError naming `source` when the model has no finite, non-empty geometry.
content::LoadedScene stageModel(const content::LoadedScene& loaded, const StagingOptions& options,
                                const std::string& source);

/// @brief A standalone scene around one mesh (a terrain or a generated surface): the mesh at the origin, a
/// camera near one edge looking across it from `cameraElevation` degrees (or `cameraHeight` above the
/// surface), and a low sun.
content::LoadedScene stageSurface(engine::MeshData surface, const StagingOptions& options);

} // namespace corpus
