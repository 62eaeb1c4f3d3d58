#version 450 core
// Mipmap pass: builds levels k+1 .. k+uDispatch.y of the radiance volume from level k.
//
// The volume holds PREMULTIPLIED radiance: rgb = radiance × opacity, a = opacity (docs/GI.md).
// A parent is its 2×2×2 children STACKED along the axis where they block the most light
// (directional opacity, as anisotropic VXGI, but stored as one isotropic value):
//   for each axis X, Y, Z, composite each of the 4 child pairs along it (front c1,a1, back c2,a2)
//     a   = 1 − (1 − a1)(1 − a2)
//     rgb = ((c1 + (1 − a1)·c2) + (c2 + (1 − a2)·c1)) / 2     both orders, averaged
//         = c1·(1 − a2/2) + c2·(1 − a1/2)
//   and average the 4 pairs; the parent is the axis with the largest opacity, and where two or
//   three axes tie exactly, the average of their colours (no axis is preferred).
// Why: a plain average makes a one-voxel wall 2^-k opaque at level k, and the wide diffuse cones
// that read coarse levels see through it. Stacked, a wall keeps a = 1 and its colour at every
// level, empty space stays 0 and a uniform region (L, 1) stays (L, 1). Colour stays opacity-
// weighted: rgb/a is a convex combination of the children's colours rgb_i/a_i (pair weights
// a1(1 − a2/2), a2(1 − a1/2)), so empty children do not darken edges. A lone opaque voxel gets
// a = 1/4 at level 1 (one of four pairs along any axis), 4^-k at level k: the fraction of the
// parent's cross-section it covers.
//
// Summed over the 4 pairs of an axis, c1 + c2 adds up all 8 children whatever the axis, and each
// child i has one partner per axis (i^1 along X, i^2 along Y, i^4 along Z; i = x + 2y + 4z), so
//   axis value = (S − ½·Σ_i c_i·a_partner(i)) / 4,   S = Σ children,
//   its opacity = (S.a − P_axis) / 4,                P_axis = Σ_pairs a1·a2.
// The most opaque axis is the one whose pairs overlap least (smallest P). Only the selected
// (tied) axes' colour is computed: Σ_tied Σ_i c_i·a_partner = Σ_i c_i·B_i with
// B_i = Σ_tied a_partner(i) (8 multiplies, not 3·8). tests/gl/test_mipmap.cpp checks this form
// against the compositing above.
//
// One invocation owns one voxel of the last level it writes and reduces the whole block of level k
// below it (2³, 4³ or 8³ voxels), storing every intermediate voxel on the way. A level k+1 value is
// rounded to the texture format before it feeds level k+2, so the result is the same as one
// dispatch per level. No shared memory and no barrier() (slower on llvmpipe: MipmapPass.cpp).
//
// Defines set by MipmapPass:
//   LIT_MIP_RGBA8         1: RGBA8 volume, reduced in exact integer arithmetic on the bytes
//                         0: RGBA16F volume, reduced in fp32 and rounded to half floats
//   LIT_MIP_PACKED        1: the RGBA8 volume is bound as r32ui (faster loads on llvmpipe)
//   LIT_MIP_LEVELS        most levels one dispatch writes (1..3)
//   LIT_MIP_GROUP_X/Y/Z   work-group size
//   LIT_MIP_FROM_LIST     1: one invocation per entry of level k+1's occupied-parent list
//                         (mip_parents.glsl, indirect dispatch, LIT_MIP_LEVELS 1, groups of
//                         LIT_INJECT_LIST_GROUP_SIZE); the level's other voxels are not written
//                         and stay as cleared (0: all their children are empty, which is what the
//                         whole-grid chain computes for them)
#include "shared.h"
#if LIT_MIP_FROM_LIST
#include "mip_parents.glsl"
#endif

layout(local_size_x = LIT_MIP_GROUP_X, local_size_y = LIT_MIP_GROUP_Y, local_size_z = LIT_MIP_GROUP_Z) in;

#if LIT_MIP_PACKED
#define MIP_FORMAT r32ui
#define MIP_IMAGE uimage3D
#elif LIT_MIP_RGBA8
#define MIP_FORMAT rgba8
#define MIP_IMAGE image3D
#else
#define MIP_FORMAT rgba16f
#define MIP_IMAGE image3D
#endif

