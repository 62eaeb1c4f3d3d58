#version 450 core
// One more light bounce in the voxel volume (BouncePass): every occupied voxel's
// outgoing radiance becomes its direct radiance plus what it reflects of the light the volume
// holds now,
//   L_{k+1} = L_direct + albedo · Σ_i W_i/π · C_i(L_k)                (W/(sr·m²))
// with six diffuse cones as a pixel traces them (cone.glsl, traceDiffuse), from the voxel centre
// pushed out along its averaged normal. After bounce k the volume holds light that bounced up to
// k times (k = 1 is direct light only), so a pixel that traces it sees k + 1 bounces in all.
// Voxels whose normals disagree (both sides of a thin wall) gather over both hemispheres and
// average them, as injection lights them from both sides. Voxels are treated as Lambertian
// (metals too: docs/GI.md, "Known limits").
//
// Work: as inject.comp.glsl, the occupied-voxel list (uFromList = 1; glDispatchComputeIndirect with
// the dispatch size the voxelization wrote, LIT_INJECT_LIST_GROUP_SIZE entries per group) or,
// when the list overflowed, the whole grid in 8³ groups. Only occupied voxels trace cones, and
// over the grid a SIMD vector that holds one of them pays for the whole vector's cones: the
// list packs occupied voxels densely (docs/GI.md, "Bounces").
//
// Accurate mode (LIT_CONE_FOOTPRINT, footprint-bounded cones): a voxel traces one of the
// stratified cone sets of cone_strata.glsl instead of the fixed six-cone set, chosen by its
// coordinates across its surface (voxelConeSetIndex), so that each 4 × 4 patch of a surface's voxels
// holds all 16 sets and the mip levels the pixels' cones read average them (docs/GI.md, "Stratified
// cone sets"). The fixed set's pencils would otherwise give every voxel the same few directions
// (what they happen to hit).
//
// Voxel rays (LIT_VOXEL_RAYS 1, GiSettings::voxelRays > 0, docs/GI.md "Voxel rays"): instead
// of cones, uVoxelRays cosine-distributed rays per voxel, each marched through the voxel grid to
// the first surface it meets (marchVoxelRay), whose voxel's radiance it takes. A cone's opacity is a coverage fraction
// composited along it as if independent from sample to sample, so a wall the cone runs beside, or
// a floor it skims, counts whole; a ray is blocked or not. A voxel's rays cover its whole hemisphere,
// offset by its set (voxelSet), so the filter's 4 × 4 patch averages 16 × uVoxelRays directions, as
// it averages the 16 cone sets (rayIrradiance).
//
// Defines set by InjectPass: LIT_BOUNCE_RGBA8 (1: rgba8 direct volume, 0: rgba16f);
// LIT_BOUNCE_IRRADIANCE 1 (the cached GI mode, VoxelIrradiancePass, voxel_irradiance.glsl):
// store each voxel's irradiance/π instead, for the side of its averaged normal and the other side,
// in two volumes of the radiance volume's format (voxel_irradiance_filter.comp.glsl then averages
// them over the cone sets), and leave the radiance as it is; LIT_IRRADIANCE_ALL_SETS 1: average all
// kConeSetCount stratified sets per voxel instead of its one set (kConeSetCount × the cones).
#include "cone.glsl"
#include "cone_strata.glsl"

layout(local_size_x = LIT_INJECT_GROUP_SIZE, local_size_y = LIT_INJECT_GROUP_SIZE, local_size_z = LIT_INJECT_GROUP_SIZE) in;

LIT_VOXEL_LIST_READER
// The amortised update (GiBudget::updateVoxels) traces a part of the list
// at a time (listedVoxelInRange): the irradiance, and the bounces before it.
LIT_VOXEL_LIST_RANGE_READER
uint gListIndex = 0u;  // this invocation's occupied-list entry (main; the ray-hit cache's index)


layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform readonly uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
#ifndef LIT_BOUNCE_IRRADIANCE
#define LIT_BOUNCE_IRRADIANCE 0
#endif
#ifndef LIT_IRRADIANCE_ALL_SETS
#define LIT_IRRADIANCE_ALL_SETS 0
#endif
#if LIT_BOUNCE_IRRADIANCE
// In the radiance volume's format and encoding (encodeRadiance): RGBA8 halves their memory. The
// side of the averaged normal at z, the other side at z + N (otherSideTexel, voxel.glsl).
layout(binding = LIT_IMG_VOXEL_DIRECT, LIT_RADIANCE_IMAGE_FORMAT) uniform image3D voxelIrradianceOut;
// The refinement (GiBudget::refineVoxels): round k = uSetOffset
// (1..15) traces the set voxelConeSetIndex + k and averages it into what rounds 0..k − 1 left,
// weight uBlend = 1 / (k + 1); round 0 (the edit's trace) writes with weight 1.
uniform int uSetOffset;
uniform float uBlend;
#else
layout(binding = LIT_IMG_VOXEL_DIRECT, LIT_RADIANCE_IMAGE_FORMAT) uniform readonly image3D voxelDirect;
layout(binding = LIT_IMG_VOXEL_BOUNCE) uniform writeonly image3D voxelBounce;
// Every bounce until the light converges (GiSettings::bounces kAllBounces): each voxel adds the
// luminance of its new bounced light (radiance − direct) and of its change from the bounce before
// to the change bins (shared.h, LIT_SSBO_BOUNCE_CHANGE), from which VoxelGi decides when to stop.
uniform int uMeasureChange;
layout(std430, binding = LIT_SSBO_BOUNCE_CHANGE) buffer BounceChange {
    uint changeBins[2 * LIT_BOUNCE_CHANGE_BINS];
};
#endif

