#version 450 core
// Radiance injection: the outgoing radiance of every occupied voxel under direct light,
//   L = emission + Σ_lights albedo/π · E⊥ · cosθ · visibility      (W/(sr·m²))
// a Lambertian reflector, with E⊥ and visibility from lights.glsl at the voxel centre. Empty
// voxels get 0 (and opacity 0), so this pass also clears level 0 of the radiance volume.
//
// Normals: the normal volume holds the average of n·0.5+0.5 over the voxel's fragments. Its
// length tells how much the normals agreed: ~1 for a flat surface, ~0.7 at a box edge, ~0.58 at
// a corner, ~0 where opposite faces share the voxel (the two faces of a wall thinner than a
// voxel). Below kOneSidedMinLength the voxel is two-sided: in a slab (twoSidedAxis finds its
// axis a from the neighbours) each light reaches the face on its side, at cosθ = |a·l|, and the
// voxel stores the mean of its two sides' light, with their half difference in the sides volume
// (voxel.glsl, "Sides"), so that each side sends only its own face's light. Where no slab shows,
// it is lit from both sides (|n·l|) and sends that light both ways; below kDirectionMinLength the
// direction is quantization noise, and it takes the light unattenuated (cosθ = 1, the most a face
// of it can receive). A one-sided voxel's cosine is taken with the averaged normal
// as it is, not normalized: n̄·l is the mean of its faces' cosines (weighted by their fragments),
// so a voxel across a box's edge sends the mean of its faces' light (the lit top and the dark
// side of a box under a high sun: half the top's), where the normalized normal gave it 1/|n̄| of
// that (1.41× at an edge, 1.73× at a corner).
#include "frame.glsl"
#include "lights.glsl"
#include "voxel.glsl"

layout(local_size_x = LIT_INJECT_GROUP_SIZE, local_size_y = LIT_INJECT_GROUP_SIZE, local_size_z = LIT_INJECT_GROUP_SIZE) in;

layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform readonly uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D voxelNormal;
layout(binding = LIT_IMG_VOXEL_EMISSION, r32ui) uniform readonly uimage3D voxelEmission;
// RGBA16F or RGBA8 (VoxelVolume::radianceFormat()): store-only, so no format qualifier needed.
layout(binding = LIT_IMG_VOXEL_RADIANCE) uniform writeonly image3D voxelRadiance;
// With light bounces (uWriteDirect 1, VoxelVolume::direct() allocated) the same radiance goes to
// the direct volume too, which the bounces read (bounce.comp.glsl) while level 0 is replaced: one
// more store per listed voxel instead of copying the whole N³ volume in the edit's frame.
layout(binding = LIT_IMG_VOXEL_DIRECT) uniform writeonly image3D voxelDirect;
uniform int uWriteDirect;
// Two-sided voxels' split of their direct light by side (voxel.glsl, "Sides").
layout(binding = LIT_IMG_VOXEL_SIDES, rg32ui) uniform writeonly uimage3D voxelSides;
// 0 (with uWriteDirect): level 0 keeps the last update's light, which the bounces replace once
// they are done (a light edit with voxel rays: VoxelGi, InjectOptions::writeLevel0).
uniform int uWriteLevel0;
// ... but level 0 is written in these boxes all the same: a voxelization of changed boxes cleared
// their voxels' light (InjectOptions::level0Boxes; xyz first voxel, one past the last).
uniform int uLevel0BoxCount;
uniform ivec4 uLevel0BoxMin[LIT_CHANGED_BOXES], uLevel0BoxMax[LIT_CHANGED_BOXES];

bool inLevel0Box(ivec3 v) {
    for (int i = 0; i < uLevel0BoxCount; ++i)
        if (all(greaterThanEqual(v, uLevel0BoxMin[i].xyz)) && all(lessThan(v, uLevel0BoxMax[i].xyz))) return true;
    return false;
}

