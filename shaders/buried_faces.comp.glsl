#version 450 core
// The voxels where two solids touch (SolidVoxelsPass, beside the solid voxels' walk): a wall
// standing on a floor slab buries the slab's top under the wall's bottom, back to back, and the
// voxels along the room's inner edge hold those two buried faces beside the visible floor and
// wall. Their averaged normal keeps the visible faces' direction, but the buried pair shortens it
// below kOneSidedMinLength, so the voxel reads as two-sided (a wall thinner than a voxel): it
// starts its rays along the floor's or the wall's normal only, from the voxel centre, and one side
// in the buried row or in the wall, where they meet back faces; such voxels took about half the
// light of the room around them (docs/GI.md, "Solid voxels").
//
// Here a two-sided voxel with one-sided neighbours (of its 26) whose faces run through it and
// agree on a side is such a junction: its normal becomes the mean of theirs, at full length (the
// floor's +y and the wall's +z make the diagonal between them), so it is a one-sided voxel whose
// plane bevels the edge, as a room made of one mesh has at its inner edges. A thin wall's voxels
// have two-sided neighbours along the wall and stay as they are; so do the voxels buried under a
// box standing on the floor, beside which the box's sides run a voxel further out. The faces
// must agree (their mean at least kAgreement long): between a floor and a ceiling a voxel apart,
// +y and −y cancel. The solid mask cannot tell the open side: along such junctions it has holes
// where the buried faces do not cancel exactly, and the conservative voxelization spreads a box's
// top a voxel beyond its sides, which closes the air at its foot.
// The fragments' running average is lost (a voxelization writes it again); the count becomes a
// marker (kJunctionCount, voxel.glsl) that keeps how the mask's walk read the voxel and that the
// neighbours in the same pass leave out, so the result does not depend on the order the voxels
// run in.
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_LIST_GROUP_SIZE) in;

LIT_VOXEL_LIST_READER
LIT_VOXEL_SURFACE_READER

layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform uimage3D voxelNormal;

const float kAgreement = 0.5;

void main() {
    ivec3 v;
    if (uFromList != 0) {
        if (!listedVoxel(v)) return;
    } else {  // the list overflowed: over the grid, in groups of 8³
        uint i = gl_LocalInvocationIndex;
        uvec3 local = uvec3(i & 7u, (i >> 3u) & 7u, i >> 6u);
        v = ivec3(gl_WorkGroupID * uint(LIT_INJECT_GROUP_SIZE) + local);
        if (!inOnlyBoxes(v)) return;
    }
    int n = int(voxel.voxelInfo.x);
    if (any(greaterThanEqual(v, ivec3(n)))) return;
    uint bits = imageLoad(voxelNormal, v).r;
    vec4 texel = unpackVoxel(bits);
    if (texel.a == 0.0 || length(unpackAveragedNormal(bits)) >= kOneSidedMinLength) return;
    vec3 sum = vec3(0.0);
    float count = 0.0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                ivec3 c = v + ivec3(x, y, z);
                if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(n)))) continue;
                uint neighbour = imageLoad(voxelNormal, c).r;
                vec3 averaged = unpackAveragedNormal(neighbour);
                float agreement = length(averaged);
                // Empty, two-sided (a thin wall, another junction, this voxel itself), or written
                // by this pass.
                int fragments = voxelCount(unpackVoxel(neighbour));
                if (fragments == 0 || fragments >= kJunctionCount || agreement < kOneSidedMinLength) continue;
                // Only a face that runs through this voxel: the faces beside the voxels buried
                // under a box (its sides, a voxel further out) do not, and those stay as they are.
                vec3 m = averaged / agreement;
                float height = dot(vec3(v) + 0.5 - voxelSurfacePoint(c), m);
                if (abs(height) > 0.5 * (abs(m.x) + abs(m.y) + abs(m.z)) + 0.05) continue;
                sum += m;
                count += 1.0;
            }
    if (count == 0.0 || length(sum) < kAgreement * count) return;
    vec3 side = normalize(sum);
    float marker = float(junctionMarker(voxelFaceY(texel))) / 255.0;
    imageStore(voxelNormal, v, uvec4(packUnorm4x8(vec4(side * 0.5 + 0.5, marker))));
}
