// The voxel volume: placement, packing of the r32ui material volumes, and the atomic running
// average that lets many fragments write one voxel without flicker (Crassin & Green 2012,
// "Octree-Based Sparse Voxelization Using the GPU Hardware Rasterizer", OpenGL Insights ch. 22).
#include "shared.h"
#include "bfloat.glsl"
#include "octahedral.glsl"

layout(std140, binding = LIT_UBO_VOXEL) uniform VoxelBlock {
    VoxelUniforms voxel;
};

// World position → volume texture coordinate in [0,1]³.
vec3 worldToVolume(vec3 p) { return (p - voxel.volumeMin.xyz) / voxel.volumeMin.w; }
// Volume texture coordinate → world position.
vec3 volumeToWorld(vec3 uvw) { return voxel.volumeMin.xyz + uvw * voxel.volumeMin.w; }
// Integer voxel → world position of its centre.
vec3 voxelCenter(ivec3 v) { return voxel.volumeMin.xyz + (vec3(v) + 0.5) * voxel.voxelInfo.z; }

// Radiance as stored in the volume (RGBA8 volumes hold radiance × radianceScale.x).
vec3 encodeRadiance(vec3 radiance) { return radiance * voxel.radianceScale.x; }
vec3 decodeRadiance(vec3 stored) { return stored * voxel.radianceScale.y; }
// The bounce volume's alpha where a voxel's bounce holds what it adds to the bounce before rather
// than its light (bounce.comp.glsl's later bounces, RGBA16F only; bounce_copy.comp.glsl adds it).
const float kBounceAddsAlpha = 2.0;

// RGBA8 packed in a uint, as unpackUnorm4x8 expects (x in the low byte).
vec4 unpackVoxel(uint bits) { return unpackUnorm4x8(bits); }

// A voxel's averaged normal: the normal volume holds the mean of n·0.5+0.5 over the voxel's
// fragments, so the vector returned here is the mean of their normals. Its length says how far
// they agreed (~1 flat, ~0.7 at a box edge, ~0 for the two faces of a wall thinner than a voxel):
// below kOneSidedMinLength a voxel is taken to hold surfaces facing both ways, below
// kDirectionMinLength its direction is 8-bit rounding noise (±1/255 per component).
const float kOneSidedMinLength = 0.5;
const float kDirectionMinLength = 0.05;
vec3 unpackAveragedNormal(uint bits) { return unpackVoxel(bits).xyz * 2.0 - 1.0; }

// The running averages' counts (averageRgbAdd) and the junction markers above them.
const int kVoxelMaxCount = 250;
const int kJunctionCount = 252;  // + 0: level, 1: facing down, 2: facing up (in the walk's terms)

// How the solid mask's column walk (solid_voxels.comp.glsl) reads a normal texel: −1 a face
// looking down (a way into a solid walking up), 1 one looking up, 0 neither (a wall, faces buried
// back to back, empty). A junction made one-sided after the walk (buried_faces.comp.glsl) reads as
// it did before, so a walk of some columns again gives what the whole walk gave.
const float kSolidFaceY = 0.25;
int voxelCount(vec4 texel) { return int(texel.a * 255.0 + 0.5); }
// The count that marks a junction the walk read as `faceY` (voxelFaceY's −1, 0 or 1).
int junctionMarker(int faceY) { return kJunctionCount + (faceY < 0 ? 1 : (faceY > 0 ? 2 : 0)); }
int voxelFaceY(vec4 texel) {
    int count = voxelCount(texel);
    if (count >= kJunctionCount) {
        int marker = count - kJunctionCount;
        return marker == 1 ? -1 : (marker == 2 ? 1 : 0);
    }
    if (count == 0) return 0;
    float ny = texel.y * 2.0 - 1.0;
    return ny < -kSolidFaceY ? -1 : (ny > kSolidFaceY ? 1 : 0);
}

