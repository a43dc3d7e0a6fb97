#pragma once

#include "OrbitCamera.h"
#include "SandboxSettings.h"

#include <content/GltfLoader.h>

#include <engine/Scene.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sandbox {

/// @brief A loaded scene with the handles the sandbox steers: its first camera and its first light.
///
/// A scene without a camera gets one framing its meshes, a scene without a light gets a directional light
/// (each noted in warnings()). The file's camera and light transforms are kept so that settings without a
/// camera or light direction always show the scene as the file has it.
class SandboxScene {
public:
    /// @brief Loads `path` with subdivision `level` (-1 = each node's own). Throws content::ContentError.
    SandboxScene(const std::filesystem::path& path, int level);

    [[nodiscard]] const engine::Scene& scene() const { return loaded_.scene; }
    [[nodiscard]] engine::EntityId camera() const { return camera_; }
    [[nodiscard]] engine::LightType lightType() const;
    /// @brief The type of the file's first light (lightType() differs after setLightType()).
    [[nodiscard]] engine::LightType fileLightType() const { return fileLightComponent_.type; }
    /// @brief Loader warnings plus what the sandbox added.
    [[nodiscard]] const std::vector<std::string>& warnings() const { return loaded_.warnings; }
    /// @brief Triangles of every mesh.
    [[nodiscard]] std::size_t triangles() const { return triangles_; }

    /// @brief The direction the file's first light comes from (elevation clamped to
    /// ParameterTable::kElevation).
    [[nodiscard]] SandboxSettings::LightAngles fileLightAngles() const;
    /// @brief The orbit that reproduces the file's camera, orbiting the meshes' centre.
    [[nodiscard]] OrbitCamera fileOrbit() const;

    /// @brief Points the first light from `light` (or restores the file's) and places the camera at `camera`
    /// (or restores the file's). A spot light keeps its distance to the point its axis passes closest to the
    /// meshes' centre, so it swings around what it lit; a file's point light swings around the meshes' centre
    /// at its distance from it.
    void apply(const std::optional<SandboxSettings::LightAngles>& light,
               const std::optional<OrbitCamera>& camera);

    /// @brief Makes the first light a `type` light: the file's light when the file has that type, otherwise a
    /// conversion of it. A spot or point light made from a directional light has its intensity scaled by
    /// distance² (and a directional one made from them divided), so the centre stays as bright; a spot made
    /// from another type gets a cone just covering the meshes. Place a converted light with apply() and light
    /// angles (the file's transform of a directional light may sit anywhere). The soak run cycles light types
    /// so, and so does the control panel's light type choice.
    void setLightType(engine::LightType type);

    /// @brief The first light's size: a sun's angular diameter (radians), a spot or point light's radius.
    [[nodiscard]] float lightSize() const;
    /// @brief Sets the first light's size (as lightSize()), clamped to what a file may hold (a sun's below
    /// 90°, a local light's below its range): soft shadows (pcss) and their truth follow it; 0 casts hard
    /// ones.
    void setLightSize(float size);

    /// @brief Moves the first mesh entity by `offset` from where the file has it (zero puts it back): a
    /// moving caster for the soak run's virtual maps.
    void offsetFirstMesh(const glm::vec3& offset);

private:
    content::LoadedScene loaded_;
    engine::EntityId camera_ = engine::kNoEntity;
    engine::EntityId light_ = engine::kNoEntity;
    engine::EntityId firstMesh_ = engine::kNoEntity;
    glm::vec3 firstMeshTranslation_{0.0f};
    engine::Transform fileCamera_;
    engine::Transform fileLight_;
    engine::LightComponent fileLightComponent_;
    glm::vec3 centre_{0.0f};
    float radius_ = 1.0f;
    glm::vec3 lightPivot_{0.0f};
    float lightDistance_ = 1.0f;
    std::size_t triangles_ = 0;
};

} // namespace sandbox
