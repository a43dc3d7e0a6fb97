#include "content/GltfLoader.h"

#include "content/CageLoader.h"
#include "content/ContentError.h"
#include "content/SubdivisionSurface.h"

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>

namespace content {

namespace {

using engine::EntityId;

/// Reads one glTF file into tinygltf's model and maps the parts we use onto an engine::Scene.
class GltfSceneBuilder {
public:
    GltfSceneBuilder(std::filesystem::path path, const SceneLoadOptions& options)
        : path_(std::move(path)), source_(path_.string()), options_(options) {}

    LoadedScene build() {
        readModel();
        if (model_.scenes.empty()) {
            // A file without scenes still describes nodes: show every root node.
            std::vector<bool> isChild(model_.nodes.size(), false);
            for (const auto& node : model_.nodes) {
                for (int child : node.children) {
                    if (child >= 0 && static_cast<std::size_t>(child) < isChild.size()) {
                        isChild[static_cast<std::size_t>(child)] = true;
                    }
                }
            }
            for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
                if (!isChild[i]) {
                    addNode(static_cast<int>(i), engine::kNoEntity, 0);
                }
            }
        } else {
            const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (static_cast<std::size_t>(sceneIndex) >= model_.scenes.size()) {
                fail("scene " + std::to_string(sceneIndex) + " (the default scene) does not exist");
            }
            for (int node : model_.scenes[static_cast<std::size_t>(sceneIndex)].nodes) {
                addNode(node, engine::kNoEntity, 0);
            }
        }
        return std::move(result_);
    }

private:
    [[noreturn]] void fail(const std::string& detail) const { throw ContentError(source_, detail); }

