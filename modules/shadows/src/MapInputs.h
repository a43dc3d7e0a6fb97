#pragma once

#include <shadows/LightFrustum.h>

#include <engine/FrameContext.h>
#include <engine/MeshData.h>

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace shadows {

/// @brief Everything a frame's shadow maps are drawn from: the view they are fitted to and its
/// target's size (the sample pass), each light, and every mesh with its world matrix. A frame whose inputs
/// equal the last frame's would fit and draw the same maps, so it keeps them
/// (ShadowSettings::reuseUnchangedMaps). Mesh data is immutable (an edited mesh is a new MeshData), so which
/// MeshData it is names its content: the inputs hold it weakly and compare owners, which no later mesh
/// shares, without keeping a mesh alive.
struct MapInputs {
    struct Mesh {
        engine::EntityId entity = engine::kNoEntity;
        glm::mat4 model{1.0f};
        std::weak_ptr<const engine::MeshData> data;
        bool operator==(const Mesh& other) const {
            return entity == other.entity && model == other.model && !data.owner_before(other.data) &&
                   !other.data.owner_before(data);
        }
    };

    FitView fit;
    glm::ivec2 targetSize{0};
    std::vector<engine::FrameLight> lights;
    std::vector<Mesh> meshes;

    bool operator==(const MapInputs&) const = default;
    /// Whether `other` has the same lights and meshes, whatever the view: what the maps hold is then the same
    /// wherever they are placed alike.
    [[nodiscard]] bool sameScene(const MapInputs& other) const {
        return lights == other.lights && meshes == other.meshes;
    }
};

} // namespace shadows
