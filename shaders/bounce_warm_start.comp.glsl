#version 450 core
// Every bounce after a geometry edit, spread over frames (BouncePass::keepIndirect, addKeptIndirect;
// docs/GI.md, "Bounces"). The bounces iterate L ← D + albedo · gather(L), which converges to the
// same light from any start; starting from the last update's light instead of the direct light
// alone keeps level 0 (what the cones, the specular term and the gather's cone fallback read)
// near the converged light while the update runs, and converges in fewer bounces.
//   uMode 0, over the old occupied list before the voxelization: the bounce volume keeps each
//            voxel's indirect light, max(level 0 − direct, 0), opacity 1 (cleared elsewhere);
//   uMode 1, over the new list after the injection: level 0 (the new direct light) += that.
// A voxel new to the geometry starts from its direct light; one that left it is not listed.
// Define set by BouncePass: LIT_BOUNCE_RGBA8 (the volumes' format).
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_LIST_GROUP_SIZE) in;

LIT_VOXEL_LIST_READER

layout(binding = LIT_IMG_VOXEL_RADIANCE, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D voxelRadiance;
layout(binding = LIT_IMG_VOXEL_DIRECT, LIT_RADIANCE_IMAGE_FORMAT) uniform readonly image3D voxelDirect;
layout(binding = LIT_IMG_VOXEL_BOUNCE, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D voxelBounce;
uniform int uMode;

void main() {
    ivec3 v;
    if (!listedVoxel(v)) return;
    vec4 level0 = imageLoad(voxelRadiance, v);
    if (uMode == 0) {
        imageStore(voxelBounce, v, vec4(max(level0.rgb - imageLoad(voxelDirect, v).rgb, vec3(0.0)), 1.0));
    } else {
        vec4 kept = imageLoad(voxelBounce, v);
        if (kept.a > 0.0) imageStore(voxelRadiance, v, vec4(level0.rgb + kept.rgb, level0.a));
    }
}
