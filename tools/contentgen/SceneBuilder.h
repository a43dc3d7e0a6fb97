#pragma once

#include <content/GltfLoader.h>

#include <engine/Scene.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace contentgen {

/// @brief Builds one scene: meshes, subdivision surfaces referring to the cages, a camera and lights.
class SceneBuilder {
public:
    explicit SceneBuilder(std::filesystem::path cagesFolder);

    engine::EntityId ground(float size, glm::vec3 color = {0.75f, 0.75f, 0.72f});

    /// @brief A subdivision surface of cage `cageName` at `level`; the stored mesh is a level-1 preview for
    /// other viewers.
    engine::EntityId surface(const std::string& name, const std::string& cageName, int level, glm::vec3 color,
                             glm::vec3 translation, float scale = 1.0f);

    /// @brief The mesh `make()` builds, in `color`, made once per (`shape`, colour): entities that share it
    /// share one glTF mesh, so repeated objects cost the file a node each.
    std::shared_ptr<engine::MeshData> shape(const std::string& shape, glm::vec3 color,
                                            const std::function<engine::MeshData()>& make);

    /// @brief An entity drawing `mesh` with `transform`, under `parent` when given.
    engine::EntityId part(const std::string& name, std::shared_ptr<engine::MeshData> mesh,
                          const engine::Transform& transform, engine::EntityId parent = engine::kNoEntity);

    /// @brief An axis-aligned box of `size` centred at `centre` (in the parent's frame), turned `yawDegrees`
    /// about +Y: a unit cube scaled, shared between boxes of one colour.
    engine::EntityId box(const std::string& name, glm::vec3 centre, glm::vec3 size, glm::vec3 color,
                         engine::EntityId parent = engine::kNoEntity, float yawDegrees = 0.0f);

    /// @brief An entity without a mesh at `translation`, turned `yawDegrees` about +Y: the parent of a group.
    engine::EntityId group(const std::string& name, glm::vec3 translation, float yawDegrees = 0.0f);

    /// @brief A directional light from `azimuthDegrees` (around +Y, 0 = from +Z) and `elevationDegrees` above
    /// the horizon.
    engine::EntityId sun(float azimuthDegrees, float elevationDegrees, float intensity = 1.1f);

    engine::EntityId spot(glm::vec3 position, glm::vec3 target, float intensity, float outerConeAngle);

    /// @brief A point light at `position`; `range` 0 is unlimited.
    engine::EntityId point(const std::string& name, glm::vec3 position, float intensity, float range,
                           glm::vec3 color = glm::vec3(1.0f));

    engine::EntityId camera(glm::vec3 eye, glm::vec3 target, float verticalFov = 0.75f,
                            float nearPlane = 0.1f, float farPlane = 60.0f);

    engine::Scene& scene() { return scene_; }

    /// @brief Writes the scene to `path` and reads it back (so the tool never emits content the engine would
    /// reject), printing its entities and triangles as loaded.
    void save(const std::filesystem::path& path) const;

private:
    std::filesystem::path cages_;
    engine::Scene scene_;
    std::vector<std::pair<engine::EntityId, content::SubdivisionTag>> tags_;
    std::map<std::pair<std::string, std::tuple<float, float, float>>, std::shared_ptr<engine::MeshData>>
        shapes_;
};

} // namespace contentgen