#if LIT_VOXEL_RAYS
uniform int uVoxelRays;

// Empty blocks of 16³ and of 4³ voxels (levels 4 and 2 of the radiance volume are 0 exactly where
// nothing is below them: docs/GI.md, "Mipmaps over the occupied parents") are crossed in one step;
// the 16³ blocks halve the pass at 256³ in the Cornell box on llvmpipe (docs/GI.md, "Voxel rays").
const int kRaySkipLevelCoarse = 4;
const int kRaySkipLevel = 2;
const int kRayMaxSteps = 2048;
// A ray that meets a one-sided voxel's surface from behind (its direction within 60° of the voxel's
// averaged normal) sees the unlit back: black. Not from behind at all angles past 90°: the voxels on a
// box's edge average the top's and the side's normals, and a ray that skims the lit top towards the
// far edge meets that diagonal normal at under 90° (measured: the lit floor's indirect 0.96 of the
// reference with the test at 90°, 0.98 at 60°, 1.02 without any; docs/GI.md, "Voxel rays").
const float kRayBackFaceCosine = 0.5;
// A one-sided voxel (averaged normal at least kRayPlaneMinLength long: a surface, or an edge or
// corner of one) is solid only behind its surface: the part of the voxel behind the plane through
// the point of its surface the voxelization recorded (voxelSurfacePoint), with its averaged normal
// (at an edge, a bevel across it); docs/GI.md, "Rays that end on the surface":
// - a ray ends in such a voxel if it is behind that plane where it enters or leaves the voxel, and
//   passes on if it stays in front. Behind, not only across: a slanted plane is written to one voxel
//   per column (voxelize.frag.glsl) but runs on into the column's next voxel, where a ray can cross
//   it unseen, and then meets the voxels of that surface from behind (the sealed room turned 30°
//   and 12°, walls 1.5 voxels thick at 128³, let in 4.1 % of the outside light when rays ended only
//   on a crossing, 2.8 % so; 0.8 % when voxels were cubes; why they are not, below).
//   A voxel's faces lie up to a voxel off its surface, so rays that ended on them saw every
//   object up to a voxel larger: a 2 m roof 0.95 m above a floor hid 0.60 / 0.83 of the closed form's
//   sky at 64³ / 128³ (tests/gl/test_scene_defaults.cpp), and the Cornell floor in the blocks' shadows
//   read 0.83 of the reference at 64³ against 0.89 at 128³;
// - its rays start kRayStartVoxels off that plane. A ray that leaves a plane cannot cross it, nor the
//   coplanar planes of its neighbours, so it need not start clear of its own voxel: rays started √3
//   voxels off the voxel centre (coneOrigin), 6 cm nearer the lit floor at 64³ and 1 cm at 512³,
//   and the Cornell ceiling and back wall read 1.10 of the reference at 64³ against 0.99 and 0.97
//   at 512³.
// Two-sided voxels (both faces of a wall thinner than a voxel) stay cubes: rays end where they enter
// them and start at coneOrigin, so that a thin wall stops every ray.
const float kRayPlaneMinLength = kOneSidedMinLength;
const float kRayStartVoxels = LIT_RAY_START_VOXELS;
LIT_VOXEL_SURFACE_READER

// Where voxel v's rays start for the side `normal` (its averaged normal, unit, or its opposite).
vec3 rayOrigin(ivec3 v, vec3 normal, float agreement) {
    if (agreement < kRayPlaneMinLength) return coneOrigin(voxelCenter(v), normal);
    return voxelSurfaceWorldPoint(v, kRayStartVoxels * normal);
}

// The ray-hit cache (RayHitCache, LIT_SSBO_VOXEL_RAY_HITS): a ray's first hit depends
// on the voxels' occupancy, normals and surface points only, not on their light, so a trace over the list records
// each ray's hit (uRayHits 1) and later traces of the same rays replay them (2) with the radiance
// the volume holds then: a light edit's bounce and irradiance march no ray. 0: march, record nothing
// (the refinement's other sets, the all-sets variant). Entry (list index × 2 + side) × rays + ray.
layout(std430, binding = LIT_SSBO_VOXEL_RAY_HITS) buffer VoxelRayHits { uint rayHits[]; };
uniform int uRayHits;
// After a voxelization of changed boxes (VoxelChangeTracker) the hits stay: a list entry's hits
// were recorded in epoch rayEpochs[entry], a box changed in epoch uChangedBoxMin[i].w, and a replay
// marches (and records) again only the rays of an entry older than a box whose voxel lies in it
// (voxelChanged) or that cross it before their hits (rayCrossesChange).
layout(std430, binding = LIT_SSBO_VOXEL_RAY_EPOCHS) buffer VoxelRayEpochs { uint rayEpochs[]; };
uniform uint uRayEpoch;  // the epoch this trace records in
uniform int uChangedBoxCount;
uniform ivec4 uChangedBoxMin[LIT_CHANGED_BOXES];  // xyz first voxel, w the epoch of the change
uniform ivec4 uChangedBoxMax[LIT_CHANGED_BOXES];  // xyz one past the last voxel
uint gRecordedEpoch = 0u;    // this invocation's entry's epoch (main)
bool gVoxelChanged = false;  // its voxel changed since (main): every ray is marched again
#ifndef LIT_RAY_HIT_CACHE
#define LIT_RAY_HIT_CACHE 1  // 0: always march (the GL test's yardstick for the cache)
#endif
int rayHitMode() { return LIT_RAY_HIT_CACHE != 0 ? uRayHits : 0; }
const uint kRayHitSky = 0xffffffffu;   // left the volume: the sky
const uint kRayHitBack = 0x40000000u;  // flag: met a one-sided surface from behind (black)
// Flag: ended in a two-sided voxel, whose light depends on the side met (voxel.glsl, "Sides"; only
// these hits read the sides volume). Bit 29 is z's tenth bit, which volumes up to 512³ leave 0.
const uint kRayHitTwoSided = 0x20000000u;
ivec3 rayHitVoxel(uint hit) { return unpackVoxelCoord(hit & ~(kRayHitBack | kRayHitTwoSided)); }

