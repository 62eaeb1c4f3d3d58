#version 450 core
// Voxel irradiance strata filter (IrradianceFilterPass, the cached GI mode; docs/GI.md,
// "The filter").
//
// Each voxel traces one of the 16 stratified cone sets (bounce.comp.glsl, voxelConeSetIndex: the
// 4 × 4 pattern over the two axes that run along its surface), so the traced irradiance carries
// that pattern: a blotch per voxel that the per-pixel gather (voxel_irradiance.glsl, 3 × 3 × 3
// voxels) averages only partly, and that differs from one pixel to the next at voxel scale. This
// pass does in voxel space what ConeStrataFilterPass does for the per-pixel sets: every occupied
// voxel gets, per side, the weighted mean of the traced irradiance over one period of the pattern
// along its surface: 5 × 5 voxels over the two along-surface axes with weights ½, 1, 1, 1, ½ (each
// set exactly once on a flat surface), in the voxel's own layer (the layers above and below added
// nothing to the Cornell regions and let the sealed room's inside floor read more of its walls:
// leak 0.97 % / 0.56 % at 64³ / 128³ against 0.63 % / 0.46 % in one layer), each neighbour
// weighted by (normal agreement)^16 with the side's normal (as the gather: voxels of a wall
// meeting this floor get ~none), and only if it was traced (alpha > 0). A voxel with no traced
// neighbour stays untraced (alpha 0), which the gather skips.
//
// Reads the traced ("raw") volume, writes the gather texels (voxel.glsl, packGatherTexel: the
// voxel's unit normal and both sides' filtered irradiance/π, in either radiance format); over
// the occupied list (uFromList 1, as inject.comp.glsl), a part of it, or the whole grid.
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_GROUP_SIZE, local_size_y = LIT_INJECT_GROUP_SIZE, local_size_z = LIT_INJECT_GROUP_SIZE) in;

LIT_VOXEL_LIST_READER
// Between the edit and the end of an amortised update only the entries traced in the frame are
// filtered (listedVoxelInRange); the frame that completes the update filters the whole list.
LIT_VOXEL_LIST_RANGE_READER

// The traced volume holds both sides (otherSideTexel, voxel.glsl).
layout(binding = LIT_TEX_VOXEL_IRRADIANCE) uniform sampler3D rawIrradiance;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
layout(binding = LIT_IMG_VOXEL_DIRECT, rgba32ui) uniform writeonly uimage3D gatherTexels;

// A voxel's unit normal and whether it is one-sided, as bounce.comp.glsl traced it; false if empty.
bool voxelSurface(ivec3 v, out vec3 normal, out bool oneSided) {
    uint packedNormal = imageLoad(voxelNormal, v).r;
    if (unpackVoxel(packedNormal).a == 0.0) return false;
    vec3 averaged = unpackAveragedNormal(packedNormal);
    float agreement = length(averaged);
    normal = agreement >= kDirectionMinLength ? averaged / agreement : vec3(0.0, 1.0, 0.0);
    oneSided = agreement >= kOneSidedMinLength;
    return true;
}

// The filtered irradiance/π (decoded) around voxel c for the side facing `n`; alpha = weight sum.
vec4 filteredSide(ivec3 c, vec3 n, int res) {
    vec3 a = abs(n);
    // Axis indices u, w along the surface (the pattern's axes, as voxelConeSetIndex).
    ivec2 axes = a.x >= a.y && a.x >= a.z ? ivec2(1, 2) : (a.y >= a.z ? ivec2(0, 2) : ivec2(0, 1));
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int w = -2; w <= 2; ++w)
        for (int u = -2; u <= 2; ++u) {
            ivec3 o = ivec3(0);
            o[axes.x] = u;
            o[axes.y] = w;
            ivec3 v = c + o;
            if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(res)))) continue;
            vec3 vn;
            bool oneSided;
            if (!voxelSurface(v, vn, oneSided)) continue;
            float d = dot(n, vn);
            bool otherSide = !oneSided && d < 0.0;
            float facing = otherSide ? -d : d;
            if (facing <= 0.0) continue;
            vec4 e = texelFetch(rawIrradiance, otherSide ? otherSideTexel(v) : v, 0);
            if (e.a == 0.0) continue;  // not traced yet
            float f2 = facing * facing, f4 = f2 * f2, f8 = f4 * f4;
            float weight = (abs(u) == 2 ? 0.5 : 1.0) * (abs(w) == 2 ? 0.5 : 1.0) * f8 * f8;
            sum += weight * decodeRadiance(e.rgb);
            weightSum += weight;
        }
    return vec4(weightSum > 0.0 ? sum / weightSum : vec3(0.0), weightSum);
}

void main() {
    ivec3 v;
    if (uFromList != 0) {
        if (!listedVoxelInRange(v)) return;
    } else {
        v = ivec3(gl_GlobalInvocationID);
    }
    int res = int(voxel.voxelInfo.x);
    if (any(greaterThanEqual(v, ivec3(res)))) return;
    vec3 normal;
    bool oneSided;
    if (!voxelSurface(v, normal, oneSided)) return;  // empty: the gather skips its zero texel
    vec4 front = filteredSide(v, normal, res);
    vec4 back = oneSided ? front : filteredSide(v, -normal, res);
    imageStore(gatherTexels, v, packGatherTexel(normal, oneSided, front, back));
}
