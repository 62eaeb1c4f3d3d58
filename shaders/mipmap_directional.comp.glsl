#version 450 core
// Anisotropic mip levels (Crassin et al. 2011, "Interactive Indirect Illumination Using Voxel Cone
// Tracing", section 5.1): one volume per face a cone can look through, VoxelVolume::directional.
// Face f = 2·axis + s holds, for a cone TRAVELLING along +axis (s = 0) or −axis (s = 1), what the
// cone sees of each 2×2×2 block: the 4 child pairs along the axis are composited front to back
// (front = the child the cone reaches first), premultiplied,
//     parent_pair = front + (1 − front.a) · back        (rgb and a alike)
// and the 4 pairs averaged (their share of the parent's cross-section). A wall one voxel thick
// stays opaque seen face-on at every level, but covers only 2^-k of the cross-section seen
// edge-on at level k (the isotropic stacked mips make it opaque from every side, so a surface
// occludes and lights itself through its own coarse voxels: docs/GI.md, "Anisotropic voxels").
// Seen from inside a closed room, a coarse voxel that holds the wall and what lies behind it shows
// the wall's inner side, so the outside does not bleed in.
//
// Level 1 is built from the isotropic level 0 and the voxels' normals (directional emission):
// a Lambertian surface sends its radiance only to the side it faces, so a child whose averaged
// normal n faces away from the cone (n·(−D) < 0, D the travel direction) keeps its opacity but
// not its light. The weight is clamp(1 + 4·n·(−D), 0, 1): 1 for a face turned towards the cone
// or seen edge-on (edge-on 0 on a slab: "backed" below), 0 for one turned away by more than 15°. (Edge-on ½ instead halved the light a
// floor sends to cones that graze it: a hollow emissive box lost 20 % of its bounce light; edge-on 1 lets a one-voxel wall lit on one side
// glow, seen edge-on, towards its dark side: GiAccuracy.ThinWallLitOnOneSide*.) Voxels whose
// normals disagree (both faces of a wall thinner than a voxel, averaged length < ½) or that have no
// normal (volumes filled by tests) stay isotropic. Levels k+1 ≥ 2 come from level k of the same
// face.
//
// Defines set by MipmapPass:
//   LIT_MIP_RGBA8            1: rgba8 images, 0: rgba16f
//   LIT_DIRECTIONAL_FROM_ISO 1: build level 1 of all six faces from the isotropic level 0 (+ normals),
//                            0: level k+1 of one face (uFace) from its level k
//   LIT_MIP_FROM_LIST        1: one invocation per entry of the occupied-parent list of the
//                            radiance level this directional level mirrors (mip_parents.glsl,
//                            indirect dispatch); other voxels stay as cleared (0, as the whole
//                            grid computes them: their children are all empty)
#include "shared.h"
#if LIT_MIP_FROM_LIST
#include "mip_parents.glsl"
layout(local_size_x = LIT_INJECT_LIST_GROUP_SIZE) in;
LIT_MIP_PARENT_READER;
#else
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#endif

#if LIT_MIP_RGBA8
#define MIP_FORMAT rgba8
#else
#define MIP_FORMAT rgba16f
#endif

layout(binding = LIT_IMG_MIP_SOURCE, MIP_FORMAT) uniform readonly image3D uSource;
#if LIT_DIRECTIONAL_FROM_ISO
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform readonly uimage3D uNormal;
#endif

#if LIT_DIRECTIONAL_FROM_ISO
// The three directional volumes, axis X, Y, Z; the −axis face at x offset 2·edge of each.
layout(binding = LIT_IMG_MIP_DEST, MIP_FORMAT) uniform writeonly image3D uDestX;
layout(binding = LIT_IMG_MIP_DEST2, MIP_FORMAT) uniform writeonly image3D uDestY;
layout(binding = LIT_IMG_MIP_DEST3, MIP_FORMAT) uniform writeonly image3D uDestZ;
uniform int uEdge;  // edge of the level written
const ivec2 uOffsets = ivec2(0);  // the source is the isotropic level 0
#else
layout(binding = LIT_IMG_MIP_DEST, MIP_FORMAT) uniform writeonly image3D uDest;
uniform ivec3 uFace;  // x axis (0 X, 1 Y, 2 Z), y 1 if the cone travels towards −axis, z edge of the level written
// The two faces of an axis share one volume, side by side along x (VoxelVolume.h): x offsets in
// texels of this face's region in the source (x) and destination (y) level; 0 for the +axis face.
uniform ivec2 uOffsets;
#endif