// Whether the ray g0 + t'·d (in voxels from the volume's corner, t' ≥ t; inv = 1/d) meets the surface of the
// occupied voxel `cell` it is in, whose averaged normal is `averaged` (of length `agreement`) and
// whose surface point is `surfacePoint` (in voxels): a one-sided voxel where the ray is behind its
// plane at its entry or exit (0.01 voxel of slack: a plane on the face between two voxels belongs to
// one of them), any other where the ray enters it (a cube).
bool rayMeetsVoxelSurface(ivec3 cell, vec3 averaged, float agreement, vec3 surfacePoint, vec3 g0, vec3 d, vec3 inv,
                          float t) {
    if (agreement < kRayPlaneMinLength) return true;
    vec3 planeNormal = averaged / agreement;
    vec3 cellExit = (vec3(cell) + vec3(greaterThan(d, vec3(0.0))) - g0) * inv;
    float tCellExit = min(cellExit.x, min(cellExit.y, cellExit.z));
    vec3 fromSurface = g0 - surfacePoint;
    float heightIn = dot(fromSurface + t * d, planeNormal), heightOut = dot(fromSurface + tCellExit * d, planeNormal);
    return min(heightIn, heightOut) < 0.01;
}

// Whether a ray along `dir` meets a voxel of averaged normal `averaged` (length `agreement`) from
// behind: a one-sided surface facing away from it (black).
bool seenFromBehind(vec3 averaged, float agreement, vec3 dir) {
    return agreement >= kOneSidedMinLength && dot(averaged, dir) > kRayBackFaceCosine * agreement;
}

// Where a ray from `origin` along `dir` (world space, unit) ends: the first occupied level-0 voxel
// whose surface it meets (a one-sided voxel's plane crossed inside it, a two-sided voxel where the
// ray enters it; kRayPlaneMinLength), packed as the occupied list packs it, kRayHitBack added when
// that voxel holds a one-sided surface facing away from the ray (its back), or kRayHitSky past the
// volume. The march visits every voxel the ray passes through (cell by cell, from each cell's exit
// to the next), so a wall of face-connected voxels stops it: a plane that runs through a row of
// voxels is crossed in one of them.
uint marchVoxelRay(vec3 origin, vec3 dir) {
    int n = int(voxel.voxelInfo.x);
    vec3 g0 = (origin - voxel.volumeMin.xyz) / voxel.voxelInfo.z;  // in voxels from the volume's corner
    vec3 d = mix(dir, vec3(1e-7), lessThan(abs(dir), vec3(1e-7)));
    vec3 inv = 1.0 / d;
    vec3 t1 = -g0 * inv, t2 = (vec3(float(n)) - g0) * inv;
    float t = max(max(min(t1.x, t2.x), max(min(t1.y, t2.y), min(t1.z, t2.z))), 0.0) + 1e-4;
    float tLeave = min(max(t1.x, t2.x), min(max(t1.y, t2.y), max(t1.z, t2.z)));
    vec3 exitSide = vec3(greaterThan(d, vec3(0.0)));  // which face of a cell the ray leaves by
    for (int i = 0; i < kRayMaxSteps && t < tLeave; ++i) {
        ivec3 cell = clamp(ivec3(floor(g0 + t * d)), ivec3(0), ivec3(n - 1));
        ivec3 coarse = cell >> kRaySkipLevelCoarse;
        bool coarseEmpty = texelFetch(voxelRadianceTexture, coarse, kRaySkipLevelCoarse).a == 0.0;
        ivec3 block = cell >> kRaySkipLevel;
        bool blockEmpty = coarseEmpty || texelFetch(voxelRadianceTexture, block, kRaySkipLevel).a == 0.0;
        if (!blockEmpty && texelFetch(voxelRadianceTexture, cell, 0).a > 0.0) {
            vec3 averaged = unpackAveragedNormal(imageLoad(voxelNormal, cell).r);
            float agreement = length(averaged);
            if (rayMeetsVoxelSurface(cell, averaged, agreement, voxelSurfacePoint(cell), g0, d, inv, t)) {
                bool fromBehind = seenFromBehind(averaged, agreement, dir);
                return packVoxelCoord(cell) | (fromBehind ? kRayHitBack : 0u) |
                       (agreement < kOneSidedMinLength ? kRayHitTwoSided : 0u);
            }
        }
        // The cell to leave: the empty 16³ or 4³ block around the ray, else its voxel.
        float size = coarseEmpty ? float(1 << kRaySkipLevelCoarse) : (blockEmpty ? float(1 << kRaySkipLevel) : 1.0);
        vec3 corner = floor(vec3(cell) / size) * size;
        vec3 tExit = (corner + exitSide * size - g0) * inv;
        t = min(tExit.x, min(tExit.y, tExit.z)) + 1e-3;
    }
    return kRayHitSky;
}

