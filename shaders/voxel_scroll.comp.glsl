#version 450 core
// A near level scrolled by uShift voxels (VoxelScrollPass): a voxel at v moves to v − uShift. Only
// listed voxels hold anything in the per-voxel volumes (the voxelization lists every voxel it
// writes; injection, bounces, irradiance and its filter write listed voxels only), so the move
// runs over the occupied-voxel list, in two dispatches of two programs: LIT_SCROLL_PHASE 0 lifts
// each entry's texels into the scratch buffer and zeroes them at the old place, LIT_SCROLL_PHASE 1
// writes them at the new one. An entry whose voxel left the volume writes nothing: its texels stay
// zero.
//
// LIT_SCROLL_WRITTEN 0: the material volumes, level 0 of the radiance, its sides and the texels the
// pixels gather; phase 1 also gives each entry its voxel's new coordinates, in place (the progress of an
// update under way over the list stays valid). An entry whose voxel left wraps round into the slab
// the scroll uncovered, where it becomes the entry of whatever the slab's voxelization puts there
// (its listed bit is set, so no second entry is appended), or an empty one. Every entry sets its
// listed bit (zeroed before).
// LIT_SCROLL_WRITTEN 1, run first (it reads the old coordinates): the traced irradiance (both
// sides), which the refinement goes on averaging, and what an update under way has written so far
// (the bounce, the texels being written).
#include "shared.h"
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_LIST_GROUP_SIZE) in;

LIT_OCCUPIED_VOXELS_BLOCK();
layout(std430, binding = LIT_SSBO_LISTED_VOXELS) buffer ListedVoxels { uint listedBits[]; };
layout(std430, binding = LIT_SSBO_VOXEL_SCROLL) buffer Saved { uvec4 saved[]; };

#if LIT_SCROLL_WRITTEN
layout(binding = LIT_IMG_SCROLL_TRACED, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D traced;  // N × N × 2N: both sides
layout(binding = LIT_IMG_SCROLL_BOUNCE, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D bounce;
layout(binding = LIT_IMG_SCROLL_WRITTEN_TEXELS, rgba32ui) uniform uimage3D writtenTexels;
uniform bool uHasBounce;
uniform bool uHasWrittenTexels;
#else
layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform uimage3D albedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform uimage3D normal;
layout(binding = LIT_IMG_VOXEL_EMISSION, r32ui) uniform uimage3D emission;
layout(binding = LIT_IMG_VOXEL_SURFACE, r32ui) uniform uimage3D surface;
layout(binding = LIT_IMG_VOXEL_RADIANCE, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D radiance;
layout(binding = LIT_IMG_SCROLL_SHOWN_TEXELS, rgba32ui) uniform uimage3D shownTexels;
layout(binding = LIT_IMG_VOXEL_SIDES, rg32ui) uniform uimage3D sides;
#endif

uniform uint uEntries;  // entries stored: min(count, capacity)
uniform ivec3 uShift;   // voxels, |uShift| < N along each axis

void main() {
    uint index = gl_WorkGroupID.x * uint(LIT_INJECT_LIST_GROUP_SIZE) + gl_LocalInvocationIndex;
    if (index >= uEntries) return;
    int n = int(voxel.voxelInfo.x);
    ivec3 v = unpackVoxelCoord(occupiedVoxels[index]);
    uint slot = index * uint(LIT_SCROLL_SAVED_TEXELS);
#if LIT_SCROLL_PHASE == 0
#if LIT_SCROLL_WRITTEN
    ivec3 back = v + ivec3(0, 0, n);
    saved[slot] = floatBitsToUint(imageLoad(traced, v));
    saved[slot + 1u] = floatBitsToUint(imageLoad(traced, back));
    imageStore(traced, v, vec4(0.0));
    imageStore(traced, back, vec4(0.0));
    if (uHasBounce) {
        saved[slot + 2u] = floatBitsToUint(imageLoad(bounce, v));
        imageStore(bounce, v, vec4(0.0));
    }
    if (uHasWrittenTexels) {
        saved[slot + 3u] = imageLoad(writtenTexels, v);
        imageStore(writtenTexels, v, uvec4(0u));
    }
#else
    saved[slot] = uvec4(imageLoad(albedo, v).r, imageLoad(normal, v).r, imageLoad(emission, v).r,
                        imageLoad(surface, v).r);
    saved[slot + 1u] = floatBitsToUint(imageLoad(radiance, v));
    saved[slot + 2u] = imageLoad(shownTexels, v);
    saved[slot + 3u] = uvec4(imageLoad(sides, v).xy, 0u, 0u);
    imageStore(albedo, v, uvec4(0u));
    imageStore(normal, v, uvec4(0u));
    imageStore(emission, v, uvec4(0u));
    imageStore(surface, v, uvec4(0u));
    imageStore(radiance, v, vec4(0.0));
    imageStore(shownTexels, v, uvec4(0u));
    imageStore(sides, v, uvec4(0u));
#endif
#else
    ivec3 moved = v - uShift;
    bool kept = all(greaterThanEqual(moved, ivec3(0))) && all(lessThan(moved, ivec3(n)));
#if LIT_SCROLL_WRITTEN
    if (!kept) return;
    imageStore(traced, moved, uintBitsToFloat(saved[slot]));
    imageStore(traced, moved + ivec3(0, 0, n), uintBitsToFloat(saved[slot + 1u]));
    if (uHasBounce) imageStore(bounce, moved, uintBitsToFloat(saved[slot + 2u]));
    if (uHasWrittenTexels) imageStore(writtenTexels, moved, saved[slot + 3u]);
#else
    if (kept) {
        uvec4 materials = saved[slot];
        imageStore(albedo, moved, uvec4(materials.x));
        imageStore(normal, moved, uvec4(materials.y));
        imageStore(emission, moved, uvec4(materials.z));
        imageStore(surface, moved, uvec4(materials.w));
        imageStore(radiance, moved, uintBitsToFloat(saved[slot + 1u]));
        imageStore(shownTexels, moved, saved[slot + 2u]);
        imageStore(sides, moved, saved[slot + 3u]);
    }
    ivec3 w = (moved + n) % n;  // a voxel that left wraps into the uncovered slab
    occupiedVoxels[index] = packVoxelCoord(w);
    uint voxelIndex = uint(w.x) + uint(n) * (uint(w.y) + uint(n) * uint(w.z));
    atomicOr(listedBits[voxelIndex >> 5u], 1u << (voxelIndex & 31u));
#endif
#endif
}
