#version 450 core
// Cone-strata filter (ConeStrataFilterPass, accurate mode): averages the demodulated indirect
// diffuse of each low-resolution texel with its neighbours over one period of the stratified cone
// sets' pattern (include/cone_strata.glsl), so every texel on a flat surface gets the mean of all
// LIT_CONE_STRATA² sets. Window: LIT_CONE_STRATA + 1 texels per axis with half weight at both
// ends (even periods), which covers each pattern phase exactly once: 1/2 + 1 + 1 + 1 + 1/2 at 4.
// Neighbours on another surface get no weight, as in the resolve (indirect_resolve.glsl): off this
// texel's tangent plane by more than kPlaneTolerance of the view distance, or turned (weight cos^16).
// Rough specular that reused the diffuse cones (cone.glsl, specularCanReuseDiffuseCones) comes
// from the same stratified cones and is averaged the same way (neighbours of another roughness,
// by more than kRoughnessTolerance, get no weight, as in the resolve); other specular, traced by
// its own GGX cones, is passed on unchanged, and so is the guide.
#include "frame.glsl"
#include "gbuffer.glsl"
#include "cone.glsl"
// indirect.glsl: packIndirect, unpackIndirect, octDecode
#include "indirect.glsl"

layout(binding = LIT_TEX_INDIRECT_LOW_PACKED) uniform usampler2D tracedPacked;  // the trace, one set per texel
layout(binding = LIT_TEX_INDIRECT_LOW_GUIDE) uniform usampler2D tracedGuide;    // position, normal (indirect.glsl)

layout(location = 0) out uvec4 outPacked;

const int kRadius = LIT_CONE_STRATA / 2;
const float kEndWeight = (LIT_CONE_STRATA % 2 == 0) ? 0.5 : 1.0;  // odd periods: 2r + 1 = period taps of weight 1
const float kPlaneTolerance = 0.01;     // as the resolve: 1 % of the view distance off the plane → no weight
const float kRoughnessTolerance = 0.2;  // as the resolve

void main() {
    ivec2 low = ivec2(gl_FragCoord.xy);
    uvec4 centre = texelFetch(tracedPacked, low, 0);
    outPacked = centre;
    vec4 d, sp;
    unpackIndirect(centre, d, sp);
    if (d.a <= 0.0) return;  // no diffuse traced here (background, metal, L_ID off)
    uvec4 guide = texelFetch(tracedGuide, low, 0);
    vec3 position = uintBitsToFloat(guide.xyz);
    vec3 normal = octDecode(unpackSnorm2x16(guide.w));
    float viewDistance = max((frame.viewProjection * vec4(position, 1.0)).w, 1e-6);
    ivec2 size = textureSize(tracedPacked, 0);
    vec3 sum = vec3(0.0), specularSum = vec3(0.0);
    float weightSum = 0.0, specularWeightSum = 0.0;
    float roughness = sp.a - 1.0;
    bool reusedCones = sp.a > 0.0 && specularCanReuseDiffuseCones(alphaFromRoughness(roughness), voxel.traceParams.w);
    for (int y = -kRadius; y <= kRadius; ++y) {
        for (int x = -kRadius; x <= kRadius; ++x) {
            ivec2 q = low + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qd, qs;
            unpackIndirect(texelFetch(tracedPacked, q, 0), qd, qs);
            if (qd.a <= 0.0) continue;
            uvec4 qg = texelFetch(tracedGuide, q, 0);
            float plane = abs(dot(normal, uintBitsToFloat(qg.xyz) - position)) / viewDistance;
            // cos^16 by four squarings (pow is exp2(16·log2) on llvmpipe, per tap).
            float turn = max(dot(normal, octDecode(unpackSnorm2x16(qg.w))), 0.0);
            turn *= turn;
            turn *= turn;
            turn *= turn;
            turn *= turn;
            float w = (abs(x) == kRadius ? kEndWeight : 1.0) * (abs(y) == kRadius ? kEndWeight : 1.0) *
                      max(1.0 - plane / kPlaneTolerance, 0.0) * turn;
            sum += w * qd.rgb;
            weightSum += w;
            if (reusedCones && qs.a > 0.0) {
                float ws = w * max(1.0 - abs(qs.a - 1.0 - roughness) / kRoughnessTolerance, 0.0);
                specularSum += ws * qs.rgb;
                specularWeightSum += ws;
            }
        }
    }
    // The centre always counts (weight ≥ ¼ · 1 · 1 > 0), so weightSum > 0, and specularWeightSum
    // > 0 when reusedCones.
    if (reusedCones) sp.rgb = specularSum / specularWeightSum;
    outPacked = packIndirect(vec4(sum / weightSum, 1.0), sp);
}
