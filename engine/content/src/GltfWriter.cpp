#include "content/ContentError.h"
#include "content/GltfLoader.h"

#include <engine/AtomicFile.h>
#include <engine/Error.h>

#include <tiny_gltf.h>

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <map>

namespace content {

namespace {

using engine::EntityId;

class GltfModelBuilder {
public:
    explicit GltfModelBuilder(const engine::Scene& scene) : scene_(scene) {
        model_.asset.version = "2.0";
        model_.asset.generator = "gradient-shadows GltfWriter";
        model_.buffers.emplace_back();
    }

    tinygltf::Model build(const std::vector<std::pair<EntityId, SubdivisionTag>>& subdivided) {
        for (const auto& [entity, tag] : subdivided) {
            tags_[entity] = &tag;
        }
        tinygltf::Scene root;
        scene_.forEach([&](EntityId id, const engine::Entity& entity) {
            model_.nodes.push_back(node(id, entity));
            if (entity.parent == engine::kNoEntity) {
                root.nodes.push_back(static_cast<int>(id));
            }
        });
        model_.scenes.push_back(root);
        model_.defaultScene = 0;
        if (!model_.lights.empty()) {
            model_.extensionsUsed.push_back("KHR_lights_punctual");
        }
        return std::move(model_);
    }

private:
    tinygltf::Node node(EntityId id, const engine::Entity& entity) {
        tinygltf::Node node;
        node.name = entity.name;
        for (EntityId child : entity.children) {
            node.children.push_back(static_cast<int>(child));
        }
        const engine::Transform& t = entity.transform;
        node.translation = {t.translation.x, t.translation.y, t.translation.z};
        node.rotation = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
        node.scale = {t.scale.x, t.scale.y, t.scale.z};
        if (entity.mesh && entity.mesh->mesh) {
            node.mesh = mesh(*entity.mesh->mesh);
        }
        if (entity.camera) {
            node.camera = camera(*entity.camera);
        }
        if (entity.light) {
            tinygltf::Value::Object extension{{"light", tinygltf::Value(light(entity.name, *entity.light))}};
            node.extensions["KHR_lights_punctual"] = tinygltf::Value(extension);
        }
        if (const auto tag = tags_.find(id); tag != tags_.end()) {
            tinygltf::Value::Object subdivision{{"scheme", tinygltf::Value(tag->second->scheme)},
                                                {"level", tinygltf::Value(tag->second->level)}};
            if (!tag->second->cage.empty()) {
                subdivision["cage"] = tinygltf::Value(tag->second->cage);
            }
            node.extras =
                tinygltf::Value(tinygltf::Value::Object{{"subdivision", tinygltf::Value(subdivision)}});
        }
        return node;
    }

    int mesh(const engine::MeshData& data) {
        if (const auto found = meshes_.find(&data); found != meshes_.end()) {
            return found->second;
        }
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.attributes["POSITION"] = vec3Accessor(data.positions, true);
        if (data.normals.size() == data.positions.size()) {
            primitive.attributes["NORMAL"] = vec3Accessor(data.normals, false);
        }
        primitive.indices = indexAccessor(data.indices);
        primitive.material = material(data.material);
        tinygltf::Mesh mesh;
        mesh.name = data.name;
        mesh.primitives.push_back(primitive);
        model_.meshes.push_back(mesh);
        return meshes_[&data] = static_cast<int>(model_.meshes.size() - 1);
    }

    int append(const void* bytes, std::size_t size, int target) {
        auto& buffer = model_.buffers.front().data;
        while (buffer.size() % 4 != 0) { // keep every view 4-byte aligned (glTF 2.0, 3.6.2.4)
            buffer.push_back(0);
        }
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = size;
        view.target = target;
        buffer.insert(buffer.end(), static_cast<const unsigned char*>(bytes),
                      static_cast<const unsigned char*>(bytes) + size);
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size() - 1);
    }

    int vec3Accessor(const std::vector<glm::vec3>& values, bool withBounds) {
        tinygltf::Accessor accessor;
        accessor.bufferView =
            append(values.data(), values.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = TINYGLTF_TYPE_VEC3;
        accessor.count = values.size();
        if (withBounds && !values.empty()) { // POSITION requires min and max (glTF 2.0, 3.7.2.1)
            glm::vec3 low = values.front();
            glm::vec3 high = values.front();
            for (const glm::vec3& v : values) {
                low = glm::min(low, v);
                high = glm::max(high, v);
            }
            accessor.minValues = {low.x, low.y, low.z};
            accessor.maxValues = {high.x, high.y, high.z};
        }
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size() - 1);
    }

