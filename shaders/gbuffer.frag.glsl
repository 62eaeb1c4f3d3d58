#version 450 core
// G-buffer pass: writes the surface attributes the lighting passes need.
#include "frame.glsl"
#include "material.glsl"

#include "geometry_varyings.glsl"

layout(location = 0) out vec4 outAlbedo;    // rgb base colour (linear, stored sRGB), a occlusion
layout(location = 1) out vec4 outNormal;    // rgb world normal
layout(location = 2) out vec4 outMaterial;  // r roughness, g metalness, b clear-coat texel, a coat-roughness texel
layout(location = 3) out vec4 outEmissive;  // rgb emitted radiance
// r: scene node index + 1 (0 = background); g: the primitive's index within the node's mesh;
// b: the material index (the lighting passes read the material's specular layers by it).
layout(location = 4) out uvec4 outNodeId;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_LAYERS)
// The specular layers' colour texels, each packUnorm4x8(rgb, a) (shared.h LIT_TEX_GBUFFER_LAYERS):
// x specular colour and specular, y sheen colour and sheen roughness.
layout(location = 5) out uvec2 outLayerTexels;
#endif

layout(location = LIT_LOC_NODE_ID) uniform uint uNodeId;
layout(location = LIT_LOC_PRIMITIVE) uniform uint uPrimitive;

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    if (materialIsSheet(m)) discard;  // drawn over the lit image by SheetPass
    vec4 baseColor = materialBaseColor(m, fs.uv);
    if (materialAlphaDiscard(m, baseColor.a)) discard;

    vec3 n = normalize(fs.worldNormal);
    // Double-sided materials (and back faces seen through open geometry) face the viewer.
    if (!gl_FrontFacing) n = -n;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_NORMAL)
    if (m.textures.z != 0) {
        vec3 t = fs.worldTangent.xyz - n * dot(n, fs.worldTangent.xyz);
        if (dot(t, t) > 1e-10) {
            t = normalize(t);
            float handedness = fs.worldTangent.w < 0.0 ? -1.0 : 1.0;
            // The map's frame follows its KHR_texture_transform (identity: t itself).
            vec3 frame = materialUvTangent(LIT_MATERIAL_SLOT_NORMAL);
            t = normalize(t * frame.x + cross(n, t) * handedness * frame.y);
            vec3 b = cross(n, t) * handedness * frame.z;
            vec3 tn = texture(normalTexture, materialUv(LIT_MATERIAL_SLOT_NORMAL, fs.uv)).xyz * 2.0 - 1.0;
            tn.xy *= m.params.z;
            n = normalize(mat3(t, b, n) * tn);
        }
    }
#endif

    float metalness = m.params.x;
    float roughness = m.params.y;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_METALLIC_ROUGHNESS)
    if (m.textures.y != 0) {
        vec4 mr = texture(metallicRoughnessTexture, materialUv(LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS, fs.uv));
        roughness *= mr.g;
        metalness *= mr.b;
    }
#endif
    float occlusion = 1.0;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_OCCLUSION)
    if (m.modes.x != 0) {
        float ao = texture(occlusionTexture, materialUv(LIT_MATERIAL_SLOT_OCCLUSION, fs.uv)).r;
        occlusion = 1.0 + m.params.w * (ao - 1.0);
    }
#endif
    vec3 emissive = m.emissive.rgb;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_EMISSIVE)
    if (m.textures.w != 0)
        emissive *= texture(emissiveTexture, materialUv(LIT_MATERIAL_SLOT_EMISSIVE, fs.uv)).rgb;
#endif

    LayerTexels layers = materialLayerTexels(m, fs.uv);

    outAlbedo = vec4(baseColor.rgb, occlusion);
    outNormal = vec4(n, 1.0);
    outMaterial = vec4(clamp(roughness, 0.0, 1.0), clamp(metalness, 0.0, 1.0), layers.clearcoat, layers.clearcoatRoughness);
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_LAYERS)
    outLayerTexels = uvec2(packUnorm4x8(layers.specular), packUnorm4x8(layers.sheen));
#endif
    outEmissive = vec4(emissive, 1.0);
    outNodeId = uvec4(uNodeId, uPrimitive, uint(uMaterialIndex), 0u);
}
