#version 450 core
// After a voxelization whose update is spread over frames, the pixels go on gathering the last
// complete update's texels (VoxelIrradianceCache::showingPrevious). Those sit at the old geometry:
// this pass empties the shown texels of voxels the new voxelization left empty or turned (normal
// agreement below ½), so the gather never reads light from a surface that is gone; where nothing
// is left around a pixel (a moved object's new place) it traces cones instead
// (voxel_irradiance.glsl). Over the whole grid: the old list is gone.
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_GROUP_SIZE, local_size_y = LIT_INJECT_GROUP_SIZE, local_size_z = LIT_INJECT_GROUP_SIZE) in;

layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
layout(binding = LIT_IMG_VOXEL_DIRECT, rgba32ui) uniform uimage3D shownTexels;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, imageSize(shownTexels)))) return;
    uvec4 t = imageLoad(shownTexels, v);
    if (t.x == 0u) return;
    uint packedNormal = imageLoad(voxelNormal, v).r;
    bool kept = unpackVoxel(packedNormal).a > 0.0;
    if (kept) {
        // A two-sided voxel (normals cancelling) keeps its texel: either side may face the pixel.
        vec3 averaged = unpackAveragedNormal(packedNormal);
        float length2 = dot(averaged, averaged);
        kept = !gatherTexelOneSided(t) || length2 < 0.25 || dot(averaged, gatherTexelNormal(t)) > 0.5 * sqrt(length2);
    }
    if (!kept) imageStore(shownTexels, v, uvec4(0u));
}