// Whether voxel v lies in a box that changed after its entry's hits were recorded: then its own
// normal and surface point may be others, and with them its rays' origins and directions.
bool voxelChanged(ivec3 v) {
    for (int i = 0; i < uChangedBoxCount; ++i)
        if (uint(uChangedBoxMin[i].w) > gRecordedEpoch && all(greaterThanEqual(v, uChangedBoxMin[i].xyz)) &&
            all(lessThan(v, uChangedBoxMax[i].xyz)))
            return true;
    return false;
}

// Whether the ray from `origin` along `dir` (world space, unit), which ended at `hit` when it was
// recorded, crosses a box that changed since, before its hit (or before it left the volume): then
// its hit may be another now. A box counts as the empty-space blocks (2^kRaySkipLevelCoarse voxels)
// around it: a march steps by those blocks where they are empty, so a block that a change emptied or
// filled changes the steps (and which grazed voxels are visited) of every ray through it. The hit
// voxel's centre bounds the segment, with 1.5 voxels to spare (a ray meets its hit voxel within
// √3/2 of the centre's projection).
bool rayCrossesChange(vec3 origin, vec3 dir, uint hit) {
    float n = voxel.voxelInfo.x;
    vec3 g0 = (origin - voxel.volumeMin.xyz) / voxel.voxelInfo.z;
    float tEnd = hit == kRayHitSky ? 2.0 * n : dot(vec3(rayHitVoxel(hit)) + 0.5 - g0, dir) + 1.5;
    vec3 d = mix(dir, vec3(1e-7), lessThan(abs(dir), vec3(1e-7)));
    vec3 inv = 1.0 / d;
    const float block = float(1 << kRaySkipLevelCoarse);
    for (int i = 0; i < uChangedBoxCount; ++i) {
        if (uint(uChangedBoxMin[i].w) <= gRecordedEpoch) continue;
        vec3 lo = floor(vec3(uChangedBoxMin[i].xyz) / block) * block - 0.5;
        vec3 hi = ceil(vec3(uChangedBoxMax[i].xyz) / block) * block + 0.5;
        vec3 t1 = (lo - g0) * inv, t2 = (hi - g0) * inv;
        float tIn = max(max(min(t1.x, t2.x), min(t1.y, t2.y)), min(t1.z, t2.z));
        float tOut = min(min(max(t1.x, t2.x), max(t1.y, t2.y)), max(t1.z, t2.z));
        if (tIn <= tOut && tOut >= 0.0 && tIn <= tEnd) return true;
    }
    return false;
}

// What a ray along `dir` that ended at `hit` (marchVoxelRay) sees: the radiance the hit voxel holds
// now, black from behind, the sky past the volume.
// The bounces (not the irradiance pass) read it from LIT_IMG_VOXEL_RAY_SOURCE: the direct light for
// the second bounce, so that level 0 may keep the last update's light while a light edit's update
// runs (Renderer: the mips and specular cones see a whole update, and a light dragged in the editor
// does not restart it), the bounce before for later ones.
#if !LIT_BOUNCE_IRRADIANCE
layout(binding = LIT_IMG_VOXEL_RAY_SOURCE, LIT_RADIANCE_IMAGE_FORMAT) uniform readonly image3D voxelRaySource;
// Later bounces (uChangeSubset ≥ 0, BouncePass's BounceTrace::changeSubset): the light is linear in
// the light it gathers, so bounce k + 1 adds to bounce k what it reflects of bounce k's change,
//   L_{k+1} = L_k + albedo · Σ W_i/π · C_i(L_k − L_{k−1}),
// which uses no more rays than the change needs: one in uChangeStride of the voxel's rays, subset
// uChangeSubset (rotating from bounce to bounce). The change after the first bounce is smooth (a
// gather already); the direct light, whose small bright patches need every ray, is gathered
// whole by the first bounce of an update. The sky does not change: a ray that leaves sees none.
uniform int uChangeSubset;  // −1: gather the light itself over every ray
uniform int uChangeStride;
layout(binding = LIT_IMG_VOXEL_CHANGE, LIT_RADIANCE_IMAGE_FORMAT) uniform readonly image3D voxelChange;
bool gathersChange() { return uChangeSubset >= 0; }
vec3 rayHitChange(uint hit) {
    if (hit == kRayHitSky || (hit & kRayHitBack) != 0u) return vec3(0.0);
    return decodeRadiance(imageLoad(voxelChange, rayHitVoxel(hit)).rgb);
}
#else
bool gathersChange() { return false; }
#endif
#ifndef LIT_NEAR_LEVEL
#define LIT_NEAR_LEVEL 0
#endif
#if LIT_NEAR_LEVEL
// A near level (docs/GI.md, "Near levels"): a ray that leaves it goes on, from the point where it
// left, through the next volume out (the next near level, or the scene's volume), then through the
// scene's volume, each time stepped through the volume's level 0 (with the same empty-block
// skipping) to the first occupied voxel whose surface it meets (the plane test of marchVoxelRay),
// whose radiance it takes (black from behind); past the scene's volume, the sky. Those volumes updated first, so their
// level 0 holds every bounce they gathered, and their light does not change while this level's
// update runs: a later bounce's change gathers none of it (rayHitChange).
layout(std140, binding = LIT_UBO_OUTER_VOXEL) uniform OuterVoxelBlock {
    VoxelUniforms outerVoxel;
};
layout(std140, binding = LIT_UBO_FAR_VOXEL) uniform FarVoxelBlock {
    VoxelUniforms farVoxel;
};
layout(binding = LIT_TEX_OUTER_RADIANCE) uniform sampler3D outerRadianceTexture;
layout(binding = LIT_TEX_FAR_RADIANCE) uniform sampler3D farRadianceTexture;
layout(binding = LIT_TEX_OUTER_NORMAL) uniform usampler3D outerNormalTexture;
layout(binding = LIT_TEX_OUTER_SURFACE) uniform usampler3D outerSurfaceTexture;
layout(binding = LIT_TEX_FAR_NORMAL) uniform usampler3D farNormalTexture;
layout(binding = LIT_TEX_FAR_SURFACE) uniform usampler3D farSurfaceTexture;