// Sides. A two-sided voxel (faces back to back: a slab thinner than a voxel) sends each face's
// direct light to that face's side only. The injection finds the axis of the slab it lies in
// (inject.comp.glsl, twoSidedAxis) and stores in VoxelVolume::sides the half difference of its two
// sides' direct light, Δ = (D₊ − D₋)/2, in the radiance volume's encoding; level 0 and the direct
// volume hold the mean (D₊ + D₋)/2. A voxel ray that ends on the +axis side (travelling against the
// axis) sees what the volume it reads holds + Δ, one on the other side − Δ: every such volume holds
// the direct mean (the later bounces' changes do not, and take none). Bounced light stays the mean of
// the sides.
//   x: packHalf2x16(Δr, Δg); y: bits 0–15 half Δb, 16–29 the axis (octahedral, 7 bits per
//   coordinate), 31 set (0 everywhere else: one-sided voxels, no slab found).
const uint kSidesSplit = 0x80000000u;
uvec2 packSides(vec3 axis, vec3 delta) {
    uvec2 q = uvec2(round(clamp(octEncode(axis) * 0.5 + 0.5, 0.0, 1.0) * 127.0));
    return uvec2(packHalf2x16(delta.rg), (packHalf2x16(vec2(delta.b, 0.0)) & 0xffffu) | (q.x << 16u) | (q.y << 23u) |
                                             kSidesSplit);
}
vec3 unpackSidesAxis(uint y) {
    return octDecode(vec2(float((y >> 16u) & 127u), float((y >> 23u) & 127u)) / 127.0 * 2.0 - 1.0);
}
// The radiance a ray along `dir` sees where it ends in a voxel whose volume holds `stored` (decoded)
// and whose sides texel is `sides`.
vec3 radianceSeenFrom(vec3 stored, uvec2 sides, vec3 dir) {
    if ((sides.y & kSidesSplit) == 0u) return stored;
    vec3 delta = decodeRadiance(vec3(unpackHalf2x16(sides.x), unpackHalf2x16(sides.y).x));
    return max(stored + (dot(dir, unpackSidesAxis(sides.y)) < 0.0 ? delta : -delta), vec3(0.0));
}

// The format qualifier of the voxel compute passes' images that hold radiance or irradiance, as the
// radiance volume stores it (VoxelVolume::radianceFormat): InjectPass defines LIT_BOUNCE_RGBA8 for
// its bounce, irradiance, filter and copy programs.
#ifdef LIT_BOUNCE_RGBA8
#if LIT_BOUNCE_RGBA8
#define LIT_RADIANCE_IMAGE_FORMAT rgba8
#else
#define LIT_RADIANCE_IMAGE_FORMAT rgba16f
#endif
#endif

// The cached GI mode's traced irradiance volume (InjectPass) holds both sides of a voxel in one
// N × N × 2N volume: the side its averaged normal points to at v, the other side (thin walls) here.
ivec3 otherSideTexel(ivec3 v) { return ivec3(v.xy, v.z + int(voxel.voxelInfo.x)); }

// The gather texel (the cached GI mode's filtered irradiance, RGBA32UI N³; voxel_irradiance_filter
// writes it, the per-pixel gather of voxel_irradiance.glsl reads it): everything the gather needs of
// a voxel in one fetch, where it took two (the normal volume, then the irradiance of the side).
//   x: bits 0-26 the voxel's unit normal as the bounces traced it (its averaged normal
//      normalized, +Y where the normals cancel), 9 bits per axis (round((c + 1)·255), ≤ 0.002 off:
//      a quarter of the averaged normal's own 8-bit step); bit 27 written (so x is never 0 once
//      the filter wrote it), 28 side traced, 29 other side traced, 30 one-sided
//   y, z, w: bfloat2(side.r, side.g), bfloat2(other.r, other.g), bfloat2(side.b, other.b):
//      irradiance/π decoded (not in the radiance volume's encoding), a side's three values from
//      words chosen first
// An all-zero texel (cleared by a voxelization, not filtered since) is an empty voxel to the gather.
// One fetch per voxel, bfloat16 rather than halves (llvmpipe converts halves in software, 54 times
// a pixel; bfloat16 keeps 8 significant bits, ≤ 0.2 % off), and the normal stored normalized (no
// square root or division per voxel in the gather): each made the ½-scale gather of the full-frame
// Cornell box cheaper on llvmpipe (docs/GI.md, "The filter"; docs/PERFORMANCE.md, "llvmpipe").
const uint kGatherWritten = 1u << 27;
const uint kGatherSideTraced = 1u << 28;
const uint kGatherOtherSideTraced = 1u << 29;
const uint kGatherOneSided = 1u << 30;
uvec4 packGatherTexel(vec3 unitNormal, bool oneSided, vec4 side, vec4 other) {
    uvec3 q = uvec3(round(clamp(unitNormal, -1.0, 1.0) * 255.0 + 255.0));
    uint flags = kGatherWritten | (side.a > 0.0 ? kGatherSideTraced : 0u) |
                 (other.a > 0.0 ? kGatherOtherSideTraced : 0u) | (oneSided ? kGatherOneSided : 0u);
    return uvec4(q.x | (q.y << 9) | (q.z << 18) | flags, packBfloat2(side.rg), packBfloat2(other.rg),
                 packBfloat2(vec2(side.b, other.b)));
}
vec3 gatherTexelNormal(uvec4 t) {
    return vec3(uvec3(t.x, t.x >> 9, t.x >> 18) & 511u) * (1.0 / 255.0) - 1.0;
}
bool gatherTexelOneSided(uvec4 t) { return (t.x & kGatherOneSided) != 0u; }
bool gatherTexelTraced(uvec4 t, bool otherSide) {
    return (t.x & (otherSide ? kGatherOtherSideTraced : kGatherSideTraced)) != 0u;
}
vec3 gatherTexelIrradiance(uvec4 t, bool otherSide) {
    uint rg = otherSide ? t.z : t.y;
    return vec3(unpackBfloatLow(rg), unpackBfloatHigh(rg), otherSide ? unpackBfloatHigh(t.w) : unpackBfloatLow(t.w));
}

