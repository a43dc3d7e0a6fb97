#include "OsgScene.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LightModel>
#include <osg/Material>
#include <osg/MatrixTransform>

#include <cmath>
#include <map>
#include <optional>

namespace osgpeer {
namespace {

// glm stores column-major with column vectors, OSG row-major with row vectors: the same 16 numbers in the
// same order describe the same transform, so a straight float-to-double copy converts.
osg::Matrixd toOsg(const glm::mat4& m) {
    return osg::Matrixd(glm::value_ptr(m));
}

osg::Vec3 toOsg(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

osg::ref_ptr<osg::Geometry> makeGeometry(const engine::MeshData& mesh, const std::string& sourceName) {
    const std::size_t vertexCount = mesh.positions.size();
    if (mesh.indices.size() % 3 != 0) {
        throw PeerError(sourceName + ": mesh '" + mesh.name + "' has " + std::to_string(mesh.indices.size()) +
                        " indices, not a multiple of 3");
    }
    for (const std::uint32_t index : mesh.indices) {
        if (index >= vertexCount) {
            throw PeerError(sourceName + ": mesh '" + mesh.name + "' index " + std::to_string(index) +
                            " is past its " + std::to_string(vertexCount) + " positions");
        }
    }

    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(mesh.name);
    // Vertex buffer objects, as our renderer uses; display lists would time differently.
    geometry->setUseDisplayList(false);
    geometry->setUseVertexBufferObjects(true);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> normals = new osg::Vec3Array;

    if (mesh.normals.size() == vertexCount) {
        positions->reserve(vertexCount);
        normals->reserve(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            positions->push_back(toOsg(mesh.positions[i]));
            normals->push_back(toOsg(mesh.normals[i]));
        }
        geometry->addPrimitiveSet(
            new osg::DrawElementsUInt(GL_TRIANGLES, mesh.indices.begin(), mesh.indices.end()));
    } else {
        // No (or mismatched) normals: our renderer shades such meshes with face normals, so un-index and give
        // each triangle's three corners its own normal.
        positions->reserve(mesh.indices.size());
        normals->reserve(mesh.indices.size());
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 a = mesh.positions[mesh.indices[t]];
            const glm::vec3 b = mesh.positions[mesh.indices[t + 1]];
            const glm::vec3 c = mesh.positions[mesh.indices[t + 2]];
            const glm::vec3 cross = glm::cross(b - a, c - a);
            const float length = glm::length(cross);
            // Degenerate triangles cover no pixels; any unit normal avoids NaNs in the lighting.
            const glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f, 0.0f, 1.0f);
            for (const glm::vec3& corner : {a, b, c}) {
                positions->push_back(toOsg(corner));
                normals->push_back(toOsg(normal));
            }
        }
        geometry->addPrimitiveSet(
            new osg::DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(positions->size())));
    }
    geometry->setVertexArray(positions);
    geometry->setNormalArray(normals, osg::Array::BIND_PER_VERTEX);
    return geometry;
}

osg::ref_ptr<osg::StateSet> makeLightingState(const osg::Light& light) {
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    state->setMode(GL_LIGHTING, osg::StateAttribute::ON);
    state->setMode(GL_LIGHT0 + light.getLightNum(), osg::StateAttribute::ON);
    state->setMode(GL_NORMALIZE, osg::StateAttribute::ON); // world matrices may scale

    // OpenGL's default light-model ambient (0.2) would lift shadowed and unlit surfaces above black.
    osg::ref_ptr<osg::LightModel> model = new osg::LightModel;
    model->setAmbientIntensity(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    model->setTwoSided(false);
    model->setLocalViewer(false);
    state->setAttributeAndModes(model, osg::StateAttribute::ON);

    // White diffuse only: the shaded value is then max(N.L, 0) times the shadow term, and shadowed/unshadowed
    // isolates the shadow term.
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setColorMode(osg::Material::OFF);
    material->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    material->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    material->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    material->setShininess(osg::Material::FRONT_AND_BACK, 0.0f);
    state->setAttributeAndModes(material, osg::StateAttribute::ON);
    return state;
}

} // namespace