    int indexAccessor(const std::vector<std::uint32_t>& indices) {
        tinygltf::Accessor accessor;
        accessor.bufferView = append(indices.data(), indices.size() * sizeof(std::uint32_t),
                                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.type = TINYGLTF_TYPE_SCALAR;
        accessor.count = indices.size();
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size() - 1);
    }

    int material(const engine::Material& source) {
        tinygltf::Material material;
        material.pbrMetallicRoughness.baseColorFactor = {source.baseColor.r, source.baseColor.g,
                                                         source.baseColor.b, 1.0};
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        // Inverse of the loader's Blinn-Phong mapping s = 2/r^4 - 2.
        material.pbrMetallicRoughness.roughnessFactor =
            std::pow(2.0 / (std::max(source.shininess, 0.0f) + 2.0), 0.25);
        model_.materials.push_back(material);
        return static_cast<int>(model_.materials.size() - 1);
    }

    int camera(const engine::CameraComponent& source) {
        tinygltf::Camera camera;
        if (source.projection == engine::ProjectionType::Perspective) {
            camera.type = "perspective";
            camera.perspective.yfov = source.verticalFov;
            camera.perspective.znear = source.nearPlane;
            camera.perspective.zfar = source.farPlane;
            camera.perspective.aspectRatio = 0.0; // the viewport decides
        } else {
            camera.type = "orthographic";
            camera.orthographic.ymag = source.orthographicHeight * 0.5;
            camera.orthographic.xmag = source.orthographicHeight * 0.5;
            camera.orthographic.znear = source.nearPlane;
            camera.orthographic.zfar = source.farPlane;
        }
        model_.cameras.push_back(camera);
        return static_cast<int>(model_.cameras.size() - 1);
    }

    /// A KHR_lights_punctual light named after its entity, so the loader's messages can name it.
    int light(const std::string& name, const engine::LightComponent& source) {
        tinygltf::Light light;
        light.name = name;
        light.color = {source.color.r, source.color.g, source.color.b};
        light.intensity = source.intensity;
        light.type = engine::toString(source.type);
        // Written only for spot lights by tinygltf.
        light.spot.innerConeAngle = source.innerConeAngle;
        light.spot.outerConeAngle = source.outerConeAngle;
        // Range belongs to spot and point lights; tinygltf leaves out a range of 0 (unlimited), as the spec
        // asks (range must be > 0 when present).
        if (source.type != engine::LightType::Directional) {
            light.range = source.range;
        }
        tinygltf::Value::Object extras;
        if (!source.castsShadows) {
            extras["castsShadows"] = tinygltf::Value(false);
        }
        // The size where it is not the default (GltfLoader reads it back).
        if (source.type == engine::LightType::Directional &&
            source.angularDiameter != engine::LightComponent::kSunAngularDiameter) {
            extras["angularDiameter"] = tinygltf::Value(static_cast<double>(source.angularDiameter));
        } else if (source.type != engine::LightType::Directional && source.radius != 0.0f) {
            extras["radius"] = tinygltf::Value(static_cast<double>(source.radius));
        }
        if (!extras.empty()) {
            light.extras = tinygltf::Value(std::move(extras));
        }
        model_.lights.push_back(light);
        return static_cast<int>(model_.lights.size() - 1);
    }

    const engine::Scene& scene_;
    tinygltf::Model model_;
    std::map<const engine::MeshData*, int> meshes_;
    std::map<EntityId, const SubdivisionTag*> tags_;
};

} // namespace

void GltfWriter::save(const engine::Scene& scene, const std::filesystem::path& path,
                      const std::vector<std::pair<EntityId, SubdivisionTag>>& subdivided) {
    tinygltf::Model model = GltfModelBuilder(scene).build(subdivided);
    const bool binary = path.extension() == ".glb";
    try {
        engine::writeAtomically(path, [&](const std::filesystem::path& temporary) {
            tinygltf::TinyGLTF writer;
            return writer.WriteGltfSceneToFile(&model, temporary.string(), false, true, !binary, binary);
        });
    } catch (const engine::IoError& error) {
        throw ContentError(path.string(), std::string("cannot write glTF: ") + error.what());
    }
}

} // namespace content