// Marches `volume`'s level 0 (`radiance`, `normals`, `surfaces`) from `origin` along `d` (unit, no
// zero component): true with the radiance of the first voxel whose surface the ray meets in
// `found` (black from behind), else false with `leave` the distance (m) from `origin` at which the
// ray leaves the volume (0 when it starts outside and never enters).
bool marchLevel0(sampler3D radiance, usampler3D normals, usampler3D surfaces, VoxelUniforms volume, vec3 origin, vec3 d,
                 out vec3 found, out float leave) {
    found = vec3(0.0);
    int n = int(volume.voxelInfo.x);
    vec3 inv = 1.0 / d;
    vec3 g0 = (origin - volume.volumeMin.xyz) / volume.voxelInfo.z;
    vec3 t1 = -g0 * inv, t2 = (vec3(float(n)) - g0) * inv;
    float t = max(max(min(t1.x, t2.x), max(min(t1.y, t2.y), min(t1.z, t2.z))), 0.0) + 1e-4;
    float tLeave = min(max(t1.x, t2.x), min(max(t1.y, t2.y), max(t1.z, t2.z)));
    leave = max(tLeave, 0.0) * volume.voxelInfo.z;
    float tEnter = t;
    vec3 exitSide = vec3(greaterThan(d, vec3(0.0)));
    for (int i = 0; i < kRayMaxSteps && t < tLeave; ++i) {
        ivec3 cell = clamp(ivec3(floor(g0 + t * d)), ivec3(0), ivec3(n - 1));
        bool coarseEmpty = texelFetch(radiance, cell >> kRaySkipLevelCoarse, kRaySkipLevelCoarse).a == 0.0;
        bool blockEmpty = coarseEmpty || texelFetch(radiance, cell >> kRaySkipLevel, kRaySkipLevel).a == 0.0;
        vec4 s = blockEmpty ? vec4(0.0) : texelFetch(radiance, cell, 0);
        if (s.a > 0.0) {
            vec3 averaged = unpackAveragedNormal(texelFetch(normals, cell, 0).r);
            float agreement = length(averaged);
            // The plane test only in the cell where the ray entered this volume, which may hold the
            // surface it left (or one it runs along); past it a coarse voxel is taken whole.
            bool entryCell = all(equal(cell, clamp(ivec3(floor(g0 + tEnter * d)), ivec3(0), ivec3(n - 1))));
            vec4 local = unpackVoxel(texelFetch(surfaces, cell, 0).r);
            vec3 surfacePoint = vec3(cell) + (local.a > 0.0 ? local.xyz : vec3(0.5));
            if (!entryCell || rayMeetsVoxelSurface(cell, averaged, agreement, surfacePoint, g0, d, inv, t)) {
                found = seenFromBehind(averaged, agreement, d) ? vec3(0.0) : s.rgb / s.a * volume.radianceScale.y;
                return true;
            }
        }
        float size = coarseEmpty ? float(1 << kRaySkipLevelCoarse) : (blockEmpty ? float(1 << kRaySkipLevel) : 1.0);
        vec3 corner = floor(vec3(cell) / size) * size;
        vec3 tExit = (corner + exitSide * size - g0) * inv;
        t = min(tExit.x, min(tExit.y, tExit.z)) + 1e-3;
    }
    return false;
}

vec3 outerRayRadiance(vec3 origin, vec3 dir) {
    vec3 d = mix(dir, vec3(1e-7), lessThan(abs(dir), vec3(1e-7)));
    vec3 inv = 1.0 / d;
    // Where the ray leaves this level (m from origin).
    vec3 lo = (voxel.volumeMin.xyz - origin) * inv, hi = (voxel.volumeMin.xyz + voxel.volumeMin.w - origin) * inv;
    vec3 p = origin + max(min(max(lo.x, hi.x), min(max(lo.y, hi.y), max(lo.z, hi.z))), 0.0) * d;
    vec3 found;
    float leave;
    if (marchLevel0(outerRadianceTexture, outerNormalTexture, outerSurfaceTexture, outerVoxel, p, d, found, leave))
        return found;
    // From where it left the next volume out (when that is the scene's, it starts at its face and
    // never enters).
    if (marchLevel0(farRadianceTexture, farNormalTexture, farSurfaceTexture, farVoxel, p + leave * d, d, found, leave))
        return found;
    return skyRadiance(dir);
}
#endif

// Two-sided voxels' direct light by side (voxel.glsl, "Sides").
layout(binding = LIT_TEX_VOXEL_SIDES) uniform usampler3D voxelSidesTexture;