layout(binding = LIT_IMG_MIP_SOURCE, MIP_FORMAT) uniform readonly MIP_IMAGE uSource;  // level k
layout(binding = LIT_IMG_MIP_DEST, MIP_FORMAT) uniform writeonly MIP_IMAGE uDest1;    // level k+1
#if LIT_MIP_LEVELS >= 2
layout(binding = LIT_IMG_MIP_DEST2, MIP_FORMAT) uniform writeonly MIP_IMAGE uDest2;   // level k+2
#endif
#if LIT_MIP_LEVELS >= 3
layout(binding = LIT_IMG_MIP_DEST3, MIP_FORMAT) uniform writeonly MIP_IMAGE uDest3;   // level k+3
#endif

// x: edge (voxels) of the last level this dispatch writes, y: how many levels it writes (1..3).
uniform ivec2 uDispatch;
#if LIT_MIP_FROM_LIST
LIT_MIP_PARENT_READER;
#endif

// Children of a block, index i = x + 2y + 4z: i's partner along X is i^1, along Y i^2, along Z i^4.
const ivec3 kChild[8] = ivec3[8](ivec3(0, 0, 0), ivec3(1, 0, 0), ivec3(0, 1, 0), ivec3(1, 1, 0),
                                 ivec3(0, 0, 1), ivec3(1, 0, 1), ivec3(0, 1, 1), ivec3(1, 1, 1));

