#version 450 core
// Low-resolution cone trace (ConeTracePass at RenderSettings::indirectScale > 1, or with temporal
// accumulation): one pixel of every s × s block (tracedPixel, jittered per frame) traces the
// demodulated indirect terms (indirect.glsl) for IndirectResolvePass to upsample.
//   diffuse:  rgb irradiance/π (traceDiffuse), a 1 where it was traced (0: background, metal, L_ID off)
//   specular: rgb lobe-averaged radiance ⟨L⟩, a 1 + roughness where L_IS was traced here; 0 where the
//             surface is smoother than uSmoothRoughness (the resolve traces those at full resolution)
// both packed into out 0, and the traced pixel's position and normal into out 1 (indirect.glsl).
#include "frame.glsl"
#include "gbuffer.glsl"
#include "cone.glsl"
#include "indirect.glsl"
#include "cone_strata.glsl"

layout(location = 0) out uvec4 outPacked;
layout(location = 1) out uvec4 outGuide;

uniform ivec2 uTraceTerms;       // x: L_ID wanted, y: L_IS wanted (1/0)
uniform float uSmoothRoughness;  // L_IS of smoother surfaces is left to the resolve

void main() {
    ivec2 pixel = tracedPixel(ivec2(gl_FragCoord.xy));
    vec2 uv = (vec2(pixel) + 0.5) * frame.viewport.zw;
    Surface s = readSurface(pixel, uv);
    vec4 outDiffuse = vec4(0.0), outSpecular = vec4(0.0);
    outPacked = uvec4(0u);
    outGuide = uvec4(0u);
    if (!s.valid) return;
    outGuide = packGuide(s.position, s.normal);
    vec3 v = normalize(frame.cameraPosition.xyz - s.position);
    vec3 n = shadingNormal(s.normal, v);
    vec3 origin = coneOrigin(s.position, n);
    float maxDistance = voxel.traceParams.y;
    mat3 basis = rotatedTangentFrame(n, coneSetRotation());

    int count = clamp(voxel.traceOptions.x, 1, 8);
    vec3 albedo = diffuseAlbedo(s.baseColor, s.metalness);
    bool diffuseSurface = max(albedo.r, max(albedo.g, albedo.b)) > 0.0;
    bool specular = uTraceTerms.y != 0 && s.roughness >= uSmoothRoughness;
    // As cone_trace.frag.glsl: rough specular on a diffuse surface reuses the diffuse cones.
    bool reuse = specular && diffuseSurface &&
                 specularCanReuseDiffuseCones(alphaFromRoughness(s.roughness), count, voxel.traceParams.w);
    vec3 cones[kDiffuseConeCount];
    if ((uTraceTerms.x != 0 || reuse) && diffuseSurface)
#if LIT_CONE_FOOTPRINT
        // Bounded cones: this texel's stratified set (cone_strata.glsl; ConeStrataFilterPass averages the sets).
        outDiffuse = vec4(traceDiffuseStratified(origin, basis, coneSetIndex(ivec2(gl_FragCoord.xy)), voxel.traceParams.w,
                                                 maxDistance, cones), 1.0);
#else
        outDiffuse = vec4(traceDiffuseInFrame(origin, basis, voxel.traceParams.w, maxDistance, cones), 1.0);
#endif
    if (specular) {
        vec3 lobe = traceSpecularLobe(origin, n, basis, v, s.roughness, count, vec2(pixel), voxel.traceOptions.y,
                                      maxDistance, reuse, cones);
        outSpecular = vec4(lobe, 1.0 + s.roughness);
    }
    outPacked = packIndirect(outDiffuse, outSpecular);
}
