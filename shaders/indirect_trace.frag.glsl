#version 450 core
// Low-resolution cone trace (ConeTracePass at IndirectSettings::scale > 1, or with temporal
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
#include "voxel_irradiance.glsl"

// The cached mode (LIT_VOXEL_IRRADIANCE) in two programs (ConeTracePass::executeReduced): without
// LIT_TRACE_LOBES the gather, with no cone code, writes every texel and marks in the lobe mask
// (gl_FragDepth 0) those whose specular lobe needs cones (rougher than uSmoothRoughness, too narrow
// for the gathered irradiance); with it, early depth tests run the whole texel again, lobe
// included, on the marked texels only. The same texel results as one program doing both; on
// llvmpipe the mere presence of the lobe's cone loops, never taken on a rough wall, cost the gather
// 40 % of its time. The other modes trace cones for L_ID anyway and use one program.
#ifndef LIT_TRACE_LOBES
#define LIT_TRACE_LOBES 0
#endif
#if LIT_VOXEL_IRRADIANCE && LIT_TRACE_LOBES
layout(early_fragment_tests) in;  // the lobe mask's depth test decides before the shader runs
#endif
// Tests only (GiAccuracy.CachedTraceLobePassEqualsOneProgramForEveryTexel): 1 marks every texel
// with a specular lobe, so that the lobe pass does all of them.
#ifndef LIT_LOBES_FOR_EVERY_TEXEL
#define LIT_LOBES_FOR_EVERY_TEXEL 0
#endif
const float kLobeTrace = 0.0;  // lobe-mask depth of a texel the lobe pass traces
const float kLobeDone = 1.0;

layout(location = 0) out uvec4 outPacked;
layout(location = 1) out uvec4 outGuide;

uniform ivec2 uTraceTerms;       // x: L_ID wanted, y: L_IS wanted (1/0)
uniform float uSmoothRoughness;  // L_IS of smoother surfaces is left to the resolve
uniform int uConeSubset;         // LIT_CONE_SUBSETS: this frame's phase (0..4) of the subsets

// Cone subsets (LIT_CONE_SUBSETS 1, a separate program: IndirectSettings::temporalConeSubsets with
// temporal accumulation; ConeTracePass::executeReduced picks it): a texel traces the normal cone and two of the five side cones, k and k + 2
// (mod 5, 144° apart), k = (phase + x + 2y) mod 5 for texel (x, y), so the four neighbours of a
// texel trace the other four pairs and each side cone comes back every five frames. Half the
// marching per texel (3 of 6 cones); the irradiance estimate
//   D = W_0·C_0 + (1 − W_0)·½(C_k + C_{k+2})
// is exact in a uniform field (the furnace holds every frame) and its mean over the five phases
// is the full set's W_0·C_0 + Σ W_i·C_i (each side cone is in two of the five pairs, W_i = (1 − W_0)/5);
// the temporal accumulation averages the phases (docs/GI.md, "Cone subsets"). With
// footprint-bounded cones (the accurate mode) the cones are those of the texel's stratified set
// (cone_strata.glsl), whose regions have the fixed table's weights, so the same estimate holds per
// set; the strata filter then averages the texels' sets as without subsets, and since the accurate
// mode's sets do not turn with the frame, five frames of one texel are exactly its whole set.
#ifndef LIT_CONE_SUBSETS
#define LIT_CONE_SUBSETS 0
#endif
#if LIT_CONE_SUBSETS && LIT_DIFFUSE_CONE_COUNT != 6
#error "cone subsets need the six-cone table"
#endif

#if LIT_CONE_SUBSETS
const int kSideCones = kDiffuseConeCount - 1;

// The first side cone (1..5) of texel `low`'s pair at phase `phase`; the second is secondSideCone().
int firstSideCone(ivec2 low, int phase) { return 1 + (phase + low.x + 2 * low.y) % kSideCones; }
int secondSideCone(int first) { return 1 + (first - 1 + 2) % kSideCones; }

