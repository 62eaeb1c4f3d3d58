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
#define LIT_SHADOW_CASCADES 1  // the camera's cascades sharpen the directional lights' shadows
#include "lights.glsl"
#include "direct_light.glsl"

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
    vec3 diffuse, specular;
    directLight(s, n, v, diffuseAlbedo(s.baseColor, s.metalness), uShadowNormalOffset, diffuse, specular);
    outDirectDiffuse = vec4(diffuse + s.emissive, 1.0);
    outDirectSpecular = vec4(specular, 1.0);
}