    void readModel() {
        std::error_code error;
        if (!std::filesystem::is_regular_file(path_, error)) {
            fail("file not found");
        }
        tinygltf::TinyGLTF loader;
        // Textures are not used: skip decoding images (and failing on formats we cannot read).
        loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                                 const unsigned char*, int, void*) { return true; },
                              nullptr);
        std::string errors;
        std::string warnings;
        bool ok = false;
        if (isBinary()) {
            ok = loader.LoadBinaryFromFile(&model_, &errors, &warnings, path_.string());
        } else {
            ok = loader.LoadASCIIFromFile(&model_, &errors, &warnings, path_.string());
        }
        if (!ok) {
            fail("not a valid glTF 2.0 file: " +
                 (errors.empty() ? std::string("unknown error") : trim(errors)));
        }
        if (!warnings.empty()) {
            result_.warnings.push_back(trim(warnings));
        }
    }

    bool isBinary() const {
        std::ifstream file(path_, std::ios::binary);
        char magic[4] = {};
        file.read(magic, 4);
        return file.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
    }

    static std::string trim(std::string text) {
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
            text.pop_back();
        }
        return text;
    }

    template <typename T>
    const T& at(const std::vector<T>& items, int index, const std::string& what) const {
        if (index < 0 || static_cast<std::size_t>(index) >= items.size()) {
            fail(what + " " + std::to_string(index) + " does not exist (the file has " +
                 std::to_string(items.size()) + ")");
        }
        return items[static_cast<std::size_t>(index)];
    }

    void addNode(int index, EntityId parent, int depth) {
        // glTF forbids cycles; a malformed file could still contain one.
        if (depth > 256) {
            fail("node " + std::to_string(index) + " is nested more than 256 deep (a cycle in 'children'?)");
        }
        const tinygltf::Node& node = at(model_.nodes, index, "node");
        const std::string field = "nodes[" + std::to_string(index) + "]";
        const EntityId entity =
            result_.scene.create(node.name.empty() ? "node" + std::to_string(index) : node.name, parent);
        result_.scene.entity(entity).transform = nodeTransform(node, field);

        if (node.camera >= 0) {
            result_.scene.entity(entity).camera = camera(at(model_.cameras, node.camera, field + ".camera"));
        }
        if (const auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end()) {
            addLight(entity, light->second, field);
        }
        if (node.mesh >= 0) {
            addMesh(entity, node, field);
        }
        for (int child : node.children) {
            addNode(child, entity, depth + 1);
        }
    }

    engine::Transform nodeTransform(const tinygltf::Node& node, const std::string& field) const {
        engine::Transform transform;
        auto finite = [&](const std::vector<double>& values, std::size_t size, const char* name) {
            if (values.empty()) {
                return false;
            }
            if (values.size() != size ||
                !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
                fail(field + "." + name + " must hold " + std::to_string(size) + " finite numbers");
            }
            return true;
        };
        if (finite(node.matrix, 16, "matrix")) {
            glm::dmat4 matrix = glm::make_mat4(node.matrix.data());
            glm::dvec3 scale;
            glm::dquat rotation;
            glm::dvec3 translation;
            glm::dvec3 skew;
            glm::dvec4 perspective;
            if (!glm::decompose(matrix, scale, rotation, translation, skew, perspective)) {
                fail(field + ".matrix is singular or not an affine transform");
            }
            transform.translation = glm::vec3(translation);
            transform.rotation = glm::quat(rotation);
            transform.scale = glm::vec3(scale);
            return transform;
        }
        if (finite(node.translation, 3, "translation")) {
            transform.translation = glm::vec3(glm::make_vec3(node.translation.data()));
        }
        if (finite(node.rotation, 4, "rotation")) {
            // glTF stores quaternions as x, y, z, w.
            const auto& r = node.rotation;
            transform.rotation =
                glm::normalize(glm::quat(static_cast<float>(r[3]), static_cast<float>(r[0]),
                                         static_cast<float>(r[1]), static_cast<float>(r[2])));
        }
        if (finite(node.scale, 3, "scale")) {
            transform.scale = glm::vec3(glm::make_vec3(node.scale.data()));
        }
        return transform;
    }

    engine::CameraComponent camera(const tinygltf::Camera& source) const {
        engine::CameraComponent camera;
        if (source.type == "perspective") {
            camera.projection = engine::ProjectionType::Perspective;
            camera.verticalFov = static_cast<float>(source.perspective.yfov);
            camera.nearPlane = static_cast<float>(source.perspective.znear);
            // An infinite far plane (no zfar) is approximated: depth precision needs a finite one.
            camera.farPlane = source.perspective.zfar > 0.0 ? static_cast<float>(source.perspective.zfar)
                                                            : camera.nearPlane * 1e4f;
        } else if (source.type == "orthographic") {
            camera.projection = engine::ProjectionType::Orthographic;
            camera.orthographicHeight = 2.0f * static_cast<float>(source.orthographic.ymag);
            camera.nearPlane = static_cast<float>(source.orthographic.znear);
            camera.farPlane = static_cast<float>(source.orthographic.zfar);
        } else {
            fail("camera '" + source.name + "' has unknown type '" + source.type + "'");
        }
        if (!(camera.nearPlane >= 0.0f) || !(camera.farPlane > camera.nearPlane) ||
            !std::isfinite(camera.farPlane)) {
            fail("camera '" + source.name + "' needs 0 <= znear < zfar");
        }
        if (camera.projection == engine::ProjectionType::Perspective &&
            (!(camera.nearPlane > 0.0f) || !(camera.verticalFov > 0.0f && camera.verticalFov < 3.14159f))) {
            fail("camera '" + source.name + "' needs znear > 0 and 0 < yfov < pi");
        }
        return camera;
    }

    void addLight(EntityId entity, const tinygltf::Value& extension, const std::string& field) {
        if (!extension.IsObject() || !extension.Has("light") || !extension.Get("light").IsInt()) {
            fail(field + ".extensions.KHR_lights_punctual needs an integer 'light'");
        }
        const int index = extension.Get("light").GetNumberAsInt();
        const tinygltf::Light& source = at(model_.lights, index, field + " light");
        engine::LightComponent light;
        if (source.type == "directional") {
            light.type = engine::LightType::Directional;
        } else if (source.type == "spot") {
            light.type = engine::LightType::Spot;
            light.innerConeAngle = static_cast<float>(source.spot.innerConeAngle);
            light.outerConeAngle = static_cast<float>(source.spot.outerConeAngle);
            if (!(light.innerConeAngle >= 0.0f && light.innerConeAngle <= light.outerConeAngle &&
                  light.outerConeAngle <= 1.5708f)) {
                fail("light " + std::to_string(index) +
                     " needs 0 <= innerConeAngle <= outerConeAngle <= pi/2");
            }
        } else {
            result_.warnings.push_back(source_ + ": light " + std::to_string(index) + " ('" + source.name +
                                       "') is a " + source.type +
                                       " light; only directional and spot lights are "
                                       "supported, so it was left out");
            return;
        }
        if (source.color.size() == 3) {
            light.color = glm::vec3(glm::make_vec3(source.color.data()));
        }
        light.intensity = static_cast<float>(source.intensity);
        light.range = static_cast<float>(source.range);
        if (!std::isfinite(light.intensity) || light.intensity < 0.0f || !std::isfinite(light.range) ||
            light.range < 0.0f) {
            fail("light " + std::to_string(index) + " needs a finite, non-negative intensity and range");
        }
        if (source.extras.IsObject() && source.extras.Has("castsShadows")) {
            light.castsShadows = source.extras.Get("castsShadows").Get<bool>();
        }
        result_.scene.entity(entity).light = light;
    }

    /// Copies accessor `index` element by element, checking every offset against its view and buffer.
    template <typename Element>
    std::vector<Element> readFloatAccessor(int index, int expectedType, const std::string& field) const {
        const tinygltf::Accessor& accessor = at(model_.accessors, index, field + " accessor");
        const std::string where = "accessors[" + std::to_string(index) + "] (" + field + ")";
        if (accessor.type != expectedType || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
            fail(where + " must be " + (expectedType == TINYGLTF_TYPE_VEC3 ? "VEC3" : "VEC4") +
                 " of FLOAT (quantised attributes are not supported)");
        }
        std::vector<Element> values(accessor.count);
        copyElements(accessor, where, sizeof(Element), [&](std::size_t i, const unsigned char* bytes) {
            std::memcpy(&values[i], bytes, sizeof(Element));
        });
        return values;
    }

    std::vector<std::uint32_t> readIndices(int index, const std::string& field) const {
        const tinygltf::Accessor& accessor = at(model_.accessors, index, field + " accessor");
        const std::string where = "accessors[" + std::to_string(index) + "] (" + field + ")";
        if (accessor.type != TINYGLTF_TYPE_SCALAR) {
            fail(where + " must be SCALAR");
        }
        std::size_t size = 0;
        switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            size = 1;
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            size = 2;
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            size = 4;
            break;
        default:
            fail(where + " must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        }
        std::vector<std::uint32_t> values(accessor.count);
        copyElements(accessor, where, size, [&](std::size_t i, const unsigned char* bytes) {
            if (size == 1) {
                values[i] = bytes[0];
            } else if (size == 2) {
                std::uint16_t value = 0;
                std::memcpy(&value, bytes, 2);
                values[i] = value;
            } else {
                std::memcpy(&values[i], bytes, 4);
            }
        });
        return values;
    }

    template <typename Visit>
    void copyElements(const tinygltf::Accessor& accessor, const std::string& where, std::size_t elementSize,
                      Visit visit) const {
        if (accessor.sparse.isSparse) {
            fail(where + " is sparse; sparse accessors are not supported");
        }
        if (accessor.count == 0) {
            return;
        }
        if (accessor.bufferView < 0) {
            fail(where + " has no bufferView (all-zero data is not supported for geometry)");
        }
        const tinygltf::BufferView& view = at(model_.bufferViews, accessor.bufferView, where + " bufferView");
        const tinygltf::Buffer& buffer = at(model_.buffers, view.buffer, "bufferView buffer");
        const std::uint64_t stride = view.byteStride ? view.byteStride : elementSize;
        if (stride < elementSize) {
            fail(where + ": bufferView.byteStride " + std::to_string(stride) +
                 " is smaller than one element");
        }
        const std::uint64_t viewEnd = static_cast<std::uint64_t>(view.byteOffset) + view.byteLength;
        if (viewEnd > buffer.data.size()) {
            fail(where + ": bufferView " + std::to_string(accessor.bufferView) + " ends at byte " +
                 std::to_string(viewEnd) + " beyond its buffer of " + std::to_string(buffer.data.size()) +
                 " bytes");
        }
        const std::uint64_t start = static_cast<std::uint64_t>(view.byteOffset) + accessor.byteOffset;
        // count is at most what fits in the view, so this product cannot overflow 64 bits for a valid view.
        const std::uint64_t last =
            start + stride * (static_cast<std::uint64_t>(accessor.count) - 1) + elementSize;
        if (accessor.count > viewEnd || last > viewEnd) {
            fail(where + ": " + std::to_string(accessor.count) + " elements overrun bufferView " +
                 std::to_string(accessor.bufferView) + " (accessor out of bounds)");
        }
        for (std::size_t i = 0; i < accessor.count; ++i) {
            visit(i, buffer.data.data() + start + stride * i);
        }
    }

    engine::Material material(int index, const std::string& field) const {
        engine::Material result;
        if (index < 0) {
            return result;
        }
        const tinygltf::Material& source = at(model_.materials, index, field + ".material");
        const auto& pbr = source.pbrMetallicRoughness;
        const glm::vec3 base = pbr.baseColorFactor.size() >= 3
                                   ? glm::vec3(glm::make_vec3(pbr.baseColorFactor.data()))
                                   : glm::vec3(1.0f);
        const float metallic = glm::clamp(static_cast<float>(pbr.metallicFactor), 0.0f, 1.0f);
        const float roughness = glm::clamp(static_cast<float>(pbr.roughnessFactor), 0.05f, 1.0f);
        // Metals tint their highlight and have no diffuse; dielectrics reflect ~4 % (Real-Time Rendering, 4th
        // ed., 9.5). Roughness maps to a Blinn-Phong exponent by 2/r^4 - 2 (Walter et al. 2007, Beckmann
        // equivalence).
        result.baseColor = base * (1.0f - metallic);
        result.specularColor = glm::mix(glm::vec3(0.04f), base, metallic);
        result.shininess = std::min(2.0f / std::pow(roughness, 4.0f) - 2.0f, 2048.0f);
        return result;
    }

    engine::MeshData primitiveMesh(const tinygltf::Mesh& mesh, std::size_t primitiveIndex,
                                   const std::string& field) {
        const tinygltf::Primitive& primitive = mesh.primitives[primitiveIndex];
        const std::string where = field + ".primitives[" + std::to_string(primitiveIndex) + "]";
        engine::MeshData data;
        data.name = mesh.name.empty() ? where : mesh.name;
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) {
            fail(where + " has no POSITION attribute");
        }
        data.positions =
            readFloatAccessor<glm::vec3>(position->second, TINYGLTF_TYPE_VEC3, where + ".POSITION");
        for (std::size_t i = 0; i < data.positions.size(); ++i) {
            const glm::vec3& p = data.positions[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                fail(where + ".POSITION vertex " + std::to_string(i) + " is not finite");
            }
        }
        if (const auto normal = primitive.attributes.find("NORMAL"); normal != primitive.attributes.end()) {
            data.normals =
                readFloatAccessor<glm::vec3>(normal->second, TINYGLTF_TYPE_VEC3, where + ".NORMAL");
            if (data.normals.size() != data.positions.size()) {
                fail(where + ".NORMAL has " + std::to_string(data.normals.size()) + " entries for " +
                     std::to_string(data.positions.size()) + " positions");
            }
            for (glm::vec3& n : data.normals) {
                const float length = glm::length(n);
                // A zero or broken normal falls back to the renderer's face normal path via an empty array.
                if (!std::isfinite(length) || length < 1e-12f) {
                    data.normals.clear();
                    result_.warnings.push_back(source_ + ": " + where +
                                               ".NORMAL has zero or non-finite normals; "
                                               "faceted shading used");
                    break;
                }
                n /= length;
            }
        }
        std::vector<std::uint32_t> indices;
        if (primitive.indices >= 0) {
            indices = readIndices(primitive.indices, where + ".indices");
        } else {
            indices.resize(data.positions.size());
            for (std::uint32_t i = 0; i < indices.size(); ++i) {
                indices[i] = i;
            }
        }
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] >= data.positions.size()) {
                fail(where + ".indices[" + std::to_string(i) + "] = " + std::to_string(indices[i]) +
                     " is out of range (" + std::to_string(data.positions.size()) + " vertices)");
            }
        }
        data.indices = triangulate(primitive.mode, indices, where);
        data.material = material(primitive.material, where);
        return data;
    }

    std::vector<std::uint32_t> triangulate(int mode, const std::vector<std::uint32_t>& indices,
                                           const std::string& where) const {
        std::vector<std::uint32_t> triangles;
        switch (mode) {
        case TINYGLTF_MODE_TRIANGLES:
            if (indices.size() % 3 != 0) {
                fail(where + ": " + std::to_string(indices.size()) + " indices do not form whole triangles");
            }
            return indices;
        case TINYGLTF_MODE_TRIANGLE_STRIP:
            for (std::size_t i = 2; i < indices.size(); ++i) {
                // Every second strip triangle is flipped to keep the winding consistent (glTF 2.0, 3.7.2.1).
                if (i % 2 == 0) {
                    triangles.insert(triangles.end(), {indices[i - 2], indices[i - 1], indices[i]});
                } else {
                    triangles.insert(triangles.end(), {indices[i - 1], indices[i - 2], indices[i]});
                }
            }
            return triangles;
        case TINYGLTF_MODE_TRIANGLE_FAN:
            for (std::size_t i = 2; i < indices.size(); ++i) {
                triangles.insert(triangles.end(), {indices[i - 1], indices[i], indices[0]});
            }
            return triangles;
        default:
            return {}; // points and lines carry no surface to light or shadow
        }
    }

    void addMesh(EntityId entity, const tinygltf::Node& node, const std::string& field) {
        const tinygltf::Mesh& mesh = at(model_.meshes, node.mesh, field + ".mesh");
        const std::string meshField = "meshes[" + std::to_string(node.mesh) + "]";
        std::vector<std::shared_ptr<engine::MeshData>> parts;
        for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
            auto data = std::make_shared<engine::MeshData>(primitiveMesh(mesh, i, meshField));
            if (data->indices.empty()) {
                result_.warnings.push_back(source_ + ": " + meshField + ".primitives[" + std::to_string(i) +
                                           "] has no triangles (points or lines) and was left out");
                continue;
            }
            parts.push_back(std::move(data));
        }
        if (auto tag = subdivisionTag(node, field)) {
            auto surface = std::make_shared<engine::MeshData>(subdivideNamingNode(*tag, parts, field));
            surface->material = parts.empty() ? engine::Material{} : parts.front()->material;
            surface->name = mesh.name.empty() ? meshField : mesh.name;
            result_.scene.entity(entity).mesh = engine::MeshComponent{surface};
            result_.subdivided.emplace_back(entity, *tag);
            return;
        }
        if (parts.size() == 1) {
            result_.scene.entity(entity).mesh = engine::MeshComponent{parts.front()};
            return;
        }
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const EntityId child = result_.scene.create(
                result_.scene.entity(entity).name + "/primitive" + std::to_string(i), entity);
            result_.scene.entity(child).mesh = engine::MeshComponent{parts[i]};
        }
    }

    std::optional<SubdivisionTag> subdivisionTag(const tinygltf::Node& node, const std::string& field) const {
        if (!node.extras.IsObject() || !node.extras.Has("subdivision")) {
            return std::nullopt;
        }
        const tinygltf::Value& value = node.extras.Get("subdivision");
        const std::string where = field + ".extras.subdivision";
        if (!value.IsObject()) {
            fail(where + " must be an object");
        }
        SubdivisionTag tag;
        if (value.Has("scheme")) {
            tag.scheme = value.Get("scheme").IsString() ? value.Get("scheme").Get<std::string>() : "";
            if (tag.scheme != "catmull-clark" && tag.scheme != "loop") {
                fail(where + ".scheme must be \"catmull-clark\" or \"loop\"");
            }
        }
        if (value.Has("level")) {
            const tinygltf::Value& level = value.Get("level");
            if (!level.IsInt() || level.GetNumberAsInt() < 0 ||
                level.GetNumberAsInt() > SubdivisionSurface::kMaxLevel) {
                fail(where + ".level must be an integer in [0, " +
                     std::to_string(SubdivisionSurface::kMaxLevel) + "]");
            }
            tag.level = level.GetNumberAsInt();
        }
        if (value.Has("cage")) {
            if (!value.Get("cage").IsString() || value.Get("cage").Get<std::string>().empty()) {
                fail(where + ".cage must be a file name");
            }
            tag.cage = value.Get("cage").Get<std::string>();
        }
        return tag;
    }

    engine::MeshData subdivide(const SubdivisionTag& tag,
                               const std::vector<std::shared_ptr<engine::MeshData>>& parts,
                               const std::string& field) const {
        const Scheme scheme = tag.scheme == "loop" ? Scheme::Loop : Scheme::CatmullClark;
        Cage cage;
        if (!tag.cage.empty()) {
            cage = CageLoader::load(path_.parent_path() / tag.cage, scheme);
        } else {
            if (parts.empty()) {
                fail(field + " is flagged for subdivision but has no triangles and no 'cage' file");
            }
            cage = weldedCage(parts, field);
            cage.scheme = scheme;
        }
        const int level = options_.subdivisionLevel >= 0 ? options_.subdivisionLevel : tag.level;
        return SubdivisionSurface(std::move(cage)).evaluate(level).mesh;
    }

    /// Cage problems name the cage file; prefix the glTF file and node that asked for it.
    engine::MeshData subdivideNamingNode(const SubdivisionTag& tag,
                                         const std::vector<std::shared_ptr<engine::MeshData>>& parts,
                                         const std::string& field) const {
        try {
            return subdivide(tag, parts, field);
        } catch (const ContentError& error) {
            fail(field + ".extras.subdivision: " + error.what());
        }
    }

    /// Triangles of every part as one cage, with vertices at identical positions merged so the cage is
    /// connected across the seams that glTF's per-vertex attributes introduce.
    Cage weldedCage(const std::vector<std::shared_ptr<engine::MeshData>>& parts,
                    const std::string& field) const {
        Cage cage;
        cage.source = source_ + " " + field;
        std::map<std::tuple<float, float, float>, std::uint32_t> index;
        for (const auto& part : parts) {
            std::vector<std::uint32_t> remap(part->positions.size());
            for (std::size_t i = 0; i < part->positions.size(); ++i) {
                const glm::vec3& p = part->positions[i];
                const auto [it, added] = index.emplace(std::tuple{p.x, p.y, p.z},
                                                       static_cast<std::uint32_t>(cage.positions.size()));
                if (added) {
                    cage.positions.push_back(p);
                }
                remap[i] = it->second;
            }
            for (std::size_t t = 0; t + 2 < part->indices.size(); t += 3) {
                cage.faces.push_back(
                    {remap[part->indices[t]], remap[part->indices[t + 1]], remap[part->indices[t + 2]]});
            }
        }
        return cage;
    }

    std::filesystem::path path_;
    std::string source_;
    SceneLoadOptions options_;
    tinygltf::Model model_;
    LoadedScene result_;
};

} // namespace

LoadedScene GltfLoader::load(const std::filesystem::path& path, const SceneLoadOptions& options) {
    if (options.subdivisionLevel < -1 || options.subdivisionLevel > SubdivisionSurface::kMaxLevel) {
        throw ContentError(path.string(), "subdivision level " + std::to_string(options.subdivisionLevel) +
                                              " is outside [-1, " +
                                              std::to_string(SubdivisionSurface::kMaxLevel) + "]");
    }
    return GltfSceneBuilder(path, options).build();
}

} // namespace content
