// Indirect resolve, the body shared by indirect_resolve.frag.glsl (IndirectResolvePass) and
// indirect_fallback.frag.glsl (IndirectFallbackPass). It upsamples the low-resolution demodulated terms of
// indirect_trace.frag.glsl to every pixel with depth- and normal-aware (joint bilateral) weights,
// traces at full resolution what they cannot stand for, optionally accumulates over frames, and
// writes the terms:
//   L_ID = a · D · intensity · AO,   L_IS = E · S · intensity · AO
// with D the irradiance/π and S the lobe-averaged radiance of this pixel (indirect.glsl),
// a = indirectDiffuseAlbedo and E = indirectSpecularWeight times what a sheen leaves of the base
// (docs/MATERIALS.md).
//
// Upsampling. The pixel sits among the four low-resolution texels whose traced pixels surround
// it; each is weighted by its bilinear weight (plus a small floor, so a neighbour on the same
// surface still counts when the nearer ones lie across an edge), by how far its surface point
// lies off this pixel's tangent plane (relative to the view distance: walls meeting at a corner,
// an object in front of a wall), and by how far its normal turns. Rough specular also weights by
// roughness. Where no neighbour is on this pixel's surface (thin objects, silhouettes) the pixel
// traces its own cones, so indirect light never bleeds across a depth or normal edge.
//
// Two passes, so that the common pixel runs no cone code. Without LIT_INDIRECT_FALLBACK (the
// resolve) a pixel that needs its own trace is only marked: gl_FragDepth 0 (kMarkTrace) in the
// pass's trace mask, 1 elsewhere; its outputs are left for the fallback. With it (the fallback)
// early depth tests against that mask run this body on the marked pixels only, with the trace.
// Both compute the same upsampling and accumulation, so the image is that of one pass doing both.
// (On llvmpipe the mere presence of the cone loops in the resolve cost about half its time.)
//
// Temporal accumulation (uHistoryValid). The surface point is projected into the last frame with
// its view-projection; the history there is used when that pixel saw the same surface (clip w
// within kHistoryDepthTolerance, normals within kHistoryNormalCos), else it is dropped
// (disocclusion). The history is clamped to the range of this frame's low-resolution neighbours
// (widened by uClampMargin) so stale light does not linger, then blended with weight
// 1 / (frames + 1), frames ≤ uMaxFrames: a still camera averages the rotated cone sets.
#include "frame.glsl"
#include "gbuffer.glsl"
#include "cone.glsl"
#include "indirect.glsl"
#include "cone_strata.glsl"
#include "voxel_irradiance.glsl"

#ifdef LIT_INDIRECT_FALLBACK
layout(early_fragment_tests) in;  // the trace mask's depth test decides before the shader runs
#endif
// 0: the resolve without temporal accumulation (IndirectResolvePass's plain program), whose
// history block is then not compiled: llvmpipe runs a uniform branch's body with every lane
// masked off, and the history's three fetches cost the resolve 6-7 of its 55 ms with temporal
// accumulation off (full-frame Cornell box, 1280×720; docs/PERFORMANCE.md, "llvmpipe").
#ifndef LIT_RESOLVE_HISTORY
#define LIT_RESOLVE_HISTORY 1
#endif

in vec2 vUv;

layout(location = 0) out vec4 outIndirectDiffuse;   // L_ID
layout(location = 1) out vec4 outIndirectSpecular;  // L_IS
layout(location = 2) out vec4 outHistoryDiffuse;    // D, a = frames accumulated
layout(location = 3) out vec4 outHistorySpecular;   // S, a = frames accumulated
layout(location = 4) out vec4 outHistoryGuide;      // normal, clip w (0 = background)

layout(binding = LIT_TEX_INDIRECT_LOW_PACKED) uniform usampler2D lowPacked;
layout(binding = LIT_TEX_INDIRECT_LOW_GUIDE) uniform usampler2D lowGuide;
layout(binding = LIT_TEX_HISTORY_DIFFUSE) uniform sampler2D historyDiffuse;
layout(binding = LIT_TEX_HISTORY_SPECULAR) uniform sampler2D historySpecular;
layout(binding = LIT_TEX_HISTORY_GUIDE) uniform sampler2D historyGuide;

