// Reading the G-buffer in full-screen passes.
#include "shared.h"

layout(binding = LIT_TEX_GBUFFER_ALBEDO) uniform sampler2D gbufferAlbedo;
layout(binding = LIT_TEX_GBUFFER_NORMAL) uniform sampler2D gbufferNormal;
layout(binding = LIT_TEX_GBUFFER_MATERIAL) uniform sampler2D gbufferMaterial;
layout(binding = LIT_TEX_GBUFFER_EMISSIVE) uniform sampler2D gbufferEmissive;
layout(binding = LIT_TEX_GBUFFER_DEPTH) uniform sampler2D gbufferDepth;

struct Surface {
    bool valid;        // false for background pixels
    vec3 position;     // world (m)
    vec3 normal;       // world, unit
    vec3 baseColor;    // linear
    float occlusion;
    float roughness;
    float metalness;
    vec3 emissive;
};

Surface readSurface(ivec2 pixel, vec2 uv) {
    Surface s;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    s.valid = depth < 1.0;
    s.position = worldPositionFromDepth(uv, depth);
    s.normal = normalize(texelFetch(gbufferNormal, pixel, 0).xyz);
    vec4 albedo = texelFetch(gbufferAlbedo, pixel, 0);
    s.baseColor = albedo.rgb;
    s.occlusion = albedo.a;
    vec4 material = texelFetch(gbufferMaterial, pixel, 0);
    s.roughness = material.r;
    s.metalness = material.g;
    s.emissive = texelFetch(gbufferEmissive, pixel, 0).rgb;
    return s;
}

// The normal used for shading, seen from view direction v (unit, towards the eye). Interpolated
// and normal-mapped normals can face away from the viewer, which would shade them black: bend
// such a normal just past perpendicular to v.
vec3 shadingNormal(vec3 n, vec3 v) {
    float nv = dot(n, v);
    return nv < 0.0 ? normalize(n - v * (nv * 1.01)) : n;
}
