#include "scene/TextureTransform.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace lit {

std::array<glm::vec3, 2> TextureTransform::rows() const {
    // The extension's reference shader: translation · rotation · scale, its rotation written
    // column by column as mat3(cos, sin, 0, −sin, cos, 0, 0, 0, 1), so u' = cos·u − sin·v.
    const float c = std::cos(rotation), s = std::sin(rotation);
    return {glm::vec3(c * scale.x, -s * scale.y, offset.x), glm::vec3(s * scale.x, c * scale.y, offset.y)};
}

glm::vec2 TextureTransform::apply(glm::vec2 uv) const {
    const std::array<glm::vec3, 2> m = rows();
    const glm::vec3 p(uv, 1.0f);
    return {glm::dot(m[0], p), glm::dot(m[1], p)};
}

TextureTransform textureTransformOf(const std::string& extensionsJson) {
    TextureTransform transform;
    if (extensionsJson.empty()) return transform;
    const nlohmann::json extensions = nlohmann::json::parse(extensionsJson, nullptr, false);
    if (!extensions.is_object()) return transform;
    const auto found = extensions.find("KHR_texture_transform");
    if (found == extensions.end() || !found->is_object()) return transform;
    const nlohmann::json& t = *found;
    const auto pair = [&](const char* key, glm::vec2& target) {
        const auto value = t.find(key);
        if (value != t.end() && value->is_array() && value->size() == 2 && (*value)[0].is_number() &&
            (*value)[1].is_number()) {
            const glm::vec2 read((*value)[0].get<float>(), (*value)[1].get<float>());
            if (std::isfinite(read.x) && std::isfinite(read.y)) target = read;
        }
    };
    pair("offset", transform.offset);
    pair("scale", transform.scale);
    if (const auto rotation = t.find("rotation"); rotation != t.end() && rotation->is_number())
        if (const float r = rotation->get<float>(); std::isfinite(r)) transform.rotation = r;
    if (const auto texCoord = t.find("texCoord"); texCoord != t.end() && texCoord->is_number_integer())
        transform.texCoord = texCoord->get<int>();
    return transform;
}

std::array<TextureTransform, 5> materialTextureTransforms(const Material& material) {
    std::array<TextureTransform, 5> transforms;
    for (std::size_t slot = 0; slot < transforms.size(); ++slot)
        transforms[slot] = textureTransformOf(material.textureExtensions[slot]);
    return transforms;
}

}  // namespace lit
