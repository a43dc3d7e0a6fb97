#include "content/GltfLoader.h"

#include "GltfMemberTypes.h"
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
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <sstream>
#include <type_traits>
#include <vector>

namespace content {

namespace {

using engine::EntityId;

// Deeper JSON is refused before tinygltf sees it: tinygltf converts `extras` and `extensions` values
// recursively, so a few hundred thousand nested brackets overflow the stack. Real files nest far less.
constexpr int kMaxJsonDepth = 128;

/// Fails on JSON nested more than kMaxJsonDepth deep; everything else is left for the JSON parser to judge.
void checkJsonNesting(std::span<const std::uint8_t> json, const std::string& source) {
    int depth = 0;
    bool inString = false;
    bool escaped = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const std::uint8_t c = json[i];
        if (escaped) {
            escaped = false;
        } else if (inString) {
            escaped = c == '\\';
            inString = c != '"';
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) {
                throw ContentError(source, "not a valid glTF 2.0 file: JSON nested more than " +
                                               std::to_string(kMaxJsonDepth) + " levels deep at byte " +
                                               std::to_string(i));
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

template <glm::length_t N>
bool allFinite(const glm::vec<N, float>& v) {
    return !glm::any(glm::isnan(v)) && !glm::any(glm::isinf(v));
}

std::uint32_t readLittleEndian32(std::span<const std::uint8_t> bytes, std::size_t offset) {
    return std::uint32_t{bytes[offset]} | std::uint32_t{bytes[offset + 1]} << 8 |
           std::uint32_t{bytes[offset + 2]} << 16 | std::uint32_t{bytes[offset + 3]} << 24;
}

/// The JSON chunk of a GLB container, after checking the header and chunk layout (glTF 2.0, 4.4). tinygltf
/// 2.7.0 checks the BIN chunk's length without its 8-byte header and then copies up to 8 bytes past the end
/// of the data, so the layout is checked here first. Returns the JSON chunk and, through `length`, the GLB's
/// own length (trailing bytes beyond it are not part of the GLB).
std::span<const std::uint8_t> glbJsonChunk(std::span<const std::uint8_t> bytes, const std::string& source,
                                           std::size_t& length) {
    auto fail = [&](const std::string& detail) {
        throw ContentError(source, "not a valid glTF 2.0 file: GLB " + detail);
    };
    constexpr std::size_t kHeader = 12;
    constexpr std::size_t kChunkHeader = 8;
    if (bytes.size() < kHeader + kChunkHeader) {
        fail("is " + std::to_string(bytes.size()) + " bytes, shorter than its headers");
    }
    if (const std::uint32_t version = readLittleEndian32(bytes, 4); version != 2) {
        fail("header has version " + std::to_string(version) + " (expected 2)");
    }
    length = readLittleEndian32(bytes, 8);
    if (length > bytes.size()) {
        fail("header says " + std::to_string(length) + " bytes, but there are only " +
             std::to_string(bytes.size()));
    }
    // Sizes are compared by subtraction from `length`, so no sum of values read from the file can wrap.
    const std::size_t jsonLength = readLittleEndian32(bytes, kHeader);
    if (readLittleEndian32(bytes, kHeader + 4) != 0x4E4F534Au) { // "JSON"
        fail("first chunk is not of type JSON");
    }
    if (length < kHeader + kChunkHeader || jsonLength > length - kHeader - kChunkHeader) {
        fail("JSON chunk of " + std::to_string(jsonLength) + " bytes overruns the GLB's " +
             std::to_string(length) + " bytes");
    }
    const std::size_t binStart = kHeader + kChunkHeader + jsonLength;
    if (binStart < length) {
        if (length - binStart < kChunkHeader) {
            fail("ends inside the header of its second chunk");
        }
        const std::size_t binLength = readLittleEndian32(bytes, binStart);
        if (binLength > length - binStart - kChunkHeader) {
            fail("BIN chunk of " + std::to_string(binLength) + " bytes overruns the GLB's " +
                 std::to_string(length) + " bytes");
        }
    }
    return bytes.subspan(kHeader + kChunkHeader, jsonLength);
}

/// tinygltf's file access, confined to one folder: a scene from an untrusted source must not make the loader
/// read files elsewhere, and tinygltf on its own also looks in the working directory.
class ConfinedFiles {
public:
    explicit ConfinedFiles(const std::filesystem::path& folder) {
        if (!folder.empty()) {
            std::error_code error;
            folder_ = std::filesystem::weakly_canonical(folder, error);
            if (error) { // e.g. a component without search permission: then nothing inside can be read either
                folder_ = folder.lexically_normal();
            }
        }
    }

    /// tinygltf gets an empty base folder, so it hands every URI to expand() unchanged (and once more as
    /// "./uri"): the folder is applied here, where it is also checked.
    tinygltf::FsCallbacks callbacks() { return {&exists, &expand, &read, &write, this}; }

    /// The first path refused for lying outside the folder, or empty.
    [[nodiscard]] const std::string& refused() const { return refused_; }
    [[nodiscard]] std::string folderName() const { return folder_.string(); }

private:
    static ConfinedFiles& self(void* user) { return *static_cast<ConfinedFiles*>(user); }

    bool inside(const std::string& path) {
        std::error_code error;
        const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
        bool ok = !folder_.empty() && !error;
        if (ok) {
            const auto [end, unused] =
                std::mismatch(folder_.begin(), folder_.end(), resolved.begin(), resolved.end());
            ok = end == folder_.end();
        }
        if (!ok && refused_.empty()) {
            refused_ = path;
        }
        return ok;
    }

    static std::string expand(const std::string& uri, void* user) {
        const std::filesystem::path& folder = self(user).folder_;
        return folder.empty() ? uri : (folder / uri).string();
    }

    static bool exists(const std::string& path, void* user) {
        std::error_code error;
        return self(user).inside(path) && std::filesystem::is_regular_file(path, error);
    }

    static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
        if (!self(user).inside(path)) {
            *err += "outside the scene's folder";
            return false;
        }
        std::ifstream file(path, std::ios::binary);
        if (!file) {
            *err += "cannot be opened";
            return false;
        }
        out->assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
        return true;
    }

    static bool write(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
        return false;
    }

    std::filesystem::path folder_;
    std::string refused_;
};

/// Reads one glTF document into tinygltf's model and maps the parts we use onto an engine::Scene.
class GltfSceneBuilder {
public:
    GltfSceneBuilder(std::filesystem::path baseFolder, std::string sourceName,
                     const SceneLoadOptions& options)
        : baseFolder_(std::move(baseFolder)), source_(std::move(sourceName)), options_(options) {}

    LoadedScene build(std::span<const std::uint8_t> bytes) {
        readModel(bytes);
        visited_.assign(model_.nodes.size(), false);
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

    void readModel(std::span<const std::uint8_t> bytes) {
        // tinygltf takes sizes as unsigned int.
        if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
            fail("is larger than 4 GiB, which glTF does not support");
        }
        const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
        std::span<const std::uint8_t> json = bytes;
        if (binary) {
            std::size_t length = 0;
            json = glbJsonChunk(bytes, source_, length);
            bytes = bytes.first(length);
        }
        checkJsonNesting(json, source_);
        // Members of the wrong JSON type would be dropped silently by tinygltf; refuse them by name. Text
        // that is not JSON at all is left to tinygltf's parser and its message.
        const nlohmann::json document = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
        if (!document.is_discarded()) {
            checkGltfMemberTypes(document, source_);
            noteLightRanges(document);
        }
        const auto size = static_cast<unsigned int>(bytes.size());
        ConfinedFiles files(baseFolder_);
        tinygltf::TinyGLTF loader;
        loader.SetFsCallbacks(files.callbacks());
        // Textures are not used: skip decoding images (and failing on formats we cannot read).
        loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                                 const unsigned char*, int, void*) { return true; },
                              nullptr);
        std::string errors;
        std::string warnings;
        bool ok = false;
        try {
            if (binary) {
                ok = loader.LoadBinaryFromMemory(&model_, &errors, &warnings, bytes.data(), size, "");
            } else {
                ok = loader.LoadASCIIFromString(&model_, &errors, &warnings,
                                                reinterpret_cast<const char*>(bytes.data()), size, "");
            }
        } catch (const std::exception& error) {
            // tinygltf reports most problems through `errors` but lets some escape as exceptions (e.g.
            // std::out_of_range for a zero-length buffer in a GLB).
            errors += error.what();
        }
        if (!files.refused().empty()) {
            const std::string refusal =
                "external file '" + files.refused() + "' was not read: " +
                (files.folderName().empty()
                     ? "no external file may be read (loaded from memory without a base folder)"
                     : "it lies outside the folder " + files.folderName());
            // Buffers are required, so a refused one fails the load; images are optional (and unused).
            if (!ok) {
                fail(refusal);
            }
            result_.warnings.push_back(source_ + ": " + refusal);
        }
        if (!ok) {
            fail("not a valid glTF 2.0 file: " +
                 (errors.empty() ? std::string("unknown error") : trim(errors)));
        }
        if (!warnings.empty()) {
            result_.warnings.push_back(trim(warnings));
        }
    }

