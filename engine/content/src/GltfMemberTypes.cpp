#include "GltfMemberTypes.h"

#include <content/ContentError.h>

#include <functional>

namespace content {

namespace {

/// Index: a non-negative integer (glTF ids and counts; tinygltf reads -1 as "none").
enum class Kind { Object, Array, Index, Number, String, Boolean };

const char* describe(Kind kind) {
    switch (kind) {
    case Kind::Object:
        return "an object";
    case Kind::Array:
        return "an array";
    case Kind::Index:
        return "a non-negative integer";
    case Kind::Number:
        return "a number";
    case Kind::String:
        return "a string";
    case Kind::Boolean:
        return "a boolean";
    }
    return "a value";
}

bool holds(const nlohmann::json& value, Kind kind) {
    switch (kind) {
    case Kind::Object:
        return value.is_object();
    case Kind::Array:
        return value.is_array();
    case Kind::Index:
        return value.is_number_unsigned();
    case Kind::Number:
        return value.is_number();
    case Kind::String:
        return value.is_string();
    case Kind::Boolean:
        return value.is_boolean();
    }
    return false;
}

/// Walks the members the loader reads; each check names the member's JSON path.
class Checker {
public:
    explicit Checker(const std::string& source) : source_(source) {}

    void expect(const nlohmann::json& value, Kind kind, const std::string& path) const {
        if (!holds(value, kind)) {
            throw ContentError(source_, path + ": expected " + describe(kind));
        }
    }

    /// The member `name` of `object` when present, after checking its type; nullptr when absent.
    const nlohmann::json* member(const nlohmann::json& object, const char* name, Kind kind,
                                 const std::string& path, bool required = false) const {
        const auto found = object.find(name);
        if (found == object.end()) {
            if (required) {
                throw ContentError(source_, join(path, name) + ": required member is missing");
            }
            return nullptr;
        }
        expect(*found, kind, join(path, name));
        return &*found;
    }

    /// An optional array member whose every item has `itemKind`.
    void arrayOf(const nlohmann::json& object, const char* name, Kind itemKind,
                 const std::string& path) const {
        if (const nlohmann::json* array = member(object, name, Kind::Array, path)) {
            for (std::size_t i = 0; i < array->size(); ++i) {
                expect((*array)[i], itemKind, join(path, name) + "[" + std::to_string(i) + "]");
            }
        }
    }

    /// An optional array of objects; `each(item, itemPath)` checks every item.
    void objects(const nlohmann::json& object, const char* name, const std::string& path,
                 const std::function<void(const nlohmann::json&, const std::string&)>& each,
                 bool required = false) const {
        if (const nlohmann::json* array = member(object, name, Kind::Array, path, required)) {
            for (std::size_t i = 0; i < array->size(); ++i) {
                const std::string itemPath = join(path, name) + "[" + std::to_string(i) + "]";
                expect((*array)[i], Kind::Object, itemPath);
                each((*array)[i], itemPath);
            }
        }
    }

    void numbers(const nlohmann::json& object, std::initializer_list<const char*> names,
                 const std::string& path) const {
        for (const char* name : names) {
            member(object, name, Kind::Number, path);
        }
    }

    void indices(const nlohmann::json& object, std::initializer_list<const char*> names,
                 const std::string& path) const {
        for (const char* name : names) {
            member(object, name, Kind::Index, path);
        }
    }