// The axis of the slab a two-sided voxel lies in: the direction in which the occupied voxels of its
// 3×3×3 neighbourhood spread least, the eigenvector of the smallest eigenvalue of M = Σ o·oᵀ over
// their offsets o (power iteration on tr(M)·I − M). False where no plane stands out: the smallest
// eigenvalue not below half the middle one (a lone voxel, a line of them, a corner).
bool twoSidedAxis(ivec3 v, out vec3 axis) {
    axis = vec3(0.0, 1.0, 0.0);
    int n = int(voxel.voxelInfo.x);
    mat3 m = mat3(0.0);
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                ivec3 c = v + ivec3(x, y, z);
                if ((x | y | z) == 0 || any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(n)))) continue;
                if (unpackVoxel(imageLoad(voxelAlbedo, c).r).a == 0.0) continue;
                vec3 o = vec3(x, y, z);
                m += outerProduct(o, o);
            }
    float trace = m[0][0] + m[1][1] + m[2][2];
    if (trace == 0.0) return false;
    mat3 b = mat3(trace) - m;
    vec3 a = normalize(vec3(0.31, 0.83, 0.47));
    for (int i = 0; i < 16; ++i) {
        vec3 next = b * a;
        if (dot(next, next) < 1e-12) return false;
        a = normalize(next);
    }
    // M's eigenvalues: the smallest along a, the other two from their sum and sum of squares.
    float smallest = dot(a, m * a);
    float sum = trace - smallest;
    float squares = dot(m[0], m[0]) + dot(m[1], m[1]) + dot(m[2], m[2]) - smallest * smallest;
    float middle = 0.5 * (sum - sqrt(max(2.0 * squares - sum * sum, 0.0)));
    axis = a;
    return smallest < 0.5 * middle;
}

void storeRadiance(ivec3 v, vec4 value) {
    if (uWriteLevel0 != 0 || inLevel0Box(v)) imageStore(voxelRadiance, v, value);
    if (uWriteDirect != 0) imageStore(voxelDirect, v, value);
}

const float kPi = 3.14159265358979;
// Where a voxel asks the shadow map whether it is lit. A one-sided voxel asks at the point of its
// surface the voxelization recorded (voxelSurfacePoint), kShadowSurfaceOffsetVoxels out along its
// normal, so its light is its surface's wherever in the voxel the surface lies. The voxel centre
// lies up to half a voxel off the surface, so a lookup from it must start a whole voxel out, and
// under a low sun a point 0.5–1.5 voxels above a floor is lit where the floor 1–3 voxels further
// along the light is: the light would move towards the window (docs/GI.md, "Injection"). Two-sided
// voxels (faces back to back) keep the centre.
const float kShadowSurfaceOffsetVoxels = 0.25;
// Plus this many shadow texels (lights.glsl's normal offset), against acne.
const float kShadowNormalOffsetTexels = 2.0;
// No PCF widening: a voxel spans several shadow texels and the mip chain filters the result.
// The 3×3 taps then hit the same texels; spread by the lighting pass's 1.5 texels they made
// injection ~2.5× slower on llvmpipe (Cornell box, 128³).
const float kShadowPcfRadius = 0.0;

// Invocation → voxel in 3D Morton order inside the 8×8×8 group: the invocations a CPU SIMD
// vector or a GPU wave runs together (consecutive indices) cover a 2×2×2 (4×4×2, ...) block
// instead of a row, so a wall crossing the block occupies about half of them in any
// orientation, not one lane in 8 for walls across the row. Only occupied voxels do the
// expensive light loop, so fewer mostly-empty vectors do it (~15% faster on llvmpipe, Cornell
// box at 128³).
uvec3 mortonLocal(uint i) {
    return uvec3((i & 1u) | ((i >> 2u) & 2u) | ((i >> 4u) & 4u),
                 ((i >> 1u) & 1u) | ((i >> 3u) & 2u) | ((i >> 5u) & 4u),
                 ((i >> 2u) & 1u) | ((i >> 4u) & 2u) | ((i >> 6u) & 4u));
}

// Occupied-voxel list (InjectPass with uFromList = 1): the work groups run along the list
// (glDispatchComputeIndirect, LIT_INJECT_LIST_GROUP_SIZE = 8³ entries each) instead of over N³.
LIT_VOXEL_LIST_READER
LIT_VOXEL_SURFACE_READER

