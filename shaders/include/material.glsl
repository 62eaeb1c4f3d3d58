// Material table and textures for passes that draw scene geometry.
#include "material_table.glsl"

layout(location = LIT_LOC_MATERIAL) uniform int uMaterialIndex;

// The textures this program may sample (LIT_MATERIAL_TEXTURE_* bits, shared.h); the material
// table's flags still say whether a material has each. The G-buffer pass builds a program per
// combination its draws use (GBufferPass), so a texture no material of a draw has is not in its
// program: llvmpipe runs a branch no lane takes with every lane masked off, and the five texture
// branches cost the untextured Cornell box's G-buffer 13 of its 34 ms at 1280×720
// (docs/PERFORMANCE.md, "llvmpipe"). Other passes keep them all.
#ifndef LIT_MATERIAL_TEXTURES
#define LIT_MATERIAL_TEXTURES LIT_MATERIAL_TEXTURES_ALL
#endif
#define LIT_HAS_MATERIAL_TEXTURE(bit) ((LIT_MATERIAL_TEXTURES & (bit)) != 0)

layout(binding = LIT_TEX_BASE_COLOR) uniform sampler2D baseColorTexture;
layout(binding = LIT_TEX_METALLIC_ROUGHNESS) uniform sampler2D metallicRoughnessTexture;
layout(binding = LIT_TEX_NORMAL) uniform sampler2D normalTexture;
layout(binding = LIT_TEX_EMISSIVE) uniform sampler2D emissiveTexture;
layout(binding = LIT_TEX_OCCLUSION) uniform sampler2D occlusionTexture;
layout(binding = LIT_TEX_TRANSMISSION) uniform sampler2D transmissionTexture;
layout(binding = LIT_TEX_CLEARCOAT) uniform sampler2D clearcoatTexture;
layout(binding = LIT_TEX_CLEARCOAT_ROUGHNESS) uniform sampler2D clearcoatRoughnessTexture;
layout(binding = LIT_TEX_SPECULAR) uniform sampler2D specularTexture;
layout(binding = LIT_TEX_SPECULAR_COLOR) uniform sampler2D specularColorTexture;
layout(binding = LIT_TEX_SHEEN_COLOR) uniform sampler2D sheenColorTexture;
layout(binding = LIT_TEX_SHEEN_ROUGHNESS) uniform sampler2D sheenRoughnessTexture;
layout(binding = LIT_TEX_CLEARCOAT_NORMAL) uniform sampler2D clearcoatNormalTexture;
layout(binding = LIT_TEX_THICKNESS) uniform sampler2D thicknessTexture;

// Per texture reference (LIT_MATERIAL_SLOT_*), the two rows of its KHR_texture_transform as a
// 2×3 matrix, xyz each (scene/TextureTransform.h; identity without the extension), and in the
// first row's w the UV set it reads (0 TEXCOORD_0, 1 TEXCOORD_1: scene/Scene.h drawnTexCoord),
// set per draw (GpuScene::drawItem). Every fetch selects and multiplies, so no shader branches on
// whether a reference has a transform or which set it reads. A uniform rather than a GpuMaterial
// field: on llvmpipe, UVs computed from the material SSBO got wrong derivatives in pixel quads
// along triangle edges (a mip level too coarse there, dots along every edge of the checker test
// scene); a uniform holds in every invocation of a quad.
layout(location = LIT_LOC_UV_TRANSFORMS) uniform vec4 uUvTransforms[2 * LIT_MATERIAL_SLOTS];

// The UVs texture reference `slot` (LIT_MATERIAL_SLOT_*, a constant) samples at mesh UVs `uvs`
// (xy TEXCOORD_0, zw TEXCOORD_1).
vec2 materialUv(int slot, vec4 uvs) {
    vec3 h = vec3(mix(uvs.xy, uvs.zw, uUvTransforms[2 * slot].w), 1.0);
    return vec2(dot(uUvTransforms[2 * slot].xyz, h), dot(uUvTransforms[2 * slot + 1].xyz, h));
}

// The tangent of texture reference `slot`'s transformed UVs in a normal map's frame (t, b) of the
// mesh UVs (b points to decreasing v, the image's up, as glTF's green does): xy the direction u'
// grows in, (∂u/∂u', −∂v/∂u') up to a positive factor; z the sign of the transform's determinant
// (a mirrored transform turns the bitangent). A normal map is painted in the frame of the UVs it
// is sampled with: scene/TextureTransform.h's uvTangentOfTransform, the reference's.
vec3 materialUvTangent(int slot) {
    vec2 r0 = uUvTransforms[2 * slot].xy, r1 = uUvTransforms[2 * slot + 1].xy;
    float s = r0.x * r1.y - r0.y * r1.x < 0.0 ? -1.0 : 1.0;
    return vec3(vec2(r1.y, r1.x) * s, s);  // the first column of the inverse of the 2×2 part, v negated
}

// Base colour × texture (linear; sRGB textures are decoded by the sampler).
vec4 materialBaseColor(GpuMaterial m, vec4 uv) {
    vec4 c = m.baseColorFactor;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_BASE_COLOR)
    if (m.textures.x != 0) c *= texture(baseColorTexture, materialUv(LIT_MATERIAL_SLOT_BASE_COLOR, uv));
