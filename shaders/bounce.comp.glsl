#version 450 core
// One more light bounce in the voxel volume (InjectPass::executeBounce): every occupied voxel's
// outgoing radiance becomes its direct radiance plus what it reflects of the light the volume
// holds now,
//   L_{k+1} = L_direct + albedo · Σ_i W_i/π · C_i(L_k)                (W/(sr·m²))
// with six diffuse cones as a pixel traces them (cone.glsl, traceDiffuse), from the voxel centre
// pushed out along its averaged normal. After bounce k the volume holds light that bounced up to
// k times (k = 1 is direct light only), so a pixel that traces it sees k + 1 bounces in all.
// Voxels whose normals disagree (both sides of a thin wall) gather over both hemispheres and
// average them, as injection lights them from both sides. Voxels are treated as Lambertian
// (metals too: docs/GI.md, known limitations).
//
// Work: as inject.comp.glsl, the occupied-voxel list (uFromList = 1; glDispatchComputeIndirect with
// the dispatch size the voxelization wrote, LIT_INJECT_LIST_GROUP_SIZE entries per group) or,
// when the list overflowed, the whole grid in 8³ groups. Only occupied voxels trace cones, and
// over the grid a SIMD vector that holds one of them pays for the whole vector's cones: the
// list packs occupied voxels densely (docs/GI.md, "Bounces", measured 128³).
//
// Accurate mode (LIT_CONE_FOOTPRINT, footprint-bounded cones): a voxel traces one of the
// stratified cone sets of cone_strata.glsl instead of the fixed six-cone set, chosen by its
// coordinates across its surface (voxelConeSetIndex), so that each 4 × 4 patch of a surface's voxels
// holds all 16 sets and the mip levels the pixels' cones read average them (docs/GI.md, "The
// cone-direction view and the bounces with the stratified sets"). The fixed set's pencils would otherwise give every voxel the same
// few directions (what they happen to hit), as they did to the pixels before the sets.
//
// Defines set by InjectPass: LIT_BOUNCE_RGBA8 (1: rgba8 direct volume, 0: rgba16f);
// LIT_BOUNCE_IRRADIANCE 1 (the cached GI mode, InjectPass::executeIrradiance, voxel_irradiance.glsl):
// store each voxel's irradiance/π instead, for the side of its averaged normal and the other side,
// in two volumes of the radiance volume's format (voxel_irradiance_filter.comp.glsl then averages
// them over the cone sets), and leave the radiance as it is; LIT_IRRADIANCE_ALL_SETS 1: average all
// kConeSetCount stratified sets per voxel instead of its one set (kConeSetCount × the cones).
#include "cone.glsl"
#include "cone_strata.glsl"

layout(local_size_x = LIT_INJECT_GROUP_SIZE, local_size_y = LIT_INJECT_GROUP_SIZE, local_size_z = LIT_INJECT_GROUP_SIZE) in;

LIT_VOXEL_LIST_READER

#if LIT_BOUNCE_RGBA8
#define BOUNCE_FORMAT rgba8
#else
#define BOUNCE_FORMAT rgba16f
#endif

layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform readonly uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
#ifndef LIT_BOUNCE_IRRADIANCE
#define LIT_BOUNCE_IRRADIANCE 0
#endif
#ifndef LIT_IRRADIANCE_ALL_SETS
#define LIT_IRRADIANCE_ALL_SETS 0
#endif
#if LIT_BOUNCE_IRRADIANCE
// In the radiance volume's format and encoding (encodeRadiance): RGBA8 halves their memory.
layout(binding = LIT_IMG_VOXEL_DIRECT, BOUNCE_FORMAT) uniform image3D voxelIrradiancePosOut;
layout(binding = LIT_IMG_VOXEL_BOUNCE, BOUNCE_FORMAT) uniform image3D voxelIrradianceNegOut;
// The refinement (RenderSettings::voxelIrradianceRefineVoxelsPerFrame): round k = uSetOffset
// (1..15) traces the set voxelConeSetIndex + k and averages it into what rounds 0..k − 1 left,
// weight uBlend = 1 / (k + 1); round 0 (the edit's trace) writes with weight 1.
uniform int uSetOffset;
uniform float uBlend;
// The amortised update (RenderSettings::voxelIrradianceVoxelsPerFrame) traces a part of the list
// at a time (listedVoxelInRange).
LIT_VOXEL_LIST_RANGE_READER
#else
layout(binding = LIT_IMG_VOXEL_DIRECT, BOUNCE_FORMAT) uniform readonly image3D voxelDirect;
layout(binding = LIT_IMG_VOXEL_BOUNCE) uniform writeonly image3D voxelBounce;
#endif