uniform ivec2 uTraceTerms;        // x: L_ID, y: L_IS (1/0)
uniform float uSmoothRoughness;   // L_IS of smoother surfaces is traced here, per pixel
uniform int uHistoryValid;        // 1: the history textures hold the last frame's result
uniform int uMaxFrames;           // frames of history at most
uniform mat4 uPrevViewProjection; // the last frame's world → clip

// A neighbour 1 % of the view distance off this pixel's tangent plane gets no weight: walls of
// the Cornell box seen at 1280×720 are < 0.1 % off their plane 4 pixels away, a box standing on
// the floor is its height (≫ 1 %) off it.
const float kPlaneTolerance = 0.01;
// cos^16: 30° apart → 0.1 weight, 45° → 0.004. By squaring: pow() is exp2(16·log2) per lane on
// llvmpipe, and four a pixel cost the resolve 5-8 of its 57 ms (full-frame Cornell box, 1280×720).
float normalPower16(float c) {
    float c2 = c * c, c4 = c2 * c2, c8 = c4 * c4;
    return c8 * c8;
}
const float kRoughnessTolerance = 0.2; // rough specular: neighbours this much rougher/smoother get no weight
const float kSpatialFloor = 0.02;      // added to each bilinear weight
const float kMinWeight = 1e-3;         // below: no neighbour stands for this pixel → trace it here
const float kHistoryDepthTolerance = 0.02;  // relative clip-w difference of a reprojected pixel
const float kHistoryNormalCos = 0.9;        // cos 25.8°
const float kMarkTrace = 0.0;  // trace-mask depth of a pixel the fallback traces (IndirectFallbackPass)
const float kMarkDone = 1.0;   // of one the resolve finished

// The neighbourhood box is widened by this fraction of its bounds (IndirectResolvePass::clampMargin:
// 10 %, wider with the accurate mode's cone subsets, whose neighbours all hold one frame's pairs).
uniform float uClampMargin;

