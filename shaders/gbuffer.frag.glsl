#version 450 core
// G-buffer pass: writes the surface attributes the lighting passes need.
#include "frame.glsl"
#include "material.glsl"
#include "octahedral.glsl"
#include "specular_footprint.glsl"

#include "geometry_varyings.glsl"

layout(location = 0) out vec4 outAlbedo;    // rgb base colour (linear, stored sRGB), a occlusion
layout(location = 1) out vec4 outNormal;    // rgb world normal, a the footprint's α² (specular_footprint.glsl)
layout(location = 2) out vec4 outMaterial;  // r roughness, g metalness, b clear-coat texel, a coat-roughness texel
layout(location = 3) out vec4 outEmissive;  // rgb emitted radiance
// r: scene node index + 1 (0 = background); g: the primitive's index within the node's mesh;
// b: the material index (the lighting passes read the material's specular layers by it).
layout(location = 4) out uvec4 outNodeId;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_LAYERS)
// The specular layers' colour texels, each packUnorm4x8(rgb, a) (shared.h LIT_TEX_GBUFFER_LAYERS):
// x specular colour and specular, y sheen colour and sheen roughness; z the coat's normal.
layout(location = 5) out uvec4 outLayerTexels;
#endif
// xyz: how far the point moved since the last frame (world m); drawn only in frames where nodes
// moved (GBufferPass), for the temporal anti-aliasing.
layout(location = 6) out vec4 outMotion;

layout(location = LIT_LOC_NODE_ID) uniform uint uNodeId;
layout(location = LIT_LOC_PRIMITIVE) uniform uint uPrimitive;

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    if (materialIsSheet(m)) discard;  // drawn over the lit image by SheetPass
    vec4 baseColor = materialBaseColor(m, fs.uv);
    // Discarded after the footprint's derivatives, which need the whole quad.
    bool cutOut = materialAlphaDiscard(m, baseColor.a);

    outMotion = vec4(fs.worldMotion, 0.0);
    vec3 n = normalize(fs.worldNormal);
    // What the pixel's footprint adds to the lobes' α² in the direct light (gbuffer.glsl), from the
    // interpolated normal before anything branches: values computed in a branch may be undefined
    // in a quad's helper lanes (llvmpipe leaves them out), and so are their derivatives. A normal
    // map's own bumps are left to its mipmaps.
    float footprint = footprintAlphaSquared(n);
    // Double-sided materials (and back faces seen through open geometry) face the viewer.
    if (!gl_FrontFacing) n = -n;
    vec3 interpolatedNormal = n;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_NORMAL)
    if (m.textures.z != 0)
        n = materialMappedNormal(normalTexture, LIT_MATERIAL_SLOT_NORMAL, fs.uv, n, fs.worldTangent, m.params.z);
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

    // The coat's own normal (KHR_materials_clearcoat): its map on the interpolated normal, or
    // that normal alone where only the base is normal-mapped.
    vec3 coatNormal = interpolatedNormal;
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_LAYERS)
    if ((m.layerTextures.x & LIT_LAYER_TEXTURE_CLEARCOAT_NORMAL) != 0)
        coatNormal = materialMappedNormal(clearcoatNormalTexture, LIT_MATERIAL_SLOT_CLEARCOAT_NORMAL, fs.uv,
                                          interpolatedNormal, fs.worldTangent, m.clearcoat.z);
#endif
    if (cutOut) discard;

    outAlbedo = vec4(baseColor.rgb, occlusion);
    outNormal = vec4(n, footprint);
    outMaterial = vec4(clamp(roughness, 0.0, 1.0), clamp(metalness, 0.0, 1.0), layers.clearcoat, layers.clearcoatRoughness);
#if LIT_HAS_MATERIAL_TEXTURE(LIT_MATERIAL_TEXTURE_LAYERS)
    outLayerTexels = uvec4(packUnorm4x8(layers.specular), packUnorm4x8(layers.sheen),
                           packSnorm2x16(octEncode(coatNormal)), 0u);
#endif
    outEmissive = vec4(emissive, 1.0);
    outNodeId = uvec4(uNodeId, uPrimitive, uint(uMaterialIndex), 0u);
}
