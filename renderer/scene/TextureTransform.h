#pragma once
// KHR_texture_transform on a material's texture references: offset, rotation and scale of the
// texture coordinates, read from the reference's extension text (Material::textureExtensions,
// which a save writes back as the file had it). The rasterizer (GpuMaterial::uvTransform,
// material.glsl), the voxelization (the same shader code) and the reference (ReferenceScene) apply
// the same matrix. Lit draws with TEXCOORD_0: a transform's texCoord is kept in the extension
// text and saved, and the loader warns about texture references that read another set. A normal
// map's tangent frame is the mesh's: a rotated normal map's tangent-space normals are not turned
// with it (as in most glTF viewers).

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <array>
#include <string>

namespace lit {

struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians, counter-clockwise in UV space as the extension defines it
    glm::vec2 scale{1.0f};
    int texCoord = -1;      // the extension's texCoord override, -1 when absent

    // The extension's matrix T·R·S as its two rows: uv' = (dot(row0, (uv, 1)), dot(row1, (uv, 1))).
    std::array<glm::vec3, 2> rows() const;
    glm::vec2 apply(glm::vec2 uv) const;
    bool operator==(const TextureTransform&) const = default;
};

// The KHR_texture_transform of one texture reference's extensions (a JSON object's text, "" for
// none); the identity when it has none, or for values that are not numbers of the right shape.
TextureTransform textureTransformOf(const std::string& extensionsJson);

// A material's transforms in Material::textureExtensions' order (base colour, metallic-roughness,
// normal, emissive, occlusion).
std::array<TextureTransform, 5> materialTextureTransforms(const Material& material);

}  // namespace lit