// The packed running average `current` with `value` (rgb in [0,1]) added. The alpha byte counts
// the samples averaged so far, up to kVoxelMaxCount (after which it is a moving average); the
// counts above it mark the normals of the junction voxels that buried_faces.comp.glsl made
// one-sided, and keep how the solid mask's walk read them before (voxelFaceY).
uint averageRgbAdd(uint current, vec3 value) {
    vec4 average = unpackUnorm4x8(current);
    float count = average.a * 255.0;
    vec3 sum = average.rgb * count + value;
    return packUnorm4x8(vec4(sum / (count + 1.0), min(count + 1.0, float(kVoxelMaxCount)) / 255.0));
}

// Adds `value` (rgb in [0,1]) to the running average stored in `image` at `coord`, with a
// compare-and-swap loop. `image` must be declared `layout(r32ui) coherent volatile uimage3D`.
// A macro rather than a function: GLSL allows no format qualifier on a function parameter, and
// image atomics need one (Mesa: "Image atomic functions should use r32i/r32ui format qualifier").
// At most a few hundred iterations in pathological cases; bounded so a driver bug cannot hang.
#define atomicAverageRgb(image, coord, value)                                                   \
    {                                                                                           \
        ivec3 avgCoord_ = (coord);                                                              \
        vec3 avgValue_ = (value);                                                               \
        uint avgExpected_ = 0u;                                                                 \
        uint avgDesired_ = averageRgbAdd(0u, avgValue_);                                        \
        for (int avgTry_ = 0; avgTry_ < 255; ++avgTry_) {                                       \
            uint avgCurrent_ = imageAtomicCompSwap(image, avgCoord_, avgExpected_, avgDesired_); \
            if (avgCurrent_ == avgExpected_) break;                                             \
            avgExpected_ = avgCurrent_;                                                         \
            avgDesired_ = averageRgbAdd(avgCurrent_, avgValue_);                                \
        }                                                                                       \
    }

// The occupied-voxel list (VoxelVolume::occupiedList): VoxelizePass appends, InjectPass reads.
// `dispatchX` is the indirect dispatch's group count over the list (DispatchIndirectCommand).
#define LIT_OCCUPIED_VOXELS_BLOCK(qualifiers)                                      \
    layout(std430, binding = LIT_SSBO_OCCUPIED_VOXELS) qualifiers buffer OccupiedVoxels { \
        uint occupiedCount;                                                        \
        uint dispatchX, dispatchY, dispatchZ;                                      \
        uint occupiedVoxels[];                                                     \
    }
uint packVoxelCoord(ivec3 v) { return uint(v.x) | (uint(v.y) << 10) | (uint(v.z) << 20); }
ivec3 unpackVoxelCoord(uint p) { return ivec3(int(p & 1023u), int((p >> 10) & 1023u), int(p >> 20)); }

