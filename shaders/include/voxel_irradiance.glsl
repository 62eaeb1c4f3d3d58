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
#if LIT_VOXEL_IRRADIANCE
// The gather texels (voxel.glsl, packGatherTexel): a voxel's normal and both sides' irradiance in
// one fetch, one sampler: llvmpipe pays for every fetch in the loop, and with one sampler per side
// it would fetch from both wherever a pixel chose one (docs/GI.md, "The filter"; docs/PERFORMANCE.md,
// "llvmpipe").
layout(binding = LIT_TEX_VOXEL_IRRADIANCE) uniform usampler3D voxelGatherTexels;

vec3 gatherVoxelIrradiance(vec3 position, vec3 n, out bool nothing) {
    int res = int(voxel.voxelInfo.x);
    // Continuous voxel coordinates with voxel centres on integers.
    vec3 g = (position - voxel.volumeMin.xyz) / voxel.voxelInfo.z + 0.5 * n - 0.5;
    ivec3 c = ivec3(round(g));
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                ivec3 v = c + ivec3(x, y, z);
                if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(res)))) continue;
                uvec4 t = texelFetch(voxelGatherTexels, v, 0);
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
    nothing = !(weightSum > 0.0);
    return nothing ? vec3(0.0) : sum / weightSum;
}
#endif
