#version 450 core
// Lists the occupied parents of mip level uLevel (MipmapPass::listOccupiedParents; layout in
// mip_parents.glsl): each entry of the level below (the occupied-voxel list for level 1, else
// level uLevel − 1's list) marks its parent in the level's bitmask; the entry that sets the bit
// appends the parent. Run once per voxelization, level 1 first; a light edit reuses the lists.
// A level's list can never overflow: it holds each parent once, and a parent has at least one
// listed child, so it is no longer than the list below it nor than the level's voxel count
// (MipmapPass sizes it as the smaller of the occupied list's capacity and that count).
#include "shared.h"
#include "voxel.glsl"
#include "mip_parents.glsl"

layout(local_size_x = LIT_INJECT_LIST_GROUP_SIZE) in;

LIT_OCCUPIED_VOXELS_BLOCK(readonly);
LIT_MIP_PARENTS_BLOCK();

uniform uint uOccupiedCapacity;  // entries the occupied-voxel list holds (VoxelVolume::occupiedCapacity)
uniform int uLevel;              // the level listed, ≥ 1
uniform uint uChildList;         // offset in parentData of level uLevel − 1's list (uLevel ≥ 2)
uniform uint uList;              // offset of level uLevel's list
uniform uint uMask;              // offset of level uLevel's bitmask: one bit per voxel of the level, x fastest
uniform int uEdge;               // edge of level uLevel (voxels)

void main() {
    uint index = gl_WorkGroupID.x * uint(LIT_INJECT_LIST_GROUP_SIZE) + gl_LocalInvocationIndex;
    ivec3 child;
    if (uLevel == 1) {
        if (index >= min(occupiedCount, uOccupiedCapacity)) return;
        child = unpackVoxelCoord(occupiedVoxels[index]);
    } else {
        if (index >= parentHeaders[4 * (uLevel - 1)]) return;
        child = unpackParentCoord(parentData[uChildList + index]);
    }
    ivec3 p = child >> 1;
    uint linear = uint(p.x) + uint(uEdge) * (uint(p.y) + uint(uEdge) * uint(p.z));
    uint bit = 1u << (linear & 31u);
    if ((atomicOr(parentData[uMask + (linear >> 5u)], bit) & bit) != 0u) return;  // listed by a sibling
    uint slot = atomicAdd(parentHeaders[4 * uLevel], 1u);
    parentData[uList + slot] = packVoxelCoord(p);
    atomicMax(parentHeaders[4 * uLevel + 1], slot / uint(LIT_INJECT_LIST_GROUP_SIZE) + 1u);
}