// What a compute shader that dispatchOverVoxels (gi/VoxelDispatch.h) runs (injection, bounces) declares:
// the list, whether this dispatch runs over it (uFromList = 1, LIT_INJECT_LIST_GROUP_SIZE entries
// per work group) or over the whole grid, and listedVoxel(), this invocation's voxel of the list
// (false past its end, or outside the boxes the pass is limited to: uOnlyBoxCount > 0, a near
// level's update of the slabs a scroll uncovered, VoxelVolume::onlyBoxes).
#define LIT_VOXEL_LIST_READER                                                                      \
    LIT_OCCUPIED_VOXELS_BLOCK(readonly);                                                           \
    uniform int uFromList;                                                                         \
    uniform uint uOccupiedCapacity;                                                                \
    uniform int uOnlyBoxCount;                                                                     \
    uniform ivec4 uOnlyBoxMin[LIT_CHANGED_BOXES];                                                  \
    uniform ivec4 uOnlyBoxMax[LIT_CHANGED_BOXES];                                                  \
    bool inOnlyBoxes(ivec3 v) {                                                                    \
        if (uOnlyBoxCount == 0) return true;                                                       \
        for (int i = 0; i < uOnlyBoxCount; ++i)                                                    \
            if (all(greaterThanEqual(v, uOnlyBoxMin[i].xyz)) && all(lessThan(v, uOnlyBoxMax[i].xyz))) \
                return true;                                                                       \
        return false;                                                                              \
    }                                                                                              \
    bool listedVoxel(out ivec3 v) {                                                                \
        uint index = gl_WorkGroupID.x * uint(LIT_INJECT_LIST_GROUP_SIZE) + gl_LocalInvocationIndex; \
        if (index >= min(occupiedCount, uOccupiedCapacity)) return false;                         \
        v = unpackVoxelCoord(occupiedVoxels[index]);                                               \
        return inOnlyBoxes(v);                                                                     \
    }
// A part of the list, entries [uListFirst, uListEnd), in one dispatch sized for them (the cached GI
// mode's amortised irradiance trace and its filter, dispatchListRange); the whole list
// is uListFirst 0 and uListEnd the capacity, as the indirect dispatch. Use with LIT_VOXEL_LIST_READER.
// `index`: the voxel's entry in the list (per-entry data kept beside it, the voxel rays' hits).
#define LIT_VOXEL_LIST_RANGE_READER                                                                       \
    uniform uint uListFirst;                                                                              \
    uniform uint uListEnd;                                                                                \
    bool listedVoxelInRange(out ivec3 v, out uint index) {                                                \
        index = uListFirst + gl_WorkGroupID.x * uint(LIT_INJECT_LIST_GROUP_SIZE) + gl_LocalInvocationIndex; \
        if (index >= min(min(occupiedCount, uOccupiedCapacity), uListEnd)) return false;                 \
        v = unpackVoxelCoord(occupiedVoxels[index]);                                                      \
        return inOnlyBoxes(v);                                                                            \
    }                                                                                                     \
    bool listedVoxelInRange(out ivec3 v) {                                                                \
        uint index;                                                                                       \
        return listedVoxelInRange(v, index);                                                              \
    }

// What a shader that reads the voxels' surface points declares (the voxel rays, the injection):
// voxelSurfacePoint(c), the point of voxel c's surface the voxelization recorded, in voxels from
// the volume's corner (the voxel's centre where none was; voxelize.frag.glsl); and
// voxelSurfaceWorldPoint(c, offsetVoxels), that point moved by offsetVoxels (in voxels), in world space.
#define LIT_VOXEL_SURFACE_READER                                                             \
    layout(binding = LIT_IMG_VOXEL_SURFACE, r32ui) uniform readonly uimage3D voxelSurface;   \
    vec3 voxelSurfacePoint(ivec3 c) {                                                        \
        vec4 local = unpackVoxel(imageLoad(voxelSurface, c).r);                              \
        return vec3(c) + (local.a > 0.0 ? local.xyz : vec3(0.5));                            \
    }                                                                                        \
    vec3 voxelSurfaceWorldPoint(ivec3 c, vec3 offsetVoxels) {                                  \
        return voxel.volumeMin.xyz + (voxelSurfacePoint(c) + offsetVoxels) * voxel.voxelInfo.z; \
    }

// What a shader that reads the solid voxels (SolidVoxelsPass: empty voxels inside a solid; the
// voxel rays, the injection) declares: insideSolid(p), whether world point p lies in one (false
// outside the volume). docs/GI.md, "Solid voxels".
#define LIT_SOLID_VOXELS_READER                                                                 \
    layout(std430, binding = LIT_SSBO_SOLID_VOXELS) readonly buffer SolidVoxels { uint solidBits[]; }; \
    bool insideSolid(vec3 p) {                                                                  \
        int n = int(voxel.voxelInfo.x);                                                         \
        ivec3 c = ivec3(floor((p - voxel.volumeMin.xyz) / voxel.voxelInfo.z));                  \
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(n)))) return false;     \
        uint index = uint(c.x) + uint(n) * (uint(c.y) + uint(n) * uint(c.z));                   \
        return (solidBits[index >> 5u] & (1u << (index & 31u))) != 0u;                          \
    }