    /// Notes which lights state a range. tinygltf reads an absent range as 0, which the engine takes for
    /// "unlimited", so a range written as 0 (invalid: KHR_lights_punctual requires range > 0) could not be
    /// told from none without the document. Member types are already checked.
    void noteLightRanges(const nlohmann::json& document) {
        const auto extensions = document.find("extensions");
        if (extensions == document.end()) {
            return;
        }
        const auto punctual = extensions->find("KHR_lights_punctual");
        if (punctual == extensions->end()) {
            return;
        }
        const auto lights = punctual->find("lights");
        if (lights == punctual->end()) {
            return;
        }
        for (const nlohmann::json& light : *lights) {
            lightStatesRange_.push_back(light.contains("range"));
        }
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
        // The depth limit bounds the recursion; cycles and shared children are caught below.
        if (depth > 256) {
            fail("node " + std::to_string(index) + " is nested more than 256 deep");
        }
        const tinygltf::Node& node = at(model_.nodes, index, "node");
        const std::string field = "nodes[" + std::to_string(index) + "]";
        // glTF node hierarchies are disjoint trees (glTF 2.0, 3.5.3). A node reached twice is a cycle, or a
        // child shared between parents, which would instantiate its subtree once per path: exponentially
        // many entities from a few bytes.
        if (visited_[static_cast<std::size_t>(index)]) {
            fail(field + " is reached twice in the node hierarchy (a cycle, or a node with two parents)");
        }
        visited_[static_cast<std::size_t>(index)] = true;
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
            // Finite as floats, which the transform stores: 1e300 is a finite double but an infinite float.
            if (values.size() != size || !std::all_of(values.begin(), values.end(), [](double v) {
                    return std::isfinite(static_cast<float>(v));
                })) {
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
            if (!isFinite(transform)) {
                fail(field + ".matrix has no finite translation, rotation and scale");
            }
            return transform;
        }
        if (finite(node.translation, 3, "translation")) {
            transform.translation = glm::vec3(glm::make_vec3(node.translation.data()));
        }
        if (finite(node.rotation, 4, "rotation")) {
            // glTF stores quaternions as x, y, z, w. Normalised in double, where squares of float-sized
            // components cannot overflow; glm::normalize would turn a zero quaternion into the identity.
            const auto& r = node.rotation;
            const glm::dquat rotation(r[3], r[0], r[1], r[2]);
            const double length = glm::length(rotation);
            if (!(length > 0.0)) {
                fail(field + ".rotation must be a non-zero quaternion");
            }
            transform.rotation = glm::quat(rotation / length);
        }
        if (finite(node.scale, 3, "scale")) {
            transform.scale = glm::vec3(glm::make_vec3(node.scale.data()));
        }
        return transform;
    }

