// Indirect diffuse from irradiance cached in the voxels (the cached GI mode, LIT_VOXEL_IRRADIANCE 1,
// GiSettings::voxelIrradiance(); docs/GI.md, "Voxel irradiance cache"). After each light or
// geometry edit every occupied voxel gathers its irradiance once (bounce.comp.glsl,
// LIT_BOUNCE_IRRADIANCE: voxel rays, or the stratified cones with gi.voxelRays 0) and stores
// irradiance/π for the side its averaged normal points to (POS) and, for voxels whose normals
// disagree (both sides of a thin wall), the other side (NEG), averaged over the sets along the
// surface by voxel_irradiance_filter.comp.glsl into the gather texels (voxel.glsl,
// packGatherTexel). A pixel then gathers, instead of tracing cones, the
// 3 × 3 × 3 voxels around its surface point pushed half a voxel along its normal, weighted by a
// tent of radius 1.5 voxels around that point × (normal agreement)^16 × occupancy. The 16th
// power keeps the gather to voxels facing as the pixel does (weight 0.5 at 17°, 0.1 at 30°): with
// the square the sealed room's inside floor read its walls' voxels and leaked 1.4-1.9× the
// accurate mode's light; with ^16 as much as the accurate mode (docs/GI.md, "The gather"). A voxel
// whose irradiance was not traced yet (alpha 0: cleared after a voxelization, and the spread
// update, the GiBudget's updateVoxels, has not reached it: the side's flag in its texel) is left
// out. `nothing` says that no voxel around the point counted (a surface the voxels do not hold
// facing this way: a thin feature, or geometry moved since the irradiance shown was traced); the
// caller traces cones there instead.
// Needs voxel.glsl (included by cone.glsl).
#ifndef LIT_VOXEL_IRRADIANCE
#define LIT_VOXEL_IRRADIANCE 0
#endif
#ifndef LIT_NEAR_GATHER
#define LIT_NEAR_GATHER 0
#endif
#if LIT_VOXEL_IRRADIANCE
// The gather texels (voxel.glsl, packGatherTexel): a voxel's normal and both sides' irradiance in
// one fetch, one sampler: llvmpipe pays for every fetch in the loop, and with one sampler per side
// it would fetch from both wherever a pixel chose one (docs/GI.md, "The filter"; docs/PERFORMANCE.md,
// "llvmpipe").
layout(binding = LIT_TEX_VOXEL_IRRADIANCE) uniform usampler3D voxelGatherTexels;

// The gather from one volume's texels: placed at `volumeMin` (m), voxels of `voxelSize` (m), `res`
// per side. Returns the weighted sum and its weight.
vec3 gatherTexelsAround(usampler3D texels, vec3 volumeMin, float voxelSize, int res, vec3 position, vec3 n,
                        out float weightSum) {
    // Continuous voxel coordinates with voxel centres on integers.
    vec3 g = (position - volumeMin) / voxelSize + 0.5 * n - 0.5;
    ivec3 c = ivec3(round(g));
    vec3 sum = vec3(0.0);
    weightSum = 0.0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                ivec3 v = c + ivec3(x, y, z);
                if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(res)))) continue;
                uvec4 t = texelFetch(texels, v, 0);
                if (t.x == 0u) continue;  // empty (or not filtered since the voxelization)
                // The normal and the two sides as bounce.comp.glsl traced them.
                float d = dot(n, gatherTexelNormal(t));
                bool otherSide = !gatherTexelOneSided(t) && d < 0.0;
                float facing = otherSide ? -d : d;
                if (facing <= 0.0) continue;
                if (!gatherTexelTraced(t, otherSide)) continue;  // not traced yet
                vec3 tent = max(1.0 - abs(vec3(v) - g) / 1.5, 0.0);
                float f2 = facing * facing, f4 = f2 * f2, f8 = f4 * f4;
                float w = tent.x * tent.y * tent.z * f8 * f8;
                sum += w * gatherTexelIrradiance(t, otherSide);
                weightSum += w;
            }
    return sum;
}

#if LIT_NEAR_GATHER > 0
// The near levels (docs/GI.md, "Near levels"), 0 the finest: the placement of the gather texels
// shown and the texels.
layout(std140, binding = LIT_UBO_NEAR_VOXEL_FIRST) uniform NearVoxelBlock {
    VoxelUniforms placement;
} nearVoxel[LIT_NEAR_GATHER];
layout(binding = LIT_TEX_NEAR_IRRADIANCE_FIRST) uniform usampler3D nearGatherTexels[LIT_NEAR_GATHER];
// Voxels from a near level's faces where its gather starts to count, and over how many it reaches
// full weight: the outermost voxels' rays left the level at once, and the blend hides the step
// between two levels' voxel sizes.
const float kNearGatherMargin = 3.0;
const float kNearGatherBlend = 4.0;
#endif

vec3 gatherVoxelIrradiance(vec3 position, vec3 n, out bool nothing) {
    float weightSum;
    vec3 sum = gatherTexelsAround(voxelGatherTexels, voxel.volumeMin.xyz, voxel.voxelInfo.z, int(voxel.voxelInfo.x),
                                  position, n, weightSum);
    vec3 irradiance = weightSum > 0.0 ? sum / weightSum : vec3(0.0);
    nothing = !(weightSum > 0.0);
#if LIT_NEAR_GATHER > 0
    // From the scene volume inwards, each near level's finer light replaces the coarser one's,
    // blended in over kNearGatherBlend voxels inside its faces; where a level gathers nothing (not
    // traced yet) the coarser light stands.
    for (int k = LIT_NEAR_GATHER - 1; k >= 0; --k) {
        VoxelUniforms level = nearVoxel[k].placement;
        vec3 inLevel = (position - level.volumeMin.xyz) / level.voxelInfo.z;
        float fromFace = min(min(min(inLevel.x, inLevel.y), inLevel.z),
                             min(min(level.voxelInfo.x - inLevel.x, level.voxelInfo.x - inLevel.y), level.voxelInfo.x - inLevel.z));
        float blend = clamp((fromFace - kNearGatherMargin) / kNearGatherBlend, 0.0, 1.0);
        float levelWeightSum;
        vec3 levelSum = gatherTexelsAround(nearGatherTexels[k], level.volumeMin.xyz, level.voxelInfo.z,
                                           int(level.voxelInfo.x), position, n, levelWeightSum);
        if (blend > 0.0 && levelWeightSum > 0.0) {
            vec3 levelIrradiance = levelSum / levelWeightSum;
            irradiance = nothing ? levelIrradiance : mix(irradiance, levelIrradiance, blend);
            nothing = false;
        }
    }
#endif
    return irradiance;
}

#endif
