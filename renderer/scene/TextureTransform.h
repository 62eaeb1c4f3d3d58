#pragma once
// KHR_texture_transform on one texture reference of a material: the UVs a texture is sampled
// with are offset + rotate(rotation) · (scale ∘ uv), as the extension's specification writes it
// (https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Khronos/KHR_texture_transform).
// The rasterizer, the voxelization and the reference tracer all apply it as the same 2×3 affine
// matrix (uvTransformRows), identity for references without the extension.

#include <glm/glm.hpp>

#include <array>
#include <cmath>

namespace lit {

struct TextureTransform {
    glm::dvec2 offset{0.0};  // UV units
    double rotation = 0.0;   // radians, counter-clockwise in UV space
    glm::dvec2 scale{1.0};
    int texCoord = -1;  // the extension's TEXCOORD_n override, -1 = none (the reference's own set)
    // Whether the reference has the extension: a save writes it (also when it is the identity).
    bool present = false;
    bool operator==(const TextureTransform&) const = default;
};

// The two rows of the transform's 2×3 matrix: u' = dot(row0, (u, v, 1)), v' = dot(row1, (u, v, 1)).
// T · R · S of the specification, multiplied out: R = [[cos, sin], [−sin, cos]].
inline std::array<glm::vec3, 2> uvTransformRows(const TextureTransform& t) {
    const double c = std::cos(t.rotation), s = std::sin(t.rotation);
    return {glm::vec3(glm::dvec3(c * t.scale.x, s * t.scale.y, t.offset.x)),
            glm::vec3(glm::dvec3(-s * t.scale.x, c * t.scale.y, t.offset.y))};
}

// The tangent of the transformed UVs in a normal map's frame (t, b) of the mesh UVs (b points to
// decreasing v, the image's up, as glTF's green does): xy the direction u' grows in, (∂u/∂u',
// −∂v/∂u') up to a positive factor (the first column of the inverse of the matrix's 2×2 part, v
// negated); z the sign of its determinant (a mirrored transform turns the bitangent). A normal map
// is painted in the frame of the UVs it is sampled with (material.glsl's materialUvTangent).
inline glm::vec3 uvTangentOfTransform(const std::array<glm::vec3, 2>& rows) {
    const float det = rows[0].x * rows[1].y - rows[0].y * rows[1].x;
    const float s = det < 0.0f ? -1.0f : 1.0f;
    return {rows[1].y * s, rows[1].x * s, s};
}

inline glm::vec2 applyUvTransform(const std::array<glm::vec3, 2>& rows, glm::vec2 uv) {
    const glm::vec3 h(uv, 1.0f);
    return {glm::dot(rows[0], h), glm::dot(rows[1], h)};
}

}  // namespace lit