    static bool isFinite(const engine::Transform& transform) {
        const glm::vec4 rotation(transform.rotation.x, transform.rotation.y, transform.rotation.z,
                                 transform.rotation.w);
        return allFinite(transform.translation) && allFinite(rotation) && allFinite(transform.scale);
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
            // A zero or infinite view height makes a singular projection matrix.
            if (!(camera.orthographicHeight > 0.0f) || !std::isfinite(camera.orthographicHeight)) {
                fail("camera '" + source.name + "' needs a finite ymag > 0");
            }
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
        const std::string label =
            "light " + std::to_string(index) + (source.name.empty() ? "" : " ('" + source.name + "')");
        engine::LightComponent light;
        if (source.type == "directional") {
            light.type = engine::LightType::Directional;
        } else if (source.type == "spot") {
            light.type = engine::LightType::Spot;
            light.innerConeAngle = static_cast<float>(source.spot.innerConeAngle);
            light.outerConeAngle = static_cast<float>(source.spot.outerConeAngle);
            if (!(light.innerConeAngle >= 0.0f && light.innerConeAngle <= light.outerConeAngle &&
                  light.outerConeAngle <= 1.5708f)) {
                fail(label + " needs 0 <= innerConeAngle <= outerConeAngle <= pi/2");
            }
        } else if (source.type == "point") {
            light.type = engine::LightType::Point;
        } else {
            result_.warnings.push_back(source_ + ": " + label + " has the unknown type '" + source.type +
                                       "' (KHR_lights_punctual defines directional, spot and point), so it "
                                       "was left out");
            return;
        }
        if (source.color.size() == 3) {
            light.color = glm::vec3(glm::make_vec3(source.color.data()));
            if (!allFinite(light.color) || glm::any(glm::lessThan(light.color, glm::vec3(0.0f)))) {
                fail(label + " needs a color of finite, non-negative numbers");
            }
        }
        light.intensity = static_cast<float>(source.intensity);
        if (!std::isfinite(light.intensity) || light.intensity < 0.0f) {
            fail(label + " needs a finite, non-negative intensity");
        }
        // KHR_lights_punctual gives range to point and spot lights only (a sun has no distance), and requires
        // it to be > 0 when present; absent means unlimited. Checked as a float, which the engine stores.
        const bool statesRange = static_cast<std::size_t>(index) < lightStatesRange_.size() &&
                                 lightStatesRange_[static_cast<std::size_t>(index)];
        if (light.type != engine::LightType::Directional && statesRange) {
            light.range = static_cast<float>(source.range);
            if (!std::isfinite(light.range) || !(light.range > 0.0f)) {
                std::ostringstream value;
                value << source.range;
                fail(label + ": extensions.KHR_lights_punctual.lights[" + std::to_string(index) +
                     "].range must be a finite number > 0 (leave it out for an unlimited range), not " +
                     value.str());
            }
        }
        readLightSize(source, label, light);
        if (source.extras.IsObject() && source.extras.Has("castsShadows")) {
            const tinygltf::Value& castsShadows = source.extras.Get("castsShadows");
            if (!castsShadows.IsBool()) {
                fail(label + " extras.castsShadows must be true or false");
            }
            light.castsShadows = castsShadows.Get<bool>();
        }
        result_.scene.entity(entity).light = light;
    }