#if LIT_DIRECTIONAL_FROM_ISO
// Surfaces seen edge-on on a slab (the sealed room's leak). A face seen edge-on keeps its
// light (weight 1, above), which is right for a lone surface: a cone that grazes a floor from above
// sees the floor's light. But the outer face of a wall only a few voxels thick is seen edge-on by
// a directional face of every coarse voxel that holds the wall, and such a voxel is also what a
// cone from INSIDE the room samples: the face that sees the wall edge-on showed the sunlit outside
// to it (1.36 % / 1.17 % of the outside radiance leaked into the benchmark's sealed room at
// 128³ / 256³, 0.2 m walls, footprint bound 0.25: docs/GI.md, "Anisotropic voxels"). Six faces
// cannot tell from which side of the slab a cone comes. So a surface whose slab's other side lies
// right behind it (an occupied level-0 voxel within kBackedSearchVoxels against its normal, whose
// normal points the other way or which holds both sides) is left out of the faces that see it
// edge-on: no light and no opacity there. A cone that meets the slab at a slant then takes the
// surface's light from the faces that see it face-on (the d² blend, cone.glsl). Kept opaque and
// dark there, a backed surface darkened every such cone: a rough gold sphere on a floor 6 voxels
// thick reflected 0.60 of the reference's light at 128³, and 0.79 with it left out (0.99 at
// 256³, where the floor is 12 voxels thick and not backed; GiAccuracy.GrazingConesSeeABackedFloorsLight).
// Surfaces with nothing behind them within that distance (single-sided walls, the Cornell box's
// hollow blocks away from their edges) keep weight 1.
// 8 voxels: the benchmark's walls are 3.2 voxels thick at 256³ and 6.4 at 512³ (searching 4 left
// 512³ at 1.07 %; 8: 0.06 %; the Cornell regions and the suite's scenes are the same with 4 or 8).
// A thicker slab's two faces share only voxels of level ≥ 4, wider than the slab's faces' share.
const int kBackedSearchVoxels = 8;

bool backedBySlab(ivec3 p, vec3 n) {
    for (int j = 1; j <= kBackedSearchVoxels; ++j) {
        ivec3 q = p - ivec3(round(n * float(j)));
        if (imageLoad(uSource, q + ivec3(uOffsets.x, 0, 0)).a == 0.0) continue;
        vec4 stored = unpackUnorm4x8(imageLoad(uNormal, q).r);
        if (stored.a == 0.0) continue;  // no normal recorded: not a surface of this slab
        vec3 m = stored.xyz * 2.0 - 1.0;
        float agreement = length(m);
        // The other side (normal turned away by more than 120°) or both sides in one voxel; a
        // neighbour of the same surface (a staircase, a surface on a voxel boundary) is not.
        if (agreement < 0.5 || dot(m, n) < -0.5 * agreement) return true;
    }
    return false;
}
#endif

#if LIT_DIRECTIONAL_FROM_ISO
// A level-0 voxel's normal as the faces weigh it: xyz the unit normal, w 1 if the voxel is
// directional (a normal recorded whose sides agree), else 0 (isotropic: every face sees it whole).
vec4 directionalNormal(ivec3 p) {
    vec4 stored = unpackUnorm4x8(imageLoad(uNormal, p).r);
    if (stored.a == 0.0) return vec4(0.0);  // no normal recorded
    vec3 averaged = stored.xyz * 2.0 - 1.0;
    float agreement = length(averaged);
    if (agreement < 0.5) return vec4(0.0);  // both sides of a thin wall: see inject.comp.glsl
    return vec4(averaged / agreement, 1.0);
}

// What of a level-0 voxel of normal `n` (directionalNormal) a cone travelling along `travel`
// sees: x the share of its light (its opacity kept: a face turned away), y the share of the
// whole voxel (a backed slab edge-on). `backed` is backedBySlab(p, n.xyz), asked only when it
// matters (the search reads up to 16 texels); once asked, the answer is kept in `asked`.
vec2 shareTowards(ivec3 p, vec4 n, vec3 travel, inout int asked) {
    if (n.w == 0.0) return vec2(1.0);
    float facing = dot(n.xyz, -travel);
    float light = clamp(1.0 + 4.0 * facing, 0.0, 1.0);
    // Backed (above): the voxel fades from whole (facing ≥ ¼) to absent edge-on.
    if (!(facing < 0.25 && light > 0.0)) return vec2(light, 1.0);
    if (asked == 0) asked = backedBySlab(p, n.xyz) ? 2 : 1;
    return vec2(light, asked == 2 ? clamp(4.0 * facing, 0.0, 1.0) : 1.0);
}
#endif

