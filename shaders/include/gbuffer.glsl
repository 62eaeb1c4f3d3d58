// Reading the G-buffer in full-screen passes. The material table must be bound
// (Renderer: lightTerms binds it for the lighting passes).
#include "shared.h"
#include "material_table.glsl"
#include "brdf.glsl"
#include "octahedral.glsl"

layout(binding = LIT_TEX_GBUFFER_ALBEDO) uniform sampler2D gbufferAlbedo;
layout(binding = LIT_TEX_GBUFFER_NORMAL) uniform sampler2D gbufferNormal;
layout(binding = LIT_TEX_GBUFFER_MATERIAL) uniform sampler2D gbufferMaterial;
layout(binding = LIT_TEX_GBUFFER_EMISSIVE) uniform sampler2D gbufferEmissive;
layout(binding = LIT_TEX_GBUFFER_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = LIT_TEX_GBUFFER_ID) uniform usampler2D gbufferId;

struct Surface {
    bool valid;        // false for background pixels
    vec3 position;     // world (m)
    vec3 normal;       // world, unit
    vec3 baseColor;    // linear
    float occlusion;
    float roughness;
    float metalness;
    vec3 emissive;
    vec3 f0;                  // specular reflectance at normal incidence (metal or dielectric)
    float f90;                // and at grazing incidence
    float clearcoat;          // the coat's weight (0: none)
    float clearcoatRoughness; // perceptual
    vec3 clearcoatNormal;     // world, unit; 0: the coat shares the shading normal (coatNormal)
    vec3 sheenColor;          // 0: no sheen
    float sheenRoughness;     // perceptual
    // What the pixel's footprint adds to the base's and the coat's α² in the direct light
    // (specular_footprint.glsl; 0 where no pass measured it).
    float footprint;
};

// Whether any material of the scene has a specular layer (MaterialLayersVariant): without, the
// metal-rough defaults are taken and neither the ID target nor the table is read.
#ifndef LIT_MATERIAL_LAYERS
#define LIT_MATERIAL_LAYERS 1
#endif
#if LIT_MATERIAL_LAYERS
layout(binding = LIT_TEX_SHEEN_ALBEDO) uniform sampler2D sheenAlbedoTable;
layout(binding = LIT_TEX_GBUFFER_LAYERS) uniform usampler2D gbufferLayers;
#endif

// The specular parameters of material `m` with its layer texels `t` (docs/MATERIALS.md); `s`
// needs baseColor and metalness.
void setMaterialLayers(GpuMaterial m, LayerTexels t, inout Surface s) {
    s.f0 = specularF0(s.baseColor, s.metalness, materialDielectricF0(m, t));
    s.f90 = specularF90(s.metalness, materialDielectricF90(m, t));
    s.clearcoat = m.clearcoat.x * t.clearcoat;
    s.clearcoatRoughness = m.clearcoat.y * t.clearcoatRoughness;
    s.sheenColor = m.sheen.rgb * t.sheen.rgb;
    s.sheenRoughness = m.sheen.a * t.sheen.a;
    s.clearcoatNormal = vec3(0.0);
}

// The specular parameters of the pixel's material, from the material table entry the ID target
// names and, where it has layer textures, the texels the G-buffer stored; `s` needs baseColor
// and metalness.
void readMaterialLayers(ivec2 pixel, inout Surface s) {
#if LIT_MATERIAL_LAYERS
    GpuMaterial m = materials[texelFetch(gbufferId, pixel, 0).b];
    LayerTexels t = noLayerTexels();
    uvec4 texels = uvec4(0u);
    if (m.layerTextures.x != 0) {
        vec2 coat = texelFetch(gbufferMaterial, pixel, 0).ba;
        texels = texelFetch(gbufferLayers, pixel, 0);
        t = LayerTexels(coat.x, coat.y, unpackUnorm4x8(texels.x), unpackUnorm4x8(texels.y));
    }
    setMaterialLayers(m, t, s);
    if ((m.layerTextures.x & LIT_LAYER_COAT_NORMAL_STORED) != 0) s.clearcoatNormal = octDecode(unpackSnorm2x16(texels.z));
#else
    s.f0 = specularF0(s.baseColor, s.metalness, vec3(0.04));
    s.f90 = 1.0;
    s.clearcoat = 0.0;
    s.clearcoatRoughness = 0.0;
    s.sheenColor = vec3(0.0);
    s.sheenRoughness = 0.0;
    s.clearcoatNormal = vec3(0.0);
#endif
}