vec3 clampToBox(vec3 value, vec3 lo, vec3 hi) {
    return clamp(value, lo * (1.0 - uClampMargin), hi * (1.0 + uClampMargin));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // readSurface without the emissive target, which this pass does not use.
    Surface s;
    float pixelDepth = texelFetch(gbufferDepth, pixel, 0).r;
    s.valid = pixelDepth < 1.0;
    outIndirectDiffuse = vec4(0.0);
    outIndirectSpecular = vec4(0.0);
    outHistoryDiffuse = vec4(0.0);
    outHistorySpecular = vec4(0.0);
    outHistoryGuide = vec4(0.0);
#ifndef LIT_INDIRECT_FALLBACK
    gl_FragDepth = kMarkDone;
#endif
    if (!s.valid) return;
    s.position = worldPositionFromDepth(vUv, pixelDepth);
    s.normal = normalize(texelFetch(gbufferNormal, pixel, 0).xyz);
    vec4 albedoAo = texelFetch(gbufferAlbedo, pixel, 0);
    s.baseColor = albedoAo.rgb;
    s.occlusion = albedoAo.a;
    vec2 material = texelFetch(gbufferMaterial, pixel, 0).rg;
    s.roughness = material.r;
    s.metalness = material.g;
    s.footprint = 0.0;  // the direct light's alone
    readMaterialLayers(pixel, s);
    // The lobe is traced, upsampled and accumulated at the lobe's roughness (a smoother clear coat
    // sets it); the base's own roughness weighs it at the end.
    float baseRoughness = s.roughness;
    s.roughness = specularLobeRoughness(s);
    float scale = voxel.traceParams.x * s.occlusion;
    float clipW = (frame.viewProjection * vec4(s.position, 1.0)).w;
    vec3 v = normalize(frame.cameraPosition.xyz - s.position);
    vec3 n = shadingNormal(s.normal, v);
    float NdotV = max(dot(n, v), 0.0);
    float NcdotV = coatNdotV(s, n, v);
    vec3 albedo = indirectDiffuseAlbedo(s, NdotV, NcdotV);
    bool diffuseSurface = max(albedo.r, max(albedo.g, albedo.b)) > 0.0;
    bool smoothSurface = s.roughness < uSmoothRoughness;

    // ---- Upsampling: the four low-resolution texels around this pixel.
    ivec2 lowSize = textureSize(lowPacked, 0);
    vec2 c = (vec2(pixel) - vec2(uJitter)) / float(uScale);
    ivec2 base = ivec2(floor(c));
    vec2 f = c - vec2(base);
    vec3 diffuseSum = vec3(0.0), specularSum = vec3(0.0);
    float diffuseWeight = 0.0, specularWeight = 0.0;
    vec3 diffuseLo = vec3(1e30), diffuseHi = vec3(0.0), specularLo = vec3(1e30), specularHi = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec2 offset = ivec2(i & 1, i >> 1);
        ivec2 low = clamp(base + offset, ivec2(0), lowSize - 1);
        vec2 bilinear = mix(1.0 - f, f, vec2(offset));
        float spatial = bilinear.x * bilinear.y + kSpatialFloor;
        vec4 d, sp;
        unpackIndirect(texelFetch(lowPacked, low, 0), d, sp);
        if (d.a <= 0.0 && sp.a <= 0.0) continue;  // nothing traced there (background, ...)
        uvec4 guide = texelFetch(lowGuide, low, 0);
        vec3 p = uintBitsToFloat(guide.xyz);
        vec3 normal = octDecode(unpackSnorm2x16(guide.w));
        float plane = abs(dot(s.normal, p - s.position)) / max(clipW, 1e-6);
        float w = spatial * max(1.0 - plane / kPlaneTolerance, 0.0) * normalPower16(max(dot(s.normal, normal), 0.0));
        if (w <= 0.0) continue;
        if (d.a > 0.0) {
            diffuseSum += w * d.rgb;
            diffuseWeight += w;
            diffuseLo = min(diffuseLo, d.rgb);
            diffuseHi = max(diffuseHi, d.rgb);
        }
        if (sp.a > 0.0 && !smoothSurface) {
            float ws = w * max(1.0 - abs(sp.a - 1.0 - s.roughness) / kRoughnessTolerance, 0.0);
            if (ws > 0.0) {
                specularSum += ws * sp.rgb;
                specularWeight += ws;
                specularLo = min(specularLo, sp.rgb);
                specularHi = max(specularHi, sp.rgb);
            }
        }
    }

    bool wantDiffuse = uTraceTerms.x != 0 && diffuseSurface;
    bool wantSpecular = uTraceTerms.y != 0;
    bool traceDiffuseHere = wantDiffuse && diffuseWeight < kMinWeight;
    bool traceSpecularHere = wantSpecular && (smoothSurface || specularWeight < kMinWeight);
    vec3 diffuse = diffuseWeight > 0.0 ? diffuseSum / diffuseWeight : vec3(0.0);
    vec3 specular = specularWeight > 0.0 ? specularSum / specularWeight : vec3(0.0);
    if (traceDiffuseHere || traceSpecularHere) {
#ifndef LIT_INDIRECT_FALLBACK
        gl_FragDepth = kMarkTrace;  // the fallback pass redoes this pixel with its own cones
        return;
#else
        // Nothing nearby stands for this pixel: trace its own cones (as indirect_trace does).
        vec3 origin = coneOrigin(s.position, n);
        float maxDistance = voxel.traceParams.y;
        mat3 basis = rotatedTangentFrame(n, coneSetRotation());
        int count = clamp(voxel.traceOptions.x, 1, 8);
        bool reuse = traceSpecularHere && diffuseSurface &&
                     specularCanReuseDiffuseCones(alphaFromRoughness(s.roughness), voxel.traceParams.w);
        vec3 cones[kDiffuseConeCount];
#if LIT_VOXEL_IRRADIANCE
        for (int i = 0; i < kDiffuseConeCount; ++i) cones[i] = vec3(0.0);  // never read (as in indirect_trace)
        // As indirect_trace.frag.glsl: a lobe wide enough to reuse diffuse cones takes the gathered
        // irradiance instead.
        bool gatheredNothing = false;
        vec3 gathered = traceDiffuseHere || (traceSpecularHere && reuse)
                            ? gatherVoxelIrradiance(s.position, n, gatheredNothing)
                            : vec3(0.0);
        if (gatheredNothing) gathered = traceDiffuseInFrame(origin, basis, voxel.traceParams.w, maxDistance, cones);
        if (traceDiffuseHere) diffuse = gathered;
        if (traceSpecularHere)
            specular = reuse ? gathered
                             : traceSpecularLobe(origin, n, basis, v, s.roughness, count, gl_FragCoord.xy,
                                                 voxel.traceOptions.y, maxDistance, false, cones);
#else
        if (traceDiffuseHere || reuse) {
#if LIT_CONE_FOOTPRINT
            // The stratified set of the low-resolution texel this pixel falls in (cone_strata.glsl).
            vec3 traced = traceDiffuseStratified(origin, basis, coneSetIndex((pixel - uJitter) / uScale),
                                                 voxel.traceParams.w, maxDistance, cones);
#else
            vec3 traced = traceDiffuseInFrame(origin, basis, voxel.traceParams.w, maxDistance, cones);
#endif
            if (traceDiffuseHere) diffuse = traced;
        }
        if (traceSpecularHere)
            specular = traceSpecularLobe(origin, n, basis, v, s.roughness, count, gl_FragCoord.xy, voxel.traceOptions.y,
                                         maxDistance, reuse, cones);
#endif  // LIT_VOXEL_IRRADIANCE
#endif  // LIT_INDIRECT_FALLBACK
    }

    // ---- Temporal accumulation.
    float diffuseFrames = 1.0, specularFrames = 1.0;
