// KHR_texture_transform in a glTF texture reference and back (scene/GltfTextureTransform.h).

#include "scene/GltfTextureTransform.h"

#include <cmath>
#include <utility>

namespace lit::gltfkeep {

namespace {

bool finiteNumber(const tinygltf::Value& v) { return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()); }

// A two-number array field into `target`; false (target unchanged) when it is anything else.
bool readPair(const tinygltf::Value& v, glm::dvec2& target) {
    if (!v.IsArray() || v.ArrayLen() != 2 || !finiteNumber(v.Get(0)) || !finiteNumber(v.Get(1))) return false;
    target = glm::dvec2(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
    return true;
}

tinygltf::Value pairValue(const glm::dvec2& v) {
    return tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(v.x), tinygltf::Value(v.y)});
}

}  // namespace

TextureTransform readTextureTransform(const tinygltf::ExtensionMap& extensions,
                                      const std::function<void(const std::string&)>& warn) {
    TextureTransform out;
    const auto found = extensions.find(kTextureTransformExtension);
    if (found == extensions.end()) return out;
    out.present = true;
    const tinygltf::Value& e = found->second;
    if (!e.IsObject()) {
        warn("its KHR_texture_transform is not an object; ignored");
        return out;
    }
    if (e.Has("offset") && !readPair(e.Get("offset"), out.offset))
        warn("its KHR_texture_transform offset is not two numbers; ignored");
    if (e.Has("scale") && !readPair(e.Get("scale"), out.scale))
        warn("its KHR_texture_transform scale is not two numbers; ignored");
    if (e.Has("rotation")) {
        if (finiteNumber(e.Get("rotation")))
            out.rotation = e.Get("rotation").GetNumberAsDouble();
        else
            warn("its KHR_texture_transform rotation is not a number; ignored");
    }
    if (e.Has("texCoord")) {
        const tinygltf::Value& t = e.Get("texCoord");
        if (t.IsInt() && t.Get<int>() >= 0)
            out.texCoord = t.Get<int>();
        else
            warn("its KHR_texture_transform texCoord is not a non-negative integer; ignored");
    }
    return out;
}

tinygltf::Value textureTransformValue(const TextureTransform& transform) {
    tinygltf::Value::Object out;
    if (transform.offset != glm::dvec2(0.0)) out["offset"] = pairValue(transform.offset);
    if (transform.rotation != 0.0) out["rotation"] = tinygltf::Value(transform.rotation);
    if (transform.scale != glm::dvec2(1.0)) out["scale"] = pairValue(transform.scale);
    if (transform.texCoord >= 0) out["texCoord"] = tinygltf::Value(transform.texCoord);
    return tinygltf::Value(std::move(out));
}

}  // namespace lit::gltfkeep