// Diffuse cone i of texel `low`: the fixed table's (unbounded cones) or the texel's stratified set's.
vec3 traceSubsetCone(vec3 origin, mat3 basis, int i, ivec2 low, float aperture, float maxDistance) {
#if LIT_CONE_FOOTPRINT
    return traceStratifiedDiffuseCone(origin, basis, i, coneSetIndex(low), aperture, maxDistance);
#else
    return traceDiffuseCone(origin, basis, i, aperture, maxDistance);
#endif
}

// radianceFromDiffuseCones (cone.glsl) over the traced cones only: 0, a and b.
vec3 radianceFromConeSubset(vec3 l, vec3 cones[kDiffuseConeCount], int a, int b) {
    int traced[3] = int[](0, a, b);
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int j = 0; j < 3; ++j) {
        float w = max(dot(l, kDiffuseConeDirections[traced[j]]) - 0.5, 0.0);
        sum += (w * w) * cones[traced[j]];
        weightSum += w * w;
    }
    return weightSum > 0.0 ? sum / weightSum : cones[0];
}
#endif

void main() {
    ivec2 pixel = tracedPixel(ivec2(gl_FragCoord.xy));
    vec2 uv = (vec2(pixel) + 0.5) * frame.viewport.zw;
    Surface s = readSurface(pixel, uv);
    // This pass traces the specular lobe's radiance only (the resolve weighs it): a smoother
    // clear coat sets the lobe's roughness (docs/MATERIALS.md).
    s.roughness = specularLobeRoughness(s);
    vec4 outDiffuse = vec4(0.0), outSpecular = vec4(0.0);
    outPacked = uvec4(0u);
    outGuide = uvec4(0u);
#if LIT_VOXEL_IRRADIANCE && !LIT_TRACE_LOBES
    gl_FragDepth = kLobeDone;
#endif
    if (!s.valid) return;
    outGuide = packGuide(s.position, s.normal);
    vec3 v = normalize(frame.cameraPosition.xyz - s.position);
    vec3 n = shadingNormal(s.normal, v);
    vec3 origin = coneOrigin(s.position, n);
    float maxDistance = voxel.traceParams.y;
    mat3 basis = rotatedTangentFrame(n, coneSetRotation());

    int count = clamp(voxel.traceOptions.x, 1, 8);
    vec3 albedo = indirectDiffuseAlbedo(s, max(dot(n, v), 0.0), coatNdotV(s, n, v));
    bool diffuseSurface = max(albedo.r, max(albedo.g, albedo.b)) > 0.0;
    bool specular = uTraceTerms.y != 0 && s.roughness >= uSmoothRoughness;
    // As cone_trace.frag.glsl: rough specular on a diffuse surface reuses the diffuse cones.
    bool reuse = specular && diffuseSurface &&
                 specularCanReuseDiffuseCones(alphaFromRoughness(s.roughness), voxel.traceParams.w);
#if LIT_VOXEL_IRRADIANCE
    // No diffuse cones to reuse: a lobe wide enough to have reused them (a rough lobe on a diffuse
    // surface) takes the gathered irradiance/π, the cosine-weighted mean radiance over the
    // hemisphere, in their place; it loses the lobe's direction, which the six cones' weighting
    // kept: the Cornell regions read 2-5 % more, the frame costs 0.70-0.76× of tracing the lobes
    // (docs/GI.md, "Indirect specular: GGX cones"). Narrower lobes trace their own cones.
    bool lobeFromIrradiance = reuse;
    reuse = false;
#endif
    vec3 cones[kDiffuseConeCount];
#if LIT_VOXEL_IRRADIANCE
    // Never read (reuse is false here), but passed to traceSpecularLobe: defined, so the shader
    // compiler has no uninitialized use to warn about in the editor's log.
    for (int i = 0; i < kDiffuseConeCount; ++i) cones[i] = vec3(0.0);
#endif
    bool diffuseWanted = (uTraceTerms.x != 0 || reuse) && diffuseSurface;
#if LIT_VOXEL_IRRADIANCE
    bool gatheredNothing = false;
    vec3 gathered = diffuseWanted || (specular && lobeFromIrradiance)
                        ? gatherVoxelIrradiance(s.position, n, gatheredNothing)
                        : vec3(0.0);
#if LIT_TRACE_LOBES
    // No voxel around the point faces this way: the diffuse cones give its irradiance/π instead
    // (the same estimate the accurate and fast modes use), for the lobe too.
    if (gatheredNothing) gathered = traceDiffuseInFrame(origin, basis, voxel.traceParams.w, maxDistance, cones);
#else
    if (gatheredNothing) {
        gl_FragDepth = kLobeTrace;  // the lobe pass traces this texel's cones
        return;
    }
#endif
#endif
#if LIT_CONE_SUBSETS
    {
        int a = firstSideCone(ivec2(gl_FragCoord.xy), uConeSubset), b = secondSideCone(a);
        if (diffuseWanted) {
            for (int i = 0; i < kDiffuseConeCount; ++i) cones[i] = vec3(0.0);
            int traced[3] = int[](0, a, b);
            for (int j = 0; j < 3; ++j)
                cones[traced[j]] = traceSubsetCone(origin, basis, traced[j], ivec2(gl_FragCoord.xy),
                                                   voxel.traceParams.w, maxDistance);
            float w0 = kDiffuseConeWeights[0];
            outDiffuse = vec4(w0 * cones[0] + (1.0 - w0) * 0.5 * (cones[a] + cones[b]), 1.0);
        }
        if (specular) {
            vec3 lobe;
            if (reuse) {
                // traceSpecularLobe's reuse branch with the subset's cones (same samples and weights).
                float alpha = alphaFromRoughness(s.roughness);
                vec3 weighted = vec3(0.0);
                float weightSum = 0.0;
                for (int k = 0; k < count; ++k) {
                    vec3 l;
                    float w = specularLobeCone(k, count, n, v, basis, alpha, vec2(pixel), voxel.traceOptions.y, l);
                    if (w <= 0.0) continue;
                    weighted += w * radianceFromConeSubset(normalize(l * basis), cones, a, b);
                    weightSum += w;
                }
                lobe = weightSum > 0.0 ? weighted / weightSum
                                       : radianceFromConeSubset(normalize(reflect(-v, n) * basis), cones, a, b);
            } else {
                lobe = traceSpecularLobe(origin, n, basis, v, s.roughness, count, vec2(pixel), voxel.traceOptions.y,
                                         maxDistance, false, cones);
            }
            outSpecular = vec4(lobe, 1.0 + s.roughness);
        }
    }
#else
    if (diffuseWanted)
#if LIT_VOXEL_IRRADIANCE
        outDiffuse = vec4(gathered, 1.0);
#elif LIT_CONE_FOOTPRINT
        // Bounded cones: this texel's stratified set (cone_strata.glsl; ConeStrataFilterPass averages the sets).
        outDiffuse = vec4(traceDiffuseStratified(origin, basis, coneSetIndex(ivec2(gl_FragCoord.xy)), voxel.traceParams.w,
                                                 maxDistance, cones), 1.0);
#else
        outDiffuse = vec4(traceDiffuseInFrame(origin, basis, voxel.traceParams.w, maxDistance, cones), 1.0);
#endif
    if (specular) {
#if LIT_VOXEL_IRRADIANCE && LIT_TRACE_LOBES
        vec3 lobe = lobeFromIrradiance ? gathered
                                       : traceSpecularLobe(origin, n, basis, v, s.roughness, count, vec2(pixel),
                                                           voxel.traceOptions.y, maxDistance, false, cones);
#elif LIT_VOXEL_IRRADIANCE
        if (!lobeFromIrradiance || LIT_LOBES_FOR_EVERY_TEXEL != 0) {
            gl_FragDepth = kLobeTrace;  // the lobe pass redoes this texel
            return;
        }
        vec3 lobe = gathered;
#else
        vec3 lobe = traceSpecularLobe(origin, n, basis, v, s.roughness, count, vec2(pixel), voxel.traceOptions.y,
                                      maxDistance, reuse, cones);
#endif
        outSpecular = vec4(lobe, 1.0 + s.roughness);
    }
#endif
    outPacked = packIndirect(outDiffuse, outSpecular);
}