OsgScene buildOsgScene(const engine::Scene& scene, const std::string& sourceName, glm::ivec2 size) {
    OsgScene result;

    const std::optional<engine::EntityId> camera = scene.firstCamera();
    if (!camera) {
        throw PeerError(sourceName + ": the scene has no camera");
    }
    const glm::mat4 cameraWorld = scene.worldMatrix(*camera);
    // A zero scale (or NaN) would give a view matrix of infinities and a silently black frame.
    const float determinant = glm::determinant(cameraWorld);
    if (!std::isfinite(determinant) || std::abs(determinant) < 1e-12f) {
        throw PeerError(sourceName + ": camera '" + scene.entity(*camera).name +
                        "' has a degenerate transform (its world matrix cannot be inverted)");
    }
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    result.view = toOsg(glm::inverse(cameraWorld));
    result.projection = toOsg(scene.entity(*camera).camera->projectionMatrix(aspect));

    std::optional<engine::EntityId> lightEntity;
    scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (!lightEntity && entity.light && entity.light->type == engine::LightType::Directional) {
            lightEntity = id;
        }
    });
    if (!lightEntity) {
        throw PeerError(sourceName + ": the scene has no directional light (KHR_lights_punctual type "
                                     "\"directional\")");
    }
    // A light shines along its entity's local -Z axis.
    const glm::vec3 zAxis = glm::vec3(scene.worldMatrix(*lightEntity)[2]);
    if (!(glm::length(zAxis) > 0.0f) || !std::isfinite(glm::length(zAxis))) {
        throw PeerError(sourceName + ": directional light '" + scene.entity(*lightEntity).name +
                        "' has a degenerate transform (no direction)");
    }
    result.lightDirection = -glm::normalize(zAxis);

    osg::ref_ptr<osg::Light> light = new osg::Light(0);
    const glm::vec3 towardsLight = -result.lightDirection;
    light->setPosition(osg::Vec4(towardsLight.x, towardsLight.y, towardsLight.z, 0.0f));
    light->setAmbient(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    light->setDiffuse(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    light->setSpecular(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    // osg::Light's direction is its spot axis, which OpenGL ignores for a light with the default 180-degree
    // cutoff; ParallelSplitShadowMap reads it (not the position) as the direction the sun shines along.
    light->setDirection(toOsg(result.lightDirection));
    result.light = new osg::LightSource;
    result.light->setLight(light);
    // Position given in world space: the light source sits at the root, under the view matrix only.
    result.light->setReferenceFrame(osg::LightSource::RELATIVE_RF);
    result.lighting = makeLightingState(*light);

    result.meshes = new osg::Group;
    std::map<const engine::MeshData*, osg::ref_ptr<osg::Geode>> geodes;
    scene.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh) {
            return;
        }
        const engine::MeshData& mesh = *entity.mesh->mesh;
        if (mesh.indices.empty()) {
            return;
        }
        osg::ref_ptr<osg::Geode>& geode = geodes[&mesh];
        if (!geode) {
            geode = new osg::Geode;
            geode->addDrawable(makeGeometry(mesh, sourceName));
        }
        osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform(toOsg(scene.worldMatrix(id)));
        transform->setName(entity.name);
        transform->addChild(geode);
        result.meshes->addChild(transform);
        result.triangles += mesh.triangleCount();
        ++result.drawables;
    });
    if (result.drawables == 0) {
        throw PeerError(sourceName + ": the scene has no triangle mesh to render");
    }
    return result;
}

osg::ref_ptr<osg::Group> unshadowedGraph(const OsgScene& scene) {
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->setStateSet(scene.lighting);
    root->addChild(scene.light);
    root->addChild(scene.meshes);
    return root;
}

} // namespace osgpeer