void main() {
    ivec3 v;
    if (uFromList != 0) {
        if (!listedVoxel(v)) return;
    } else {
        v = ivec3(gl_WorkGroupID * uint(LIT_INJECT_GROUP_SIZE) + mortonLocal(gl_LocalInvocationIndex));
    }
    int n = int(voxel.voxelInfo.x);
    if (any(greaterThanEqual(v, ivec3(n)))) return;

    vec4 albedo = unpackVoxel(imageLoad(voxelAlbedo, v).r);
    if (albedo.a == 0.0) {
        storeRadiance(v, vec4(0.0));
        imageStore(voxelSides, v, uvec4(0u));
        return;
    }
    vec3 averaged = unpackAveragedNormal(imageLoad(voxelNormal, v).r);
    float agreement = length(averaged);
    bool oneSided = agreement >= kOneSidedMinLength;
    bool hasDirection = agreement >= kDirectionMinLength;
    vec3 normal = hasDirection ? averaged / agreement : vec3(0.0);
    // A two-sided voxel in a slab: each light reaches the face on its side (voxel.glsl, "Sides").
    vec3 axis;
    bool split = !oneSided && twoSidedAxis(v, axis);
    vec3 plusSide = vec3(0.0), minusSide = vec3(0.0);

    vec3 radiance = unpackVoxel(imageLoad(voxelEmission, v).r).rgb * LIT_VOXEL_EMISSION_RANGE;
    vec3 centre = voxelCenter(v);
    float voxelSize = voxel.voxelInfo.z;
    int lightCount = min(frame.counts.x, LIT_MAX_LIGHTS);
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = lights[i];
        LightSample s = sampleLight(light, centre);
        float nl = dot(split ? axis : normal, s.l);
        float cosine = split ? abs(nl) : (!hasDirection ? 1.0 : (oneSided ? max(nl * agreement, 0.0) : abs(nl)));
        if (cosine <= 0.0) continue;
        // The side of the voxel that faces the light.
        vec3 facing = split ? (nl < 0.0 ? -axis : axis) : (!hasDirection ? s.l : (nl < 0.0 ? -normal : normal));
        vec3 lookup = oneSided ? voxelSurfaceWorldPoint(v, kShadowSurfaceOffsetVoxels * facing) : centre + facing * voxelSize;
        vec3 visibility = shadowVisibility(light, lookup, facing, kShadowPcfRadius,
                                            kShadowNormalOffsetTexels);
        // A voxel holding faces back to back (a wall thinner than a voxel, or two solids that touch)
        // is lit by whichever face the light reaches: only if the point half a voxel from its centre
        // towards the light is lit too, which is at or above any face inside it (a 1 cm slab stays
        // lit: VoxelInject.WallThinnerThanAVoxelSendsEachSideItsOwnLight). At a
        // room's inner edges, where a wall's end meets the next wall's face, that point is in the
        // room's shadow while the point a voxel out can be outside it, and the voxel rays, which pass
        // in front of one-sided voxels to these (bounce.comp.glsl), saw that light inside: the sealed
        // room let in 0.73 % of the outside light at 128³, 0.42 % with this (docs/GI.md, "Injection").
        if (!oneSided)
            visibility *= shadowVisibility(light, centre + facing * (0.5 * voxelSize), facing, kShadowPcfRadius,
                                           kShadowNormalOffsetTexels);
        vec3 reflected = albedo.rgb / kPi * s.radiance * cosine * visibility;
        if (!split)
            radiance += reflected;
        else if (nl < 0.0)
            minusSide += reflected;
        else
            plusSide += reflected;
    }
    radiance += 0.5 * (plusSide + minusSide);
    storeRadiance(v, vec4(encodeRadiance(radiance), 1.0));
    imageStore(voxelSides, v, uvec4(split ? packSides(axis, encodeRadiance(0.5 * (plusSide - minusSide))) : uvec2(0u), 0u, 0u));
}