    /// The light's size from its extras (KHR_lights_punctual has none): `angularDiameter` (radians, a
    /// directional light's disk) or `radius` (world units, a spot or point light's sphere), for soft shadows.
    void readLightSize(const tinygltf::Light& source, const std::string& label,
                       engine::LightComponent& light) {
        if (!source.extras.IsObject()) {
            return;
        }
        const bool directional = light.type == engine::LightType::Directional;
        const char* const field = directional ? "angularDiameter" : "radius";
        const char* const other = directional ? "radius" : "angularDiameter";
        if (source.extras.Has(other)) {
            fail(label + " extras." + other + " is for " + (directional ? "spot and point" : "directional") +
                 " lights; a " + engine::toString(light.type) + " light's size is extras." + field);
        }
        if (!source.extras.Has(field)) {
            return;
        }
        const tinygltf::Value& value = source.extras.Get(field);
        const double size = value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
        const double largest = light.sizeLimit();
        if (!std::isfinite(size) || size < 0.0 || size >= largest) {
            std::ostringstream text;
            text << label << " extras." << field << " must be a number in [0, " << largest << ")"
                 << (directional          ? " radians"
                     : light.range > 0.0f ? " (the light's range)"
                                          : "")
                 << ", not ";
            if (value.IsNumber()) {
                text << size;
            } else {
                text << "a non-number";
            }
            fail(text.str());
        }
        (directional ? light.angularDiameter : light.radius) = static_cast<float>(size);
    }

    /// Copies accessor `index`, after checking that all its elements lie inside its bufferView and buffer.
    template <typename Element>
    std::vector<Element> readFloatAccessor(int index, int expectedType, const std::string& field) {
        const tinygltf::Accessor& accessor = at(model_.accessors, index, field + " accessor");
        const std::string where = "accessors[" + std::to_string(index) + "] (" + field + ")";
        if (accessor.type != expectedType || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
            fail(where + " must be " + (expectedType == TINYGLTF_TYPE_VEC3 ? "VEC3" : "VEC4") +
                 " of FLOAT (quantised attributes are not supported)");
        }
        const ElementRange range = elementRange(accessor, where, sizeof(Element));
        charge(range.count * sizeof(Element), where);
        std::vector<Element> values(range.count);
        for (std::size_t i = 0; i < range.count; ++i) {
            std::memcpy(&values[i], range.first + range.stride * i, sizeof(Element));
        }
        return values;
    }