// E_s(n·v, r_s): the directional albedo of a white sheen (scene/SheenAlbedo.h's table).
float sheenAlbedo(float NdotV, float roughness) {
#if LIT_MATERIAL_LAYERS
    return textureLod(sheenAlbedoTable, vec2(NdotV, roughness), 0.0).r;
#else
    return 0.0;
#endif
}

// What the sheen leaves of the base under it: 1 − max(s_c)·E_s(n·v).
float sheenBaseScale(Surface s, float NdotV) {
    float strength = max(s.sheenColor.r, max(s.sheenColor.g, s.sheenColor.b));
    return strength > 0.0 ? 1.0 - strength * sheenAlbedo(NdotV, s.sheenRoughness) : 1.0;
}

// What multiplies the irradiance/π a pixel gathers to give L_ID (docs/MATERIALS.md): the diffuse
// albedo under the sheen, plus the sheen's own directional albedo (the gather stands for the
// light over its lobe), all under what a clear coat lets through (NcdotV: the coat's normal's,
// coatNdotV).
vec3 indirectDiffuseAlbedo(Surface s, float NdotV, float NcdotV) {
    vec3 albedo = diffuseAlbedo(s.baseColor, s.metalness) * sheenBaseScale(s, NdotV) +
                  s.sheenColor * sheenAlbedo(NdotV, s.sheenRoughness);
    return albedo * clearcoatBaseScale(s.clearcoat, NcdotV);
}

// The roughness the indirect specular lobe is traced with: a coat smoother than the base
// reflects the sharper lobe, which the base's rougher one is drawn with (docs/MATERIALS.md).
float specularLobeRoughness(Surface s) {
    return s.clearcoat > 0.0 ? min(s.roughness, s.clearcoatRoughness) : s.roughness;
}

Surface readSurface(ivec2 pixel, vec2 uv) {
    Surface s;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    s.valid = depth < 1.0;
    s.position = worldPositionFromDepth(uv, depth);
    vec4 normal = texelFetch(gbufferNormal, pixel, 0);
    s.normal = normalize(normal.xyz);
    s.footprint = normal.a;
    vec4 albedo = texelFetch(gbufferAlbedo, pixel, 0);
    s.baseColor = albedo.rgb;
    s.occlusion = albedo.a;
    vec4 material = texelFetch(gbufferMaterial, pixel, 0);
    s.roughness = material.r;
    s.metalness = material.g;
    s.emissive = texelFetch(gbufferEmissive, pixel, 0).rgb;
    readMaterialLayers(pixel, s);
    return s;
}

// The normal used for shading, seen from view direction v (unit, towards the eye). Interpolated
// and normal-mapped normals can face away from the viewer, which would shade them black: bend
// such a normal just past perpendicular to v.
vec3 shadingNormal(vec3 n, vec3 v) {
    float nv = dot(n, v);
    return nv < 0.0 ? normalize(n - v * (nv * 1.01)) : n;
}

// The clear coat's shading normal seen from v: its own (Surface::clearcoatNormal), else the
// base's shading normal `n`.
vec3 coatNormal(Surface s, vec3 n, vec3 v) {
    return dot(s.clearcoatNormal, s.clearcoatNormal) > 0.0 ? shadingNormal(s.clearcoatNormal, v) : n;
}
float coatNdotV(Surface s, vec3 n, vec3 v) { return max(dot(coatNormal(s, n, v), v), 0.0); }