#endif
    return c;
}

// KHR_materials_transmission's share at mesh UVs `uv`: the factor × the texture's red channel.
float materialTransmission(GpuMaterial m, vec4 uv) {
    float t = m.alpha.y;
    if (m.modes.w != 0) t *= texture(transmissionTexture, materialUv(LIT_MATERIAL_SLOT_TRANSMISSION, uv)).r;
    return t;
}

// KHR_materials_volume's thickness at mesh UVs `uv` in metres, world: the factor × the thickness
// texture's green channel × `meshScale` (meshLengthScale of the model matrix).
float materialThickness(GpuMaterial m, vec4 uv, float meshScale) {
    float thickness = m.volume.a * meshScale;
    if (m.layerTextures.y != 0) thickness *= texture(thicknessTexture, materialUv(LIT_MATERIAL_SLOT_THICKNESS, uv)).g;
    return thickness;
}

// What KHR_materials_volume's medium lets through at one face of a sheet the light crosses at
// cosθ to the normal (docs/MATERIALS.md, "Volume"): exp(−σ_a · x), x half the straight path
// through a slab of the material's thickness, thickness / |cosθ| (a closed mesh is crossed at two
// faces, which each take half), the thickness being the factor × the texture's green channel in
// the mesh's space, × `meshScale` (the model matrix's scale, cube root of its determinant).
vec3 materialVolumeTransmittance(GpuMaterial m, vec4 uv, float cosTheta, float meshScale) {
    if (m.volume.a <= 0.0 || max(m.volume.r, max(m.volume.g, m.volume.b)) <= 0.0) return vec3(1.0);
    // Grazing paths are capped at 10 thicknesses: a face seen edge-on is not a slab that long.
    return exp(-m.volume.rgb * (0.5 * materialThickness(m, uv, meshScale) / max(abs(cosTheta), 0.1)));
}

// The scale of model matrix `model` for lengths in the mesh's space (exact for a uniform scale).
float meshLengthScale(mat4 model) { return pow(abs(determinant(mat3(model))), 1.0 / 3.0); }

// The texels of the layers' textures at mesh UVs `uv` (LayerTexels, material_table.glsl).
LayerTexels materialLayerTexels(GpuMaterial m, vec4 uv) {
    LayerTexels t = noLayerTexels();
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_LAYERS)
    int bits = m.layerTextures.x;
    if (bits != 0) {
        if ((bits & LIT_LAYER_TEXTURE_CLEARCOAT) != 0)
            t.clearcoat = texture(clearcoatTexture, materialUv(LIT_MATERIAL_SLOT_CLEARCOAT, uv)).r;
        if ((bits & LIT_LAYER_TEXTURE_CLEARCOAT_ROUGHNESS) != 0)
            t.clearcoatRoughness =
                texture(clearcoatRoughnessTexture, materialUv(LIT_MATERIAL_SLOT_CLEARCOAT_ROUGHNESS, uv)).g;
        if ((bits & LIT_LAYER_TEXTURE_SPECULAR) != 0)
            t.specular.a = texture(specularTexture, materialUv(LIT_MATERIAL_SLOT_SPECULAR, uv)).a;
        if ((bits & LIT_LAYER_TEXTURE_SPECULAR_COLOR) != 0)
            t.specular.rgb = texture(specularColorTexture, materialUv(LIT_MATERIAL_SLOT_SPECULAR_COLOR, uv)).rgb;
        if ((bits & LIT_LAYER_TEXTURE_SHEEN_COLOR) != 0)
            t.sheen.rgb = texture(sheenColorTexture, materialUv(LIT_MATERIAL_SLOT_SHEEN_COLOR, uv)).rgb;
        if ((bits & LIT_LAYER_TEXTURE_SHEEN_ROUGHNESS) != 0)
            t.sheen.a = texture(sheenRoughnessTexture, materialUv(LIT_MATERIAL_SLOT_SHEEN_ROUGHNESS, uv)).a;
    }
#endif
    return t;
}

// Normal `n` (unit, facing the viewer) bent by the normal map of texture reference `slot` (a
// constant) sampled at mesh UVs `uv`, of strength `scale`, in the frame of the vertex tangent
// `tangent` (xyz world, w handedness) turned by the reference's KHR_texture_transform.
vec3 materialMappedNormal(sampler2D map, int slot, vec4 uv, vec3 n, vec4 tangent, float scale) {
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
    if (dot(t, t) <= 1e-10) return n;
    t = normalize(t);
    float handedness = tangent.w < 0.0 ? -1.0 : 1.0;
    // The map's frame follows its KHR_texture_transform (identity: t itself).
    vec3 frame = materialUvTangent(slot);
    t = normalize(t * frame.x + cross(n, t) * handedness * frame.y);
    vec3 b = cross(n, t) * handedness * frame.z;
    vec3 tn = texture(map, materialUv(slot, uv)).xyz * 2.0 - 1.0;
    tn.xy *= scale;
    return normalize(mat3(t, b, n) * tn);
}

// True when an alpha-masked fragment must be discarded.
bool materialAlphaDiscard(GpuMaterial m, float alpha) {
    return m.modes.y == LIT_ALPHA_MASK && alpha < m.alpha.x;
}