// This invocation's parent: its entry of the list, or its place in the grid; false past the list.
bool parentOfInvocation(out ivec3 p) {
#if LIT_MIP_FROM_LIST
    return listedParent(p);
#else
    p = ivec3(gl_GlobalInvocationID);
    return true;
#endif
}

// A step along `axis`, and steps along the two other axes, which span a block's 4 child pairs.
void axisFrame(int axis, out ivec3 along, out ivec3 u, out ivec3 v) {
    along = ivec3(0);
    along[axis] = 1;
    u = ivec3(0);
    v = ivec3(0);
    u[(axis + 1) % 3] = 1;
    v[(axis + 2) % 3] = 1;
}

#if LIT_DIRECTIONAL_FROM_ISO
// One invocation writes the parent of all six faces: its 8 children, their normals and each
// child's slab search are read once, not once per face.
void main() {
    ivec3 p;
    if (!parentOfInvocation(p)) return;
    if (any(greaterThanEqual(p, ivec3(uEdge)))) return;
    ivec3 base = p * 2;
    // Child i = x + 2y + 4z of the block: its radiance, its normal and its slab search, once.
    vec4 children[8];
    vec4 normals[8];
    int asked[8];
    for (int i = 0; i < 8; ++i) {
        ivec3 q = base + ivec3(i & 1, (i >> 1) & 1, i >> 2);
        children[i] = imageLoad(uSource, q);
        normals[i] = children[i].a > 0.0 ? directionalNormal(q) : vec4(0.0);
        asked[i] = 0;
    }
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 along, u, v;
        axisFrame(axis, along, u, v);
        for (int s = 0; s < 2; ++s) {
            bool negative = s == 1;
            vec3 travel = vec3(0.0);
            travel[axis] = negative ? -1.0 : 1.0;
            vec4 sum = vec4(0.0);
            for (int j = 0; j < 4; ++j) {
                ivec3 q = (j & 1) * u + (j >> 1) * v;
                int iLow = q.x + 2 * q.y + 4 * q.z;
                int iHigh = iLow + (axis == 0 ? 1 : axis == 1 ? 2 : 4);
                vec4 low = children[iLow], high = children[iHigh];
                if (low.a > 0.0) {
                    vec2 share = shareTowards(base + q, normals[iLow], travel, asked[iLow]);
                    low.rgb *= share.x;
                    low *= share.y;
                }
                if (high.a > 0.0) {
                    vec2 share = shareTowards(base + q + along, normals[iHigh], travel, asked[iHigh]);
                    high.rgb *= share.x;
                    high *= share.y;
                }
                vec4 front = negative ? high : low;
                vec4 back = negative ? low : high;
                sum += front + (1.0 - front.a) * back;
            }
            ivec3 at = p + ivec3(negative ? 2 * uEdge : 0, 0, 0);
            if (axis == 0)
                imageStore(uDestX, at, 0.25 * sum);
            else if (axis == 1)
                imageStore(uDestY, at, 0.25 * sum);
            else
                imageStore(uDestZ, at, 0.25 * sum);
        }
    }
}
#else
vec4 child(ivec3 p) { return imageLoad(uSource, p + ivec3(uOffsets.x, 0, 0)); }

void main() {
    ivec3 p;
    if (!parentOfInvocation(p)) return;
    if (any(greaterThanEqual(p, ivec3(uFace.z)))) return;
    int axis = uFace.x;
    bool negative = uFace.y != 0;
    ivec3 along, u, v;
    axisFrame(axis, along, u, v);
    ivec3 base = p * 2;
    vec4 sum = vec4(0.0);
    for (int j = 0; j < 4; ++j) {
        ivec3 q = base + (j & 1) * u + (j >> 1) * v;
        vec4 low = child(q), high = child(q + along);
        vec4 front = negative ? high : low;
        vec4 back = negative ? low : high;
        sum += front + (1.0 - front.a) * back;
    }
    imageStore(uDest, p + ivec3(uOffsets.y, 0, 0), 0.25 * sum);
}
#endif
