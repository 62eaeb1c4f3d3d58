#version 450 core
// Direct lighting pass: for every pixel, the two direct terms from all punctual lights.
//   L_DD = Σ V · E · (albedo_d / π · t + f_sheen) · max(n·l, 0) · b          (Lambert, sheen)
//   L_DS = Σ V · E · (D·G·F / (4 (n·l)(n·v)) · t · b + cc · f_coat) · max(n·l, 0)   (GGX microfacet)
// where E is the light's irradiance at normal incidence (docs/UNITS.md), V the shadow-map
// visibility, t = 1 − max(s_c)·E_s(n·v) what a sheen leaves of the base, f_sheen its lobe,
// b = 1 − cc·Fc(n·v) what a clear coat of weight cc lets through and f_coat its lobe
// (docs/MATERIALS.md; the coat shares the shading normal here). Emission is added to L_DD so
// that the four terms still sum to the final image.
#include "frame.glsl"
#include "gbuffer.glsl"
#include "brdf.glsl"
#include "lights.glsl"

in vec2 vUv;

layout(location = 0) out vec4 outDirectDiffuse;
layout(location = 1) out vec4 outDirectSpecular;

uniform float uShadowNormalOffset;  // shadow lookup offset along the normal, in shadow texels

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface s = readSurface(pixel, vUv);
    if (!s.valid) {
        outDirectDiffuse = vec4(0.0);
        outDirectSpecular = vec4(0.0);
        return;
    }
    vec3 v = normalize(frame.cameraPosition.xyz - s.position);
    vec3 n = shadingNormal(s.normal, v);
    float alpha = alphaFromRoughness(s.roughness);
    vec3 albedo = diffuseAlbedo(s.baseColor, s.metalness);
    float NdotV = max(dot(n, v), 0.0);
    float coatScale = clearcoatBaseScale(s.clearcoat, NdotV);
    float base = coatScale * sheenBaseScale(s, NdotV);
    float coatAlpha = alphaFromRoughness(s.clearcoatRoughness);
    bool sheen = max(s.sheenColor.r, max(s.sheenColor.g, s.sheenColor.b)) > 0.0;
    float alphaSheen = sheenAlpha(s.sheenRoughness);

    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    int count = frame.counts.x;
    for (int i = 0; i < count; ++i) {
        GpuLight light = lights[i];
        LightSample ls = sampleLight(light, s.position);
        float NdotL = dot(n, ls.l);
        if (NdotL <= 0.0 || max(ls.radiance.r, max(ls.radiance.g, ls.radiance.b)) <= 0.0) continue;
        vec3 visibility = shadowVisibility(light, s.position, n, frame.exposure.y, uShadowNormalOffset);
        if (max(visibility.r, max(visibility.g, visibility.b)) <= 0.0) continue;
        vec3 E = ls.radiance * visibility * NdotL;
        diffuse += E * albedo * (base / PI);
        if (sheen) {
            vec3 h = normalize(v + ls.l);
            diffuse += E * s.sheenColor *
                       (D_Charlie(max(dot(n, h), 0.0), alphaSheen) * V_Neubelt(NdotL, max(NdotV, 1e-4)) * coatScale);
        }
        specular += E * specularBrdf(n, v, ls.l, s.f0, s.f90, alpha) * base;
        if (s.clearcoat > 0.0) specular += E * s.clearcoat * specularBrdf(n, v, ls.l, kClearcoatF0, 1.0, coatAlpha);
    }
    outDirectDiffuse = vec4(diffuse + s.emissive, 1.0);
    outDirectSpecular = vec4(specular, 1.0);
}