#if LIT_RESOLVE_HISTORY
    if (uHistoryValid != 0) {
        vec4 prevClip = uPrevViewProjection * vec4(s.position, 1.0);
        vec2 prevUv = prevClip.w > 0.0 ? prevClip.xy / prevClip.w * 0.5 + 0.5 : vec2(-1.0);
        if (all(greaterThanEqual(prevUv, vec2(0.0))) && all(lessThan(prevUv, vec2(1.0)))) {
            ivec2 prevPixel = ivec2(prevUv * frame.viewport.xy);
            vec4 guide = texelFetch(historyGuide, prevPixel, 0);
            bool sameSurface = guide.w > 0.0 && abs(guide.w - prevClip.w) < kHistoryDepthTolerance * prevClip.w &&
                               dot(guide.xyz, s.normal) > kHistoryNormalCos;
            if (sameSurface) {
                vec4 hd = texelFetch(historyDiffuse, prevPixel, 0);
                vec4 hs = texelFetch(historySpecular, prevPixel, 0);
                if (hd.a > 0.0) {
                    vec3 h = traceDiffuseHere ? hd.rgb : clampToBox(hd.rgb, diffuseLo, diffuseHi);
                    diffuseFrames = min(hd.a + 1.0, float(uMaxFrames));
                    diffuse = mix(h, diffuse, 1.0 / diffuseFrames);
                }
                if (hs.a > 0.0) {
                    vec3 h = traceSpecularHere ? hs.rgb : clampToBox(hs.rgb, specularLo, specularHi);
                    specularFrames = min(hs.a + 1.0, float(uMaxFrames));
                    specular = mix(h, specular, 1.0 / specularFrames);
                }
            }
        }
    }
#endif
    outHistoryDiffuse = vec4(diffuse, diffuseFrames);
    outHistorySpecular = vec4(specular, specularFrames);
    outHistoryGuide = vec4(s.normal, clipW);

    if (scale <= 0.0) return;
    if (wantDiffuse) outIndirectDiffuse = vec4(albedo * diffuse * scale, 1.0);
    if (wantSpecular)
        outIndirectSpecular =
            vec4(indirectSpecularWeight(s.f0, s.f90, baseRoughness, sheenBaseScale(s, NdotV), s.clearcoat,
                                        s.clearcoatRoughness, NdotV, NcdotV) *
                     specular * scale, 1.0);
}