vec3 rayHitRadiance(uint hit, vec3 origin, vec3 dir) {
#if LIT_NEAR_LEVEL
    if (hit == kRayHitSky) return outerRayRadiance(origin, dir);
#else
    if (hit == kRayHitSky) return skyRadiance(dir);
#endif
    if ((hit & kRayHitBack) != 0u) return vec3(0.0);
#if LIT_BOUNCE_IRRADIANCE
    vec4 s = texelFetch(voxelRadianceTexture, rayHitVoxel(hit), 0);
#else
    vec4 s = imageLoad(voxelRaySource, rayHitVoxel(hit));
#endif
    if (s.a == 0.0) return vec3(0.0);
    vec3 stored = decodeRadiance(s.rgb / s.a);
    if ((hit & kRayHitTwoSided) == 0u) return stored;
    return radianceSeenFrom(stored, texelFetch(voxelSidesTexture, rayHitVoxel(hit), 0).xy, dir);
}

// Irradiance/π at `origin` over the hemisphere of `normal`: the mean radiance of uVoxelRays
// cosine-distributed rays (the estimator of (1/π)∫L cosθ dω). Ray i of set s: u₁ = (i + (s + j₁)/16)
// / rays (sin²θ, uniform in projected solid angle), u₂ = radical inverse of i + s/16 + j₂ (azimuth),
// mapped to the disk and lifted to the hemisphere (Malley). Each voxel's rays are a Hammersley set
// over the whole hemisphere, and the 16 sets of a 4 × 4 patch fill its strata with 16 different
// offsets: a voxel whose filter window is cut short (by an edge) still sees every direction. (j₁,
// j₂) is voxel v's own shift of the pattern (a hash of its coordinates): with one pattern for all
// voxels, neighbours saw a light source's edge through the same directions, and the ceiling and
// walls showed streaks radiating from the lit patch that the filter and the refinement kept.
// A near level's voxels hash their world coordinates (the level's corner lies on whole voxels
// of its grid, VoxelVolume::placeAt): a voxel keeps its rays when the level scrolls, so its light
// does not change with the camera's position.
uvec3 patternCoord(ivec3 v) {
#if LIT_NEAR_LEVEL
    return uvec3(v + ivec3(floor(voxel.volumeMin.xyz / voxel.voxelInfo.z + 0.5)));
#else
    return uvec3(v);
#endif
}

// Ray i's direction in voxel v's pattern (rayIrradiance): `shift` is v's shift, `frame` its side's.
vec3 patternRay(int i, int rays, int set, vec2 shift, mat3 frame) {
    float u1 = (float(i) + (float(set) + shift.x) / float(kConeSetCount)) / float(rays);
    float phi = 6.28318530718 * fract(radicalInverse(uint(i)) + float(set) / float(kConeSetCount) + shift.y);
    float r = sqrt(u1);
    return frame * vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u1, 0.0)));
}

vec3 rayIrradiance(ivec3 v, vec3 origin, vec3 normal, int set, int side) {
    mat3 frame = tangentFrame(normal);
    int rays = max(uVoxelRays, 1);
    uvec3 p = patternCoord(v);
    uint hash = pcgHash(p.x + pcgHash(p.y + pcgHash(p.z)));
    vec2 shift = vec2(float(hash & 0xffffu), float(hash >> 16u)) / 65536.0;
    uint firstSlot = (gListIndex * 2u + uint(side)) * uint(rays);
    vec3 sum = vec3(0.0);
    // A change gathers ray i = stride·j + (j + subset) mod stride, j = 0 .. rays/stride − 1: every
    // stride-th sin²θ stratum, and (rays being a Hammersley set, whose azimuth is the radical
    // inverse of i) the low bits of i, hence the azimuth's quarter, cycling with j.
    bool change = gathersChange();
#if LIT_BOUNCE_IRRADIANCE
    int stride = 1, subset = 0;
#else
    int stride = change ? max(uChangeStride, 1) : 1;
    int subset = change ? (uChangeSubset + int((hash >> 7u) & 0xffu)) % stride : 0;
#endif
    int count = max(rays / stride, 1);
    // A replay whose recorded hits all hold (no box changed since) has loops of its own that march
    // nothing: llvmpipe runs every path of a loop's body whatever its branches take, so in the
    // general loop below every replayed ray paid for a march, the change test and (in a change
    // gather) the whole radiance's reads (docs/PERFORMANCE.md, "llvmpipe").
    if (rayHitMode() == 2 && gRecordedEpoch >= uRayEpoch) {
#if !LIT_BOUNCE_IRRADIANCE
        if (change) {
            for (int j = 0; j < count; ++j)
                sum += rayHitChange(rayHits[firstSlot + uint(stride * j + (j + subset) % stride)]);
            return sum / float(count);
        }
#endif
        for (int i = 0; i < rays; ++i)
            sum += rayHitRadiance(rayHits[firstSlot + uint(i)], origin, patternRay(i, rays, set, shift, frame));
        return sum / float(rays);
    }
    for (int j = 0; j < count; ++j) {
        int i = stride * j + (j + subset) % stride;
        vec3 dir = patternRay(i, rays, set, shift, frame);
        uint slot = firstSlot + uint(i);
        uint hit;
        if (rayHitMode() == 2) {
            hit = rayHits[slot];
            if (gVoxelChanged || rayCrossesChange(origin, dir, hit)) {
                hit = marchVoxelRay(origin, dir);
                rayHits[slot] = hit;
            }
        } else {
            hit = marchVoxelRay(origin, dir);
            if (rayHitMode() == 1) rayHits[slot] = hit;
        }
#if !LIT_BOUNCE_IRRADIANCE
        if (change) {
            sum += rayHitChange(hit);
            continue;
        }
#endif
        sum += rayHitRadiance(hit, origin, dir);
    }
    return sum / float(count);
}
#endif