    std::vector<std::uint32_t> readIndices(int index, const std::string& field) {
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
        const ElementRange range = elementRange(accessor, where, size);
        charge(range.count * sizeof(std::uint32_t), where);
        std::vector<std::uint32_t> values(range.count);
        for (std::size_t i = 0; i < range.count; ++i) {
            const unsigned char* bytes = range.first + range.stride * i;
            if (size == 1) {
                values[i] = bytes[0];
            } else if (size == 2) {
                std::uint16_t value = 0;
                std::memcpy(&value, bytes, 2);
                values[i] = value;
            } else {
                std::memcpy(&values[i], bytes, 4);
            }
        }
        return values;
    }

    /// Where an accessor's elements lie: element i starts at first + stride * i.
    struct ElementRange {
        const unsigned char* first = nullptr;
        std::size_t stride = 0;
        std::size_t count = 0;
    };

    /// Checks that every element of `accessor` lies inside its bufferView and buffer. Offsets, lengths and
    /// counts all come from the file, so sizes are compared by subtracting from known-good bounds: a sum or
    /// product of file values could wrap around and pass the check.
    ElementRange elementRange(const tinygltf::Accessor& accessor, const std::string& where,
                              std::size_t elementSize) const {
        if (accessor.sparse.isSparse) {
            fail(where + " is sparse; sparse accessors are not supported");
        }
        if (accessor.count == 0) {
            return {};
        }
        if (accessor.bufferView < 0) {
            fail(where + " has no bufferView (all-zero data is not supported for geometry)");
        }
        const tinygltf::BufferView& view = at(model_.bufferViews, accessor.bufferView, where + " bufferView");
        const tinygltf::Buffer& buffer = at(model_.buffers, view.buffer, "bufferView buffer");
        const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
        if (stride < elementSize) {
            fail(where + ": bufferView.byteStride " + std::to_string(stride) +
                 " is smaller than one element");
        }
        const std::size_t bufferSize = buffer.data.size();
        if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset) {
            fail(where + ": bufferView " + std::to_string(accessor.bufferView) + " (byteOffset " +
                 std::to_string(view.byteOffset) + ", byteLength " + std::to_string(view.byteLength) +
                 ") reaches beyond its buffer of " + std::to_string(bufferSize) + " bytes");
        }
        // Bytes of the view from the first element's start to the last possible element start.
        const bool firstFits =
            accessor.byteOffset <= view.byteLength && elementSize <= view.byteLength - accessor.byteOffset;
        if (!firstFits ||
            accessor.count - 1 > (view.byteLength - accessor.byteOffset - elementSize) / stride) {
            fail(where + ": " + std::to_string(accessor.count) + " elements from byteOffset " +
                 std::to_string(accessor.byteOffset) + " overrun bufferView " +
                 std::to_string(accessor.bufferView) + " of " + std::to_string(view.byteLength) +
                 " bytes (accessor out of bounds)");
        }
        return {buffer.data.data() + view.byteOffset + accessor.byteOffset, stride, accessor.count};
    }

    /// Counts `bytes` of mesh data against SceneLoadOptions::meshByteLimit before they are allocated.
    void charge(std::uint64_t bytes, const std::string& what) {
        if (bytes > options_.meshByteLimit - meshBytes_) {
            fail(what + " needs " + std::to_string(bytes) + " bytes of mesh data, more than is left of the " +
                 std::to_string(options_.meshByteLimit) +
                 " bytes the scene may use (SceneLoadOptions::"
                 "meshByteLimit)");
        }
        meshBytes_ += bytes;
    }

