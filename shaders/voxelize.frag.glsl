#version 450 core
// Voxelization, fragment stage: one fragment = one voxel the triangle touches. Writes the
// material into the r32ui volumes as running averages (atomicAverageRgb), so every fragment
// that lands in a voxel counts equally, whatever the order.
#include "voxel.glsl"
#include "material.glsl"

in VoxelFragment {
    vec3 worldNormal;
    vec2 uv;
    flat vec4 bounds;
    flat int axis;
} fs;

layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform coherent volatile uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform coherent volatile uimage3D voxelNormal;
layout(binding = LIT_IMG_VOXEL_EMISSION, r32ui) uniform coherent volatile uimage3D voxelEmission;
LIT_OCCUPIED_VOXELS_BLOCK();
uniform uint uOccupiedCapacity;  // entries the list can hold (VoxelVolume::occupiedCapacity)

void main() {
    // The enlarged triangle overshoots at acute corners: keep pixels that touch its true bounds.
    if (any(lessThan(gl_FragCoord.xy, fs.bounds.xy)) || any(greaterThan(gl_FragCoord.xy, fs.bounds.zw))) discard;

    int n = int(voxel.voxelInfo.x);
    // (u, v, depth) in voxels; undo the geometry shader's swizzle.
    ivec3 s = ivec3(ivec2(gl_FragCoord.xy), int(floor(gl_FragCoord.z * float(n))));
    ivec3 v = fs.axis == 0 ? s.zxy : (fs.axis == 1 ? s.yzx : s);
    if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(n)))) discard;

    GpuMaterial m = materials[uMaterialIndex];
    vec4 baseColor = materialBaseColor(m, fs.uv);
    if (materialAlphaDiscard(m, baseColor.a)) discard;
    vec3 emissive = m.emissive.rgb;
    if (m.textures.w != 0) emissive *= texture(emissiveTexture, fs.uv).rgb;
    float len = length(fs.worldNormal);
    vec3 normal = len > 1e-12 ? fs.worldNormal / len : vec3(0.0);

    // The first fragment of a voxel (the albedo's compare-and-swap from 0 succeeds, as the first
    // try of atomicAverageRgb would) appends it to the occupied-voxel list; later ones average.
    vec3 albedo = clamp(baseColor.rgb, 0.0, 1.0);
    if (imageAtomicCompSwap(voxelAlbedo, v, 0u, averageRgbAdd(0u, albedo)) == 0u) {
        uint index = atomicAdd(occupiedCount, 1u);
        if (index < uOccupiedCapacity) {
            occupiedVoxels[index] = packVoxelCoord(v);
            atomicMax(dispatchX, index / uint(LIT_INJECT_LIST_GROUP_SIZE) + 1u);
        }
    } else {
        atomicAverageRgb(voxelAlbedo, v, albedo);
    }
    atomicAverageRgb(voxelNormal, v, normal * 0.5 + 0.5);
    atomicAverageRgb(voxelEmission, v, clamp(emissive / LIT_VOXEL_EMISSION_RANGE, 0.0, 1.0));
}