// Which empty voxels lie inside a solid (SolidVoxelsPass): a side whose rays or cones would start
// in one sees the inside of a wall, and through it the far side's light (docs/GI.md, "Solid voxels").
LIT_SOLID_VOXELS_READER

// The cone set (or ray set) voxel v traces: its place in the 4 × 4 pattern along its surface, turned
// by the refinement round (uSetOffset) in the cached mode's irradiance pass.
int voxelSet(ivec3 v, vec3 normal) {
#if LIT_BOUNCE_IRRADIANCE
    return (voxelConeSetIndex(v, normal) + uSetOffset) % kConeSetCount;
#else
    return voxelConeSetIndex(v, normal);
#endif
}

// Irradiance/π of voxel v's surface seen from the cone origin `origin` with normal `normal`.
// LIT_IRRADIANCE_ALL_SETS (the irradiance pass only): every set, averaged, instead of the voxel's one.
// `side`: 0 the voxel's front hemisphere, 1 its back (two-sided voxels), for the ray-hit cache.
vec3 bounceIrradiance(ivec3 v, vec3 origin, vec3 normal, float aperture, float maxDistance, int side) {
#if LIT_VOXEL_RAYS && LIT_BOUNCE_IRRADIANCE && LIT_IRRADIANCE_ALL_SETS
    vec3 sum = vec3(0.0);
    for (int set = 0; set < kConeSetCount; ++set) sum += rayIrradiance(v, origin, normal, set, side);
    return sum / float(kConeSetCount);
#elif LIT_VOXEL_RAYS
    return rayIrradiance(v, origin, normal, voxelSet(v, normal), side);
#elif LIT_CONE_FOOTPRINT && LIT_BOUNCE_IRRADIANCE && LIT_IRRADIANCE_ALL_SETS
    vec3 cones[kDiffuseConeCount];
    vec3 sum = vec3(0.0);
    mat3 frame = tangentFrame(normal);
    for (int set = 0; set < kConeSetCount; ++set)
        sum += traceDiffuseStratified(origin, frame, set, aperture, maxDistance, cones);
    return sum / float(kConeSetCount);
#elif LIT_CONE_FOOTPRINT
    vec3 cones[kDiffuseConeCount];
    return traceDiffuseStratified(origin, tangentFrame(normal), voxelSet(v, normal), aperture, maxDistance, cones);
#else
    return traceDiffuse(origin, normal, aperture, maxDistance);
#endif
}

#if !LIT_BOUNCE_IRRADIANCE
// `radiance` as the bounce volume will hold it once stored: the change is measured between stored
// values, as the next bounce reads them. In RGBA8 (steps of gi.radianceRange / 255) the unrounded
// new light against the rounded old one read the rounding alone as a steady change of 20 % of a
// dim scene's bounced light, and every bounce ran to the cap (Sponza, 128³).
vec3 asStored(vec3 radiance) {
#if LIT_BOUNCE_RGBA8
    return decodeRadiance(unpackUnorm4x8(packUnorm4x8(vec4(encodeRadiance(radiance), 1.0))).rgb);
#else
    return radiance;
#endif
}

// Adds voxel v's bounced light (radiance − direct) and its change from the bounce before to the
// change bins (every bounce until converged: uMeasureChange).
void measureChange(ivec3 v, vec3 radiance, vec3 previous, vec3 direct) {
    const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);
    // The change is measured against the bounced light, not the whole radiance: in a room lit
    // through a window the sunlit outside and the floor's patch outweigh the light inside,
    // and against them the bounces looked converged after three (the room read 0.59 of the
    // reference, with 8 bounces 0.86).
    float luminance = dot(radiance, kLuminance);
    float change = abs(luminance - dot(previous, kLuminance));
    luminance -= dot(direct, kLuminance);
    uint bin = (uint(v.x) + 7u * uint(v.y) + 13u * uint(v.z)) % uint(LIT_BOUNCE_CHANGE_BINS);
    // Fixed point, rounded stochastically (a per-voxel offset in [0, 1) before truncating):
    // truncation dropped every change below 1/256 W/(sr·m²), most of a dim room's, and its
    // bounces looked converged after four. The sums stay unbiased; over 10⁵ voxels the
    // rounding adds a few tenths of a per cent. Clamped per voxel; a bin of 32 768 voxels (a
    // million in all) overflows only at a mean radiance above 500 W/(sr·m²).
    uint dither = pcgHash(uint(v.x) + pcgHash(uint(v.y) + pcgHash(uint(v.z))));
    float offsetLuminance = float(dither & 0xffffu) * (1.0 / 65536.0);
    float offsetChange = float(dither >> 16u) * (1.0 / 65536.0);
    atomicAdd(changeBins[bin], uint(min(luminance * LIT_BOUNCE_CHANGE_SCALE + offsetLuminance, 4194304.0)));
    atomicAdd(changeBins[LIT_BOUNCE_CHANGE_BINS + bin],
              uint(min(change * LIT_BOUNCE_CHANGE_SCALE + offsetChange, 4194304.0)));
}
#endif

