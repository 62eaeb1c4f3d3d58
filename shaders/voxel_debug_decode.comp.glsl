#version 450 core
// Voxel debug views (VoxelDebugPass): decodes one material channel of the packed r32ui volumes
// into an RGBA16F volume, premultiplied by occupancy (rgb = value × occupancy, a = occupancy) so
// that the box-filtered mip chain built from it averages only occupied voxels.
#include "voxel.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 8) in;

layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform readonly uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
layout(binding = LIT_IMG_VOXEL_EMISSION, r32ui) uniform readonly uimage3D voxelEmission;
layout(binding = LIT_IMG_MIP_DEST, rgba16f) uniform writeonly image3D decoded;

uniform int uChannel;  // LIT_VOXEL_CHANNEL_ALBEDO, _NORMAL or _EMISSION

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, imageSize(decoded)))) return;
    vec4 albedo = unpackVoxel(imageLoad(voxelAlbedo, v).r);
    // Occupied when any fragment landed here (the albedo sample count is non-zero).
    float occupancy = albedo.a > 0.0 ? 1.0 : 0.0;
    vec3 value = albedo.rgb;
    if (uChannel == LIT_VOXEL_CHANNEL_NORMAL) {
        value = unpackVoxel(imageLoad(voxelNormal, v).r).xyz * 2.0 - 1.0;
    } else if (uChannel == LIT_VOXEL_CHANNEL_EMISSION) {
        value = unpackVoxel(imageLoad(voxelEmission, v).r).rgb * LIT_VOXEL_EMISSION_RANGE;
    }
    imageStore(decoded, v, vec4(value * occupancy, occupancy));
}
