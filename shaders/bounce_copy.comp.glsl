#version 450 core
// The end of a light bounce (BouncePass::finish): copies each listed voxel's traced bounce
// (bounce.comp.glsl wrote it for every entry of the occupied list) into level 0 of the radiance
// volume. Only the list: empty voxels hold 0 in level 0 since the voxelization, and a copy of the
// whole N³ volume moved 33 times the occupied voxels on Sponza at 256³ (3 % occupied; the
// whole-volume copies cost 10-14 ms each on llvmpipe there). Define set by InjectPass: LIT_BOUNCE_RGBA8 (the volumes' format).
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_LIST_GROUP_SIZE) in;

LIT_VOXEL_LIST_READER

layout(binding = LIT_IMG_VOXEL_BOUNCE, LIT_RADIANCE_IMAGE_FORMAT) uniform readonly image3D voxelBounce;
layout(binding = LIT_IMG_VOXEL_RADIANCE, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D voxelRadiance;
layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform readonly uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_DIRECT, LIT_RADIANCE_IMAGE_FORMAT) uniform readonly image3D voxelDirect;

// The bounces still to come, as a multiple of this bounce's change (BounceConvergence::tail; 0:
// none). Once the changes fall geometrically by r a bounce, each voxel's change keeps its shape
// and the rest of the series adds r/(1 − r) of the last one. Never below the direct light: the
// bounced light is never negative.
uniform float uTail;
// The bounce's change from the one before (VoxelVolume::change), which later bounces gather
// (bounce.comp.glsl, uChangeSubset): written when uWriteChange is 1. A voxel whose bounce gathered
// the change of the one before holds what it adds to level 0 (alpha kBounceAddsAlpha): that is its
// change, kept unrounded by the sum. Else the bounce holds the light, whose change is measured
// from the direct light when uChangeFromDirect is 1 (it gathered the direct light: level 0 may
// still hold the last update's), else from level 0 (the bounce before). The tail is not in it: no
// bounce follows.
uniform int uWriteChange;
uniform int uChangeFromDirect;
layout(binding = LIT_IMG_VOXEL_CHANGE, LIT_RADIANCE_IMAGE_FORMAT) uniform writeonly image3D voxelChange;

void main() {
    ivec3 v;
    if (!listedVoxel(v)) return;
    // A voxelization of changed boxes while the pass ran (the update ran on, VoxelGi) may have
    // emptied a voxel traced while occupied, or filled one traced while empty (its bounce holds
    // nothing: its direct light stands in). Level 0 must be occupied where the material is: the
    // voxel rays and their recorded hits take occupancy from it.
    vec4 bounce = imageLoad(voxelBounce, v);
    bool occupied = unpackVoxel(imageLoad(voxelAlbedo, v).r).a > 0.0;
    vec3 change = vec3(0.0);
    if (!occupied) {
        imageStore(voxelRadiance, v, vec4(0.0));
    } else if (bounce.a == 0.0) {
        imageStore(voxelRadiance, v, imageLoad(voxelDirect, v));
    } else {
        bool adds = bounce.a > 0.5 * kBounceAddsAlpha;
        bool readBefore = adds || uTail > 0.0 || (uWriteChange != 0 && uChangeFromDirect == 0);
        vec4 before = readBefore ? imageLoad(voxelRadiance, v) : vec4(0.0);
        vec4 direct = imageLoad(voxelDirect, v);
        vec3 radiance = bounce.rgb, tailChange = bounce.rgb - before.rgb;
        if (adds) {
            change = tailChange = bounce.rgb;
            radiance = max((before.a > 0.0 ? before.rgb / before.a : direct.rgb) + change, direct.rgb);
        } else if (uWriteChange != 0) {
            vec4 from = uChangeFromDirect != 0 ? direct : before;
            if (from.a > 0.0) change = bounce.rgb - from.rgb / from.a;
        }
        if (uTail > 0.0 && before.a > 0.0) radiance = max(radiance + uTail * tailChange, direct.rgb);
        imageStore(voxelRadiance, v, vec4(radiance, 1.0));
    }
    if (uWriteChange != 0) imageStore(voxelChange, v, vec4(change, 1.0));
}