void main() {
    ivec3 v;
    if (uFromList != 0) {
        if (!listedVoxelInRange(v, gListIndex)) return;
    } else {
        v = ivec3(gl_GlobalInvocationID);
    }
    int n = int(voxel.voxelInfo.x);
    if (any(greaterThanEqual(v, ivec3(n)))) return;
    vec4 albedo = unpackVoxel(imageLoad(voxelAlbedo, v).r);
#if LIT_BOUNCE_IRRADIANCE
    if (albedo.a == 0.0) return;  // empty: the gather skips it (voxel_irradiance.glsl)
#else
    vec4 direct = imageLoad(voxelDirect, v);
    if (albedo.a == 0.0 || direct.a == 0.0) {
        imageStore(voxelBounce, v, direct);
        return;
    }
#endif
#if LIT_VOXEL_RAYS
    if (rayHitMode() != 0) {
        gRecordedEpoch = rayEpochs[gListIndex];
        gVoxelChanged = voxelChanged(v);
    }
#endif
    vec3 averaged = unpackAveragedNormal(imageLoad(voxelNormal, v).r);
    float agreement = length(averaged);
    vec3 normal = agreement >= kDirectionMinLength ? averaged / agreement : vec3(0.0, 1.0, 0.0);
    vec3 centre = voxelCenter(v);
    float aperture = voxel.traceParams.w, maxDistance = voxel.traceParams.y;
    // Voxels whose normals disagree (both sides of a thin wall) gather over both hemispheres.
#if LIT_VOXEL_RAYS
    vec3 frontOrigin = rayOrigin(v, normal, agreement);
#else
    vec3 frontOrigin = coneOrigin(centre, normal);
#endif
    // A side that would start inside a solid (an edge voxel's plane pushed into the wall beside it)
    // starts at the cone apex instead; a side whose apex is inside too (faces buried back to back
    // where two solids touch) gathers nothing and is left untraced: the filter and the gather skip it.
    bool frontOpen = !insideSolid(frontOrigin);
    if (!frontOpen) {
        frontOrigin = coneOrigin(centre, normal);
        frontOpen = !insideSolid(frontOrigin);
    }
    bool twoSided = agreement < kOneSidedMinLength;
    vec3 backOrigin = coneOrigin(centre, -normal);
    bool backOpen = twoSided ? !insideSolid(backOrigin) : frontOpen;
    vec3 front = frontOpen ? bounceIrradiance(v, frontOrigin, normal, aperture, maxDistance, 0) : vec3(0.0);
    vec3 back = !twoSided ? front
                          : (backOpen ? bounceIrradiance(v, backOrigin, -normal, aperture, maxDistance, 1) : vec3(0.0));
#if LIT_VOXEL_RAYS
    // Both sides' hits hold now; a change's subset re-marched only some of them.
    if (rayHitMode() != 0 && !gathersChange()) rayEpochs[gListIndex] = uRayEpoch;
#endif
#if LIT_BOUNCE_IRRADIANCE
    if (uBlend < 1.0) {
        vec4 oldFront = imageLoad(voxelIrradianceOut, v), oldBack = imageLoad(voxelIrradianceOut, otherSideTexel(v));
        // A voxel not traced yet (alpha 0) takes the new value alone.
        if (oldFront.a > 0.0) front = mix(decodeRadiance(oldFront.rgb), front, uBlend);
        if (oldBack.a > 0.0) back = mix(decodeRadiance(oldBack.rgb), back, uBlend);
    }
    imageStore(voxelIrradianceOut, v, vec4(encodeRadiance(front), frontOpen ? 1.0 : 0.0));
    imageStore(voxelIrradianceOut, otherSideTexel(v), vec4(encodeRadiance(back), backOpen ? 1.0 : 0.0));
#else
    // The mean of the open sides (= front for a one-sided voxel); none open: direct light only.
    float openSides = float(frontOpen) + float(backOpen);
    vec3 irradiance = openSides > 0.0 ? (front + back) / openSides : vec3(0.0);
    vec3 radiance = decodeRadiance(direct.rgb) + albedo.rgb * irradiance * voxel.traceParams.x;
#if LIT_VOXEL_RAYS
    if (gathersChange()) {
        // What this bounce adds to the one before (level 0) is stored as it is, not their sum: the
        // bounce copy adds it, and keeps it unrounded as the change the next bounce gathers (a
        // change taken from two rounded sums lost the light of the later bounces where it fell
        // below the sum's half-float rounding: 1 % of a sun-lit room's bounced light).
        vec3 added = albedo.rgb * irradiance * voxel.traceParams.x;
        imageStore(voxelBounce, v, vec4(encodeRadiance(added), kBounceAddsAlpha));
        if (uMeasureChange != 0) {
            vec4 before = imageLoad(voxelRaySource, v);
            vec3 previous = before.a > 0.0 ? decodeRadiance(before.rgb / before.a) : decodeRadiance(direct.rgb);
            measureChange(v, previous + added, previous, decodeRadiance(direct.rgb));
        }
        return;
    }
#endif
    imageStore(voxelBounce, v, vec4(encodeRadiance(radiance), 1.0));
    if (uMeasureChange != 0) {
        // The bounce before: where the rays take their light (the direct volume for the second
        // bounce, level 0 after it), or level 0 for cones.
#if LIT_VOXEL_RAYS
        vec4 before = imageLoad(voxelRaySource, v);
#else
        vec4 before = texelFetch(voxelRadianceTexture, v, 0);
#endif
        measureChange(v, asStored(radiance), before.a > 0.0 ? decodeRadiance(before.rgb / before.a) : vec3(0.0),
                      decodeRadiance(direct.rgb));
    }
#endif
}