// Irradiance/π of voxel v's surface seen from the cone origin `origin` with normal `normal`.
vec3 bounceIrradiance(ivec3 v, vec3 origin, vec3 normal, float aperture, float maxDistance) {
#if LIT_CONE_FOOTPRINT && LIT_IRRADIANCE_ALL_SETS
    vec3 cones[kDiffuseConeCount];
    vec3 sum = vec3(0.0);
    mat3 frame = tangentFrame(normal);
    for (int set = 0; set < kConeSetCount; ++set)
        sum += traceDiffuseStratified(origin, frame, set, aperture, maxDistance, cones);
    return sum / float(kConeSetCount);
#elif LIT_CONE_FOOTPRINT
    vec3 cones[kDiffuseConeCount];
#if LIT_BOUNCE_IRRADIANCE
    int set = (voxelConeSetIndex(v, normal) + uSetOffset) % kConeSetCount;
#else
    int set = voxelConeSetIndex(v, normal);
#endif
    return traceDiffuseStratified(origin, tangentFrame(normal), set, aperture, maxDistance, cones);
#else
    return traceDiffuse(origin, normal, aperture, maxDistance);
#endif
}

void main() {
    ivec3 v;
    if (uFromList != 0) {
#if LIT_BOUNCE_IRRADIANCE
        if (!listedVoxelInRange(v)) return;
#else
        if (!listedVoxel(v)) return;
#endif
    } else {
        v = ivec3(gl_GlobalInvocationID);
    }
    int n = int(voxel.voxelInfo.x);
    if (any(greaterThanEqual(v, ivec3(n)))) return;
    vec4 albedo = unpackVoxel(imageLoad(voxelAlbedo, v).r);
#if LIT_BOUNCE_IRRADIANCE
    if (albedo.a == 0.0) return;  // empty: the gather skips it (voxel_irradiance.glsl)
#else
    vec4 direct = imageLoad(voxelDirect, v);
    if (albedo.a == 0.0 || direct.a == 0.0) {
        imageStore(voxelBounce, v, direct);
        return;
    }
#endif
    vec3 averaged = unpackAveragedNormal(imageLoad(voxelNormal, v).r);
    float agreement = length(averaged);
    vec3 normal = agreement >= kDirectionMinLength ? averaged / agreement : vec3(0.0, 1.0, 0.0);
    vec3 centre = voxelCenter(v);
    float aperture = voxel.traceParams.w, maxDistance = voxel.traceParams.y;
    // Voxels whose normals disagree (both sides of a thin wall) gather over both hemispheres.
    vec3 front = bounceIrradiance(v, coneOrigin(centre, normal), normal, aperture, maxDistance);
    vec3 back = agreement < kOneSidedMinLength
                    ? bounceIrradiance(v, coneOrigin(centre, -normal), -normal, aperture, maxDistance)
                    : front;
#if LIT_BOUNCE_IRRADIANCE
    if (uBlend < 1.0) {
        vec4 oldFront = imageLoad(voxelIrradiancePosOut, v), oldBack = imageLoad(voxelIrradianceNegOut, v);
        // A voxel not traced yet (alpha 0) takes the new value alone.
        if (oldFront.a > 0.0) front = mix(decodeRadiance(oldFront.rgb), front, uBlend);
        if (oldBack.a > 0.0) back = mix(decodeRadiance(oldBack.rgb), back, uBlend);
    }
    imageStore(voxelIrradiancePosOut, v, vec4(encodeRadiance(front), 1.0));
    imageStore(voxelIrradianceNegOut, v, vec4(encodeRadiance(back), 1.0));
#else
    vec3 irradiance = 0.5 * (front + back);  // = front for a one-sided voxel
    vec3 radiance = decodeRadiance(direct.rgb) + albedo.rgb * irradiance * voxel.traceParams.x;
    imageStore(voxelBounce, v, vec4(encodeRadiance(radiance), 1.0));
#endif
}