    static std::string join(const std::string& path, const char* name) {
        return path.empty() ? name : path + "." + name;
    }

private:
    const std::string& source_;
};

void checkNode(const Checker& c, const nlohmann::json& node, const std::string& path) {
    c.indices(node, {"mesh", "camera"}, path);
    c.arrayOf(node, "children", Kind::Index, path);
    for (const char* name : {"matrix", "translation", "rotation", "scale"}) {
        c.arrayOf(node, name, Kind::Number, path);
    }
    if (const nlohmann::json* extensions = c.member(node, "extensions", Kind::Object, path)) {
        const std::string extensionsPath = Checker::join(path, "extensions");
        if (const nlohmann::json* lights =
                c.member(*extensions, "KHR_lights_punctual", Kind::Object, extensionsPath)) {
            c.member(*lights, "light", Kind::Index, Checker::join(extensionsPath, "KHR_lights_punctual"));
        }
    }
    if (const nlohmann::json* extras = c.member(node, "extras", Kind::Object, path)) {
        const std::string extrasPath = Checker::join(path, "extras");
        if (const nlohmann::json* subdivision = c.member(*extras, "subdivision", Kind::Object, extrasPath)) {
            const std::string subdivisionPath = Checker::join(extrasPath, "subdivision");
            c.member(*subdivision, "scheme", Kind::String, subdivisionPath);
            c.member(*subdivision, "level", Kind::Index, subdivisionPath);
            c.member(*subdivision, "cage", Kind::String, subdivisionPath);
        }
    }
}

void checkMesh(const Checker& c, const nlohmann::json& mesh, const std::string& path) {
    c.objects(
        mesh, "primitives", path,
        [&](const nlohmann::json& primitive, const std::string& primitivePath) {
            if (const nlohmann::json* attributes =
                    c.member(primitive, "attributes", Kind::Object, primitivePath, true)) {
                for (const auto& [semantic, accessor] : attributes->items()) {
                    c.expect(accessor, Kind::Index,
                             Checker::join(primitivePath, "attributes") + "." + semantic);
                }
            }
            c.indices(primitive, {"indices", "mode", "material"}, primitivePath);
        },
        true);
}

/// A texture reference (textureInfo): textures are not drawn, but a broken reference is still a broken file.
void checkTextureInfo(const Checker& c, const nlohmann::json& owner, const char* name,
                      const std::string& path) {
    if (const nlohmann::json* info = c.member(owner, name, Kind::Object, path)) {
        const std::string infoPath = Checker::join(path, name);
        c.member(*info, "index", Kind::Index, infoPath, true);
        c.indices(*info, {"texCoord"}, infoPath);
        c.numbers(*info, {"scale", "strength"}, infoPath);
        if (const nlohmann::json* extensions = c.member(*info, "extensions", Kind::Object, infoPath)) {
            for (const auto& [extension, value] : extensions->items()) {
                c.expect(value, Kind::Object, Checker::join(infoPath, "extensions") + "." + extension);
            }
        }
    }
}

void checkMaterial(const Checker& c, const nlohmann::json& material, const std::string& path) {
    c.member(material, "doubleSided", Kind::Boolean, path);
    c.arrayOf(material, "emissiveFactor", Kind::Number, path);
    for (const char* texture : {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
        checkTextureInfo(c, material, texture, path);
    }
    if (const nlohmann::json* pbr = c.member(material, "pbrMetallicRoughness", Kind::Object, path)) {
        const std::string pbrPath = Checker::join(path, "pbrMetallicRoughness");
        c.arrayOf(*pbr, "baseColorFactor", Kind::Number, pbrPath);
        c.numbers(*pbr, {"metallicFactor", "roughnessFactor"}, pbrPath);
        checkTextureInfo(c, *pbr, "baseColorTexture", pbrPath);
        checkTextureInfo(c, *pbr, "metallicRoughnessTexture", pbrPath);
    }
}

void checkCamera(const Checker& c, const nlohmann::json& camera, const std::string& path) {
    c.member(camera, "type", Kind::String, path);
    if (const nlohmann::json* perspective = c.member(camera, "perspective", Kind::Object, path)) {
        c.numbers(*perspective, {"yfov", "znear", "zfar", "aspectRatio"}, Checker::join(path, "perspective"));
    }
    if (const nlohmann::json* orthographic = c.member(camera, "orthographic", Kind::Object, path)) {
        c.numbers(*orthographic, {"xmag", "ymag", "znear", "zfar"}, Checker::join(path, "orthographic"));
    }
}

void checkLight(const Checker& c, const nlohmann::json& light, const std::string& path) {
    c.member(light, "type", Kind::String, path);
    c.arrayOf(light, "color", Kind::Number, path);
    c.numbers(light, {"intensity", "range"}, path);
    if (const nlohmann::json* spot = c.member(light, "spot", Kind::Object, path)) {
        c.numbers(*spot, {"innerConeAngle", "outerConeAngle"}, Checker::join(path, "spot"));
    }
}

} // namespace

void checkGltfMemberTypes(const nlohmann::json& document, const std::string& source) {
    const Checker c(source);
    c.expect(document, Kind::Object, "the document");
    if (const nlohmann::json* asset = c.member(document, "asset", Kind::Object, "", true)) {
        c.member(*asset, "version", Kind::String, "asset", true);
    }
    c.member(document, "scene", Kind::Index, "");
    c.objects(document, "scenes", "", [&](const nlohmann::json& scene, const std::string& path) {
        c.arrayOf(scene, "nodes", Kind::Index, path);
    });
    c.objects(document, "nodes", "",
              [&](const nlohmann::json& node, const std::string& path) { checkNode(c, node, path); });
    c.objects(document, "meshes", "",
              [&](const nlohmann::json& mesh, const std::string& path) { checkMesh(c, mesh, path); });
    c.objects(document, "accessors", "", [&](const nlohmann::json& accessor, const std::string& path) {
        c.indices(accessor, {"bufferView", "byteOffset"}, path);
        c.member(accessor, "componentType", Kind::Index, path, true);
        c.member(accessor, "count", Kind::Index, path, true);
        c.member(accessor, "type", Kind::String, path, true);
        c.member(accessor, "normalized", Kind::Boolean, path);
        c.arrayOf(accessor, "min", Kind::Number, path);
        c.arrayOf(accessor, "max", Kind::Number, path);
    });
    c.objects(document, "bufferViews", "", [&](const nlohmann::json& view, const std::string& path) {
        c.member(view, "buffer", Kind::Index, path, true);
        c.member(view, "byteLength", Kind::Index, path, true);
        c.indices(view, {"byteOffset", "byteStride", "target"}, path);
    });
    c.objects(document, "buffers", "", [&](const nlohmann::json& buffer, const std::string& path) {
        c.member(buffer, "uri", Kind::String, path);
        c.member(buffer, "byteLength", Kind::Index, path, true);
    });
    c.objects(document, "materials", "", [&](const nlohmann::json& material, const std::string& path) {
        checkMaterial(c, material, path);
    });
    c.objects(document, "cameras", "",
              [&](const nlohmann::json& camera, const std::string& path) { checkCamera(c, camera, path); });
    if (const nlohmann::json* extensions = c.member(document, "extensions", Kind::Object, "")) {
        if (const nlohmann::json* lights =
                c.member(*extensions, "KHR_lights_punctual", Kind::Object, "extensions")) {
            c.objects(
                *lights, "lights", "extensions.KHR_lights_punctual",
                [&](const nlohmann::json& light, const std::string& path) { checkLight(c, light, path); });
        }
    }
    for (const char* array : {"scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers", "materials",
                              "cameras", "textures", "images", "samplers"}) {
        c.objects(document, array, "", [&](const nlohmann::json& item, const std::string& path) {
            c.member(item, "name", Kind::String, path);
        });
    }
    c.arrayOf(document, "extensionsUsed", Kind::String, "");
    c.arrayOf(document, "extensionsRequired", Kind::String, "");
}

} // namespace content
