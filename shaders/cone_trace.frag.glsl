#version 450 core
// Cone-tracing pass: the two indirect terms of every pixel from the radiance volume.
//   L_ID = a · Σ_i W_i/π · C_i                              (six diffuse cones, cone.glsl)
//   L_IS = E · Σ_k w_k C(l_k) / Σ_k w_k      (N GGX-sampled cones, split sum, cone.glsl;
//          on rough diffuse surfaces C(l_k) is blended from the six diffuse cones instead)
// with a = indirectDiffuseAlbedo (the base's albedo and the sheen's, under a clear coat) and
// E = indirectSpecularWeight times what a sheen leaves of the base, the lobe traced at
// specularLobeRoughness (docs/MATERIALS.md).
// both × indirect intensity (traceParams.x) × the material's ambient occlusion (G-buffer albedo.a).
// Background pixels write 0. docs/GI.md derives the weights.
#include "frame.glsl"
#include "gbuffer.glsl"
#include "cone.glsl"

in vec2 vUv;

layout(location = 0) out vec4 outIndirectDiffuse;
layout(location = 1) out vec4 outIndirectSpecular;

uniform ivec2 uTraceTerms;  // x: trace L_ID, y: trace L_IS (1/0); a term not traced writes 0

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface s = readSurface(pixel, vUv);
    float scale = voxel.traceParams.x * s.occlusion;
    if (!s.valid || scale <= 0.0) {
        outIndirectDiffuse = vec4(0.0);
        outIndirectSpecular = vec4(0.0);
        return;
    }
    vec3 v = normalize(frame.cameraPosition.xyz - s.position);
    vec3 n = shadingNormal(s.normal, v);
    vec3 origin = coneOrigin(s.position, n);
    float maxDistance = voxel.traceParams.y;

    int count = clamp(voxel.traceOptions.x, 1, 8);
    float NdotV = max(dot(n, v), 0.0);
    float NcdotV = coatNdotV(s, n, v);
    vec3 albedo = indirectDiffuseAlbedo(s, NdotV, NcdotV);
    bool diffuseSurface = max(albedo.r, max(albedo.g, albedo.b)) > 0.0;
    float lobeRoughness = specularLobeRoughness(s);
    // Rough specular on a surface with diffuse cones reuses them (cone.glsl). It does so also when
    // only L_IS is shown, so that the term views add up to the final image.
    bool reuse = uTraceTerms.y != 0 && diffuseSurface &&
                 specularCanReuseDiffuseCones(alphaFromRoughness(lobeRoughness), voxel.traceParams.w);
    vec3 diffuse = vec3(0.0);
    vec3 cones[kDiffuseConeCount];
    if ((uTraceTerms.x != 0 || reuse) && diffuseSurface) {
        vec3 irradiance = traceDiffuse(origin, n, voxel.traceParams.w, maxDistance, cones);
        if (uTraceTerms.x != 0) diffuse = albedo * irradiance;
    }

    vec3 specular = vec3(0.0);
    if (uTraceTerms.y != 0)
        specular = indirectSpecularWeight(s.f0, s.f90, s.roughness, sheenBaseScale(s, NdotV), s.clearcoat,
                                          s.clearcoatRoughness, NdotV, NcdotV) *
                   traceSpecular(origin, n, v, lobeRoughness, count, gl_FragCoord.xy, voxel.traceOptions.y,
                                 maxDistance, reuse, cones);
    outIndirectDiffuse = vec4(diffuse * scale, 1.0);
    outIndirectSpecular = vec4(specular * scale, 1.0);
}
