#version 450 core
// Which empty voxels lie inside a solid (SolidVoxelsPass): the voxelization writes surfaces only,
// so the inside of a thick wall is empty space, and a voxel ray that starts there (an edge voxel's
// origin pushed into the wall next to it, or a voxel holding two faces buried back to back where
// two boxes touch) runs through the wall to light on its far side: bright dots along a room's
// inner edges, and the sunlit outside's light in a closed room (docs/GI.md, "Solid voxels").
//
// Each column along y is walked up and down. Walking up, a surface facing down (its voxels'
// averaged normal y < −kSolidFaceY, voxelFaceY) is a way into a solid and one facing up a way out; walking down,
// the other way round. An empty voxel is inside only when both walks say so, so a lone surface
// (a ceiling made of one quad facing down) puts nothing inside: the walk from above never enters.
// Faces buried back to back cancel in their voxels' averaged normal and change nothing, so two
// boxes that touch read as one solid. One invocation walks 32 neighbouring columns along x, one
// bit each, and owns the words it writes.
#include "voxel.glsl"

layout(local_size_x = LIT_SOLID_VOXELS_GROUP_SIZE) in;

layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
layout(std430, binding = LIT_SSBO_SOLID_VOXELS) buffer SolidVoxels { uint solidBits[]; };


// The columns to walk (SolidVoxelsPass): x in words of 32 columns, z in voxels, [min, end).
uniform ivec2 uColumnMin, uColumnEnd;

// Row y of the 32 columns from x0 at z, a bit per column: occupied, facing down, facing up.
uvec3 faceBits(int x0, int y, int z) {
    uvec3 bits = uvec3(0u);
    for (int i = 0; i < 32; ++i) {
        vec4 texel = unpackVoxel(imageLoad(voxelNormal, ivec3(x0 + i, y, z)).r);
        if (texel.a == 0.0) continue;
        int faceY = voxelFaceY(texel);
        uint bit = 1u << uint(i);
        bits.x |= bit;
        if (faceY < 0) bits.y |= bit;
        if (faceY > 0) bits.z |= bit;
    }
    return bits;
}

void main() {
    int n = int(voxel.voxelInfo.x);  // a power of two, at least 64
    int words = uColumnEnd.x - uColumnMin.x;
    int word = uColumnMin.x + int(gl_GlobalInvocationID.x) % words;
    int z = uColumnMin.y + int(gl_GlobalInvocationID.x) / words;
    if (z >= uColumnEnd.y) return;
    int x0 = word * 32;

    // Walking up: inside after a face looking down, outside after one looking up.
    uint inside = 0u;
    for (int y = 0; y < n; ++y) {
        uvec3 faces = faceBits(x0, y, z);
        inside = (inside | faces.y) & ~faces.z;
        solidBits[(x0 + n * (y + n * z)) >> 5] = inside & ~faces.x;
    }
    // Walking down: inside after a face looking up; a voxel stays inside if both walks agree.
    inside = 0u;
    for (int y = n - 1; y >= 0; --y) {
        uvec3 faces = faceBits(x0, y, z);
        inside = (inside | faces.z) & ~faces.y;
        solidBits[(x0 + n * (y + n * z)) >> 5] &= inside;
    }
}