// TEXEL is one voxel as this shader handles it; reduceBlock(c) the parent of 8 children c[i],
// rounded to the texture's format: the value stored and the one the next level is built from.
#if LIT_MIP_RGBA8
// A texel is its four bytes (r, g, b, a), 0..255: c = byte/255. In bytes (A = alpha byte) the
// parent, for k tied axes, is exactly
//   round((k·510·S − Σ_i C_i·B_i, k·(510·S.a − 2·P)) / (2040·k)),   B_i = Σ_tied A_partner(i)
// (×510 turns the ½ and the /255 of a product of two bytes into integers; every numerator is at
// most 3·1 040 400), computed as (numerator·(6/k) + 6120) / 12240: one constant divisor,
// rounding half up.
#define TEXEL uvec4
#if LIT_MIP_PACKED
#define LOAD(image, p) unpackBytes(imageLoad(image, p).x)
#define STORE(image, p, v) imageStore(image, p, uvec4(packBytes(v), 0u, 0u, 0u))
#else
// rgba8 images hold byte/255 exactly enough that rounding recovers the byte.
#define LOAD(image, p) uvec4(round(imageLoad(image, p) * 255.0))
#define STORE(image, p, v) imageStore(image, p, vec4(v) * (1.0 / 255.0))
#endif
uvec4 unpackBytes(uint v) { return (uvec4(v) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu; }
uint packBytes(uvec4 b) { return b.x | (b.y << 8) | (b.z << 16) | (b.w << 24); }

TEXEL reduceBlock(TEXEL c[8]) {
    uvec4 s = ((c[0] + c[1]) + (c[2] + c[3])) + ((c[4] + c[5]) + (c[6] + c[7]));
    uvec3 overlap = uvec3((c[0].w * c[1].w + c[2].w * c[3].w) + (c[4].w * c[5].w + c[6].w * c[7].w),
                          (c[0].w * c[2].w + c[1].w * c[3].w) + (c[4].w * c[6].w + c[5].w * c[7].w),
                          (c[0].w * c[4].w + c[1].w * c[5].w) + (c[2].w * c[6].w + c[3].w * c[7].w));
    uint least = min(overlap.x, min(overlap.y, overlap.z));
    bvec3 tied = equal(overlap, uvec3(least));
    uint count = uint(tied.x) + uint(tied.y) + uint(tied.z);
    uvec3 cross = uvec3(0u);
    for (int i = 0; i < 8; ++i) {
        uint partners = (tied.x ? c[i ^ 1].w : 0u) + (tied.y ? c[i ^ 2].w : 0u) + (tied.z ? c[i ^ 4].w : 0u);
        cross += c[i].rgb * partners;
    }
    uvec4 numerator = uvec4(count * 510u * s.rgb - cross, count * (510u * s.w - 2u * least));
    uint scale = count == 1u ? 6u : count == 2u ? 3u : 2u;
    // A colour byte can exceed 255 only when its input broke premultiplication (c > a).
    return min((numerator * scale + 6120u) / 12240u, uvec4(255u));
}
#else
// fp32 in an order both this shader and the CPU reference follow; `precise` keeps the compiler
// from fusing or reordering, so the axis choice (exact comparisons) and every rounding match the
// reference. For k tied axes: rgb = (k·S − ½·Σ_i c_i·B_i) / (4k), a = (S.a − P) / 4.
#define TEXEL vec4
#define LOAD(image, p) imageLoad(image, p)
#define STORE(image, p, v) imageStore(image, p, v)

// Rounded to nearest half float here (stored as fp32 instead, llvmpipe's conversion to half came
// out low, as if truncating: RGBA16F levels 4-7 were up to 3 half-float steps too dark).
TEXEL reduceBlock(TEXEL c[8]) {
    precise vec4 s = ((c[0] + c[1]) + (c[2] + c[3])) + ((c[4] + c[5]) + (c[6] + c[7]));
    precise vec3 overlap = vec3((c[0].w * c[1].w + c[2].w * c[3].w) + (c[4].w * c[5].w + c[6].w * c[7].w),
                                (c[0].w * c[2].w + c[1].w * c[3].w) + (c[4].w * c[6].w + c[5].w * c[7].w),
                                (c[0].w * c[4].w + c[1].w * c[5].w) + (c[2].w * c[6].w + c[3].w * c[7].w));
    float least = min(overlap.x, min(overlap.y, overlap.z));
    bvec3 tied = equal(overlap, vec3(least));
    int count = int(tied.x) + int(tied.y) + int(tied.z);
    precise vec3 cross = vec3(0.0);
    for (int i = 0; i < 8; ++i) {
        precise float partners =
            ((tied.x ? c[i ^ 1].w : 0.0) + (tied.y ? c[i ^ 2].w : 0.0)) + (tied.z ? c[i ^ 4].w : 0.0);
        cross += c[i].rgb * partners;
    }
    float scale = count == 1 ? 0.25 : count == 2 ? 0.125 : 0.25 / 3.0;
    precise vec4 v = vec4((float(count) * s.rgb - 0.5 * cross) * scale, (s.w - least) * 0.25);
    return vec4(unpackHalf2x16(packHalf2x16(v.xy)), unpackHalf2x16(packHalf2x16(v.zw)));
}
#endif

// Voxel p of level k+1 from 2×2×2 voxels of level k.
TEXEL reduceOnce(ivec3 p) {
    TEXEL c[8];
    for (int i = 0; i < 8; ++i) c[i] = LOAD(uSource, p * 2 + kChild[i]);
    TEXEL parent = reduceBlock(c);
    STORE(uDest1, p, parent);
    return parent;
}

#if LIT_MIP_LEVELS >= 2
// Voxel p of level k+2 (and its 8 children of level k+1).
TEXEL reduceTwice(ivec3 p) {
    TEXEL c[8];
    for (int i = 0; i < 8; ++i) c[i] = reduceOnce(p * 2 + kChild[i]);
    TEXEL parent = reduceBlock(c);
    STORE(uDest2, p, parent);
    return parent;
}
#endif

#if LIT_MIP_LEVELS >= 3
// Voxel p of level k+3 (and its 8 + 64 descendants of levels k+2, k+1).
void reduceThrice(ivec3 p) {
    TEXEL c[8];
    for (int i = 0; i < 8; ++i) c[i] = reduceTwice(p * 2 + kChild[i]);
    STORE(uDest3, p, reduceBlock(c));
}
#endif

void main() {
#if LIT_MIP_FROM_LIST
    ivec3 parent;
    if (listedParent(parent)) reduceOnce(parent);
    return;
#endif
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, ivec3(uDispatch.x)))) return;
#if LIT_MIP_LEVELS >= 3
    if (uDispatch.y >= 3) {
        reduceThrice(p);
        return;
    }
#endif
#if LIT_MIP_LEVELS >= 2
    if (uDispatch.y == 2) {
        reduceTwice(p);
        return;
    }
#endif
    reduceOnce(p);
}