    engine::Material material(int index, const std::string& field) const {
        engine::Material result;
        if (index < 0) {
            return result;
        }
        const tinygltf::Material& source = at(model_.materials, index, field + ".material");
        const auto& pbr = source.pbrMetallicRoughness;
        // The spec bounds colour factors to [0, 1]; clamping keeps out-of-range (even infinite) ones
        // drawable.
        const glm::vec3 base =
            pbr.baseColorFactor.size() >= 3
                ? glm::clamp(glm::vec3(glm::make_vec3(pbr.baseColorFactor.data())), 0.0f, 1.0f)
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
            charge(data.positions.size() * sizeof(std::uint32_t), where + " implicit indices");
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
                                           const std::string& where) {
        std::vector<std::uint32_t> triangles;
        if ((mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) &&
            indices.size() > 2) {
            charge(3 * (indices.size() - 2) * sizeof(std::uint32_t), where + " triangles");
            triangles.reserve(3 * (indices.size() - 2));
        }
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
            auto surface = std::make_shared<engine::MeshData>(subdivide(*tag, parts, field));
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
                               const std::string& field) {
        const std::string where = field + ".extras.subdivision";
        const Scheme scheme = tag.scheme == "loop" ? Scheme::Loop : Scheme::CatmullClark;
        Cage cage;
        if (!tag.cage.empty()) {
            if (baseFolder_.empty()) {
                fail(where + ".cage '" + tag.cage +
                     "' cannot be read: the scene was loaded from memory without a base folder");
            }
            cage = namingNode(where, [&] { return CageLoader::load(baseFolder_ / tag.cage, scheme); });
        } else {
            if (parts.empty()) {
                fail(field + " is flagged for subdivision but has no triangles and no 'cage' file");
            }
            cage = weldedCage(parts, field);
            cage.scheme = scheme;
        }
        const int level = options_.subdivisionLevel >= 0 ? options_.subdivisionLevel : tag.level;
        charge(kSubdividedBytesPerFace * refinedFaceCount(cage, level), where);
        return namingNode(where, [&] { return SubdivisionSurface(std::move(cage)).evaluate(level).mesh; });
    }

    /// Output mesh bytes per refined face, rounded up: about one vertex (position and normal, 24 bytes) and
    /// two triangles (24 bytes of indices) per quad; Loop's triangles need half that.
    static constexpr std::uint64_t kSubdividedBytesPerFace = 48;

    /// Faces of `cage` after `level` uniform refinements: Catmull-Clark splits an n-gon into n quads, then
    /// every quad into 4; Loop splits every triangle into 4.
    static std::uint64_t refinedFaceCount(const Cage& cage, int level) {
        if (level == 0) {
            return cage.faces.size();
        }
        std::uint64_t firstLevel = 0;
        for (const auto& face : cage.faces) {
            firstLevel += cage.scheme == Scheme::Loop ? 4 : face.size();
        }
        return firstLevel << (2 * (level - 1));
    }

    /// Runs `action`; cage problems it reports name the cage (its file, or this file and node for a welded
    /// cage), so they get the glTF file and the node that asked for the cage as a prefix.
    template <typename Action>
    std::invoke_result_t<Action> namingNode(const std::string& where, Action action) const {
        try {
            return action();
        } catch (const ContentError& error) {
            fail(where + ": " + error.what());
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

    std::filesystem::path baseFolder_;
    std::string source_;
    SceneLoadOptions options_;
    tinygltf::Model model_;
    LoadedScene result_;
    std::vector<bool> visited_;          // per node: already placed in the scene
    std::vector<bool> lightStatesRange_; // per KHR_lights_punctual light: the document has its range
    std::uint64_t meshBytes_ = 0;        // charged against options_.meshByteLimit so far
};

} // namespace

LoadedScene GltfLoader::load(const std::filesystem::path& path, const SceneLoadOptions& options) {
    const std::string source = path.string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw ContentError(source, "file not found");
    }
    if (const auto size = std::filesystem::file_size(path, error);
        !error && size > std::numeric_limits<unsigned int>::max()) {
        throw ContentError(source, "is larger than 4 GiB, which glTF does not support");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw ContentError(source, "cannot be opened");
    }
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file),
                                          std::istreambuf_iterator<char>()};
    return loadFromMemory(bytes, path.has_parent_path() ? path.parent_path() : ".", source, options);
}

LoadedScene GltfLoader::loadFromMemory(std::span<const std::uint8_t> bytes,
                                       const std::filesystem::path& baseFolder, const std::string& sourceName,
                                       const SceneLoadOptions& options) {
    if (options.subdivisionLevel < -1 || options.subdivisionLevel > SubdivisionSurface::kMaxLevel) {
        throw ContentError(sourceName, "subdivision level " + std::to_string(options.subdivisionLevel) +
                                           " is outside [-1, " +
                                           std::to_string(SubdivisionSurface::kMaxLevel) + "]");
    }
    return GltfSceneBuilder(baseFolder, sourceName, options).build(bytes);
}

} // namespace content
