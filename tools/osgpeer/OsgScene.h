#pragma once

#include <engine/Scene.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <osg/Group>
#include <osg/LightSource>
#include <osg/Matrixd>
#include <osg/StateSet>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace osgpeer {

/// @brief The scene cannot be rendered as asked (no camera, no directional light, no meshes, bad indices).
/// The message names the scene file and what is missing or wrong.
class PeerError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief An engine::Scene rebuilt as an OpenSceneGraph graph, plus the camera and light it is seen with.
struct OsgScene {
    /// One MatrixTransform per mesh entity (world matrix), meshes shared between entities share geometry.
    osg::ref_ptr<osg::Group> meshes;
    /// The scene's first directional light as OpenGL light 0 (position = direction towards the light, w = 0;
    /// direction = lightDirection).
    osg::ref_ptr<osg::LightSource> light;
    /// Lighting state shared by the unshadowed and shadowed graphs: lighting on, light 0 on, light-model
    /// ambient 0, one-sided lighting, white diffuse material without ambient, specular or emission.
    osg::ref_ptr<osg::StateSet> lighting;
    osg::Matrixd view;
    osg::Matrixd projection;
    /// Direction the light shines along, world space, unit length.
    glm::vec3 lightDirection{0.0f};
    std::size_t triangles = 0;
    /// Geometry instances drawn per frame (one per mesh entity).
    std::size_t drawables = 0;
};

/// @brief Builds the OSG graph for `scene`: its meshes (flat normals where the mesh has none), its first
/// camera for a `size` viewport and its first directional light.
/// @param sourceName Names the scene in errors, e.g. its file path.
/// @throws PeerError naming `sourceName` when there is no camera, no directional light, no mesh, or a mesh
/// indexes past its positions.
[[nodiscard]] OsgScene buildOsgScene(const engine::Scene& scene, const std::string& sourceName,
                                     glm::ivec2 size);

/// @brief Plain graph without shadows: the light source and the meshes under the lighting state.
[[nodiscard]] osg::ref_ptr<osg::Group> unshadowedGraph(const OsgScene& scene);

} // namespace osgpeer
