#version 450 core
// Voxelization, geometry stage: projects each triangle orthographically along its dominant axis
// (the largest |component| of its normal, so the projection has the largest area and every
// voxel column the triangle crosses is sampled) and enlarges it for conservative rasterization.
//
// Conservative rasterization after Hasselgren, Akenine-Möller & Ohlsson 2005, "Conservative
// Rasterization", GPU Gems 2 ch. 42: every edge is moved outwards by the half-diagonal of a
// pixel (the support of the pixel square along the edge normal), the new vertices are the
// intersections of adjacent moved edges, and the fragment shader discards what lies outside
// the triangle's bounding box grown by half a pixel (the enlarged triangle overshoots at acute
// corners). A thin wall then covers every voxel column it touches, not only those whose centre
// it covers, so cone tracing sees no holes.
//
// Space: "voxel space" is the volume in voxel units, [0, N]³; one pixel of the N×N viewport is
// one voxel column, window depth × N is the coordinate along the projection axis.
#include "voxel.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VoxelVertex {
    vec3 worldPosition;
    vec3 worldNormal;
    vec4 uv;
} gs_in[];

out VoxelFragment {
    vec3 worldNormal;
    vec4 uv;
    flat vec4 bounds;  // enlarged 2D bounding box in window pixels: xy min, zw max
    flat int axis;     // projection axis: 0 X, 1 Y, 2 Z
    // The triangle in voxel space, swizzled for `axis` as (u, v, depth): the fragment shader records
    // the point of it nearest the voxel column's centre (the surface volume).
    flat vec3 corner0, corner1, corner2;
} gs_out;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Extra enlargement (pixels) beyond the half pixel, on the edges and the bounding box: a row or
// column that a triangle only touches (its edge lies exactly on the face between two voxels, as
// the Cornell box's block sides' top edges do at 64³) sits on the enlarged edge itself, and whether
// the rasterizer covers it then depends on sub-pixel snapping. Without the margin such rows are
// written or skipped by the grid's alignment (ceiling and back wall 1.03-1.14 of the reference over
// grid offsets, 1.03-1.08 with it: docs/GI.md, "Surfaces on voxel faces"). 10⁻³ pixel
// is below llvmpipe's snapping (8 sub-pixel bits, 1/256 pixel) and changed nothing; 0.01 is above.
const float kTouchMargin = 0.01;

// Voxel-space point → (u, v, depth) of the projection along `axis`; voxelize.frag.glsl undoes it.
vec3 swizzleForAxis(vec3 p, int axis) {
    if (axis == 0) return p.yzx;
    if (axis == 1) return p.zxy;
    return p;
}

void main() {
    float n = voxel.voxelInfo.x;
    vec3 p[3];
    for (int i = 0; i < 3; ++i) p[i] = worldToVolume(gs_in[i].worldPosition) * n;
    vec3 faceNormal = abs(cross(p[1] - p[0], p[2] - p[0]));
    int axis = (faceNormal.x >= faceNormal.y && faceNormal.x >= faceNormal.z) ? 0 : (faceNormal.y >= faceNormal.z ? 1 : 2);
    vec3 s[3];
    for (int i = 0; i < 3; ++i) s[i] = swizzleForAxis(p[i], axis);

    // Twice the signed projected area (voxels²). Along the dominant axis it is at least 1/√3 of
    // the true area, so only degenerate triangles come near zero.
    float area = cross2(s[1].xy - s[0].xy, s[2].xy - s[0].xy);
    if (abs(area) < 1e-8) return;

    // Edge i runs from vertex i to i+1, as a homogeneous 2D line: dot(e, (x, y, 1)) = 0 on the
    // edge, > 0 inside (the sign of `area` makes that hold for either winding).
    vec3 edge[3];
    float orientation = sign(area);
    for (int i = 0; i < 3; ++i) {
        edge[i] = cross(vec3(s[i].xy, 1.0), vec3(s[(i + 1) % 3].xy, 1.0)) * orientation;
        // Move outwards by the pixel half-diagonal, (0.5, 0.5) · |edge normal|, and the margin.
        edge[i].z += (0.5 + kTouchMargin) * (abs(edge[i].x) + abs(edge[i].y));
    }

    vec2 lo = min(s[0].xy, min(s[1].xy, s[2].xy));
    vec2 hi = max(s[0].xy, max(s[1].xy, s[2].xy));
    vec4 bounds = vec4(lo - (0.5 + kTouchMargin), hi + (0.5 + kTouchMargin));

    for (int i = 0; i < 3; ++i) {
        // The enlarged vertex i is where the moved edges i-1 and i meet.
        vec3 h = cross(edge[(i + 2) % 3], edge[i]);
        vec2 q = abs(h.z) > 1e-12 ? h.xy / h.z : s[i].xy;
        // Barycentric coordinates of q in the original triangle extrapolate depth (the
        // triangle's plane) and the attributes to the enlarged vertex.
        float b1 = cross2(q - s[0].xy, s[2].xy - s[0].xy) / area;
        float b2 = cross2(s[1].xy - s[0].xy, q - s[0].xy) / area;
        float b0 = 1.0 - b1 - b2;
        float depth = b0 * s[0].z + b1 * s[1].z + b2 * s[2].z;
        gs_out.worldNormal = b0 * gs_in[0].worldNormal + b1 * gs_in[1].worldNormal + b2 * gs_in[2].worldNormal;
        gs_out.uv = b0 * gs_in[0].uv + b1 * gs_in[1].uv + b2 * gs_in[2].uv;
        gs_out.bounds = bounds;
        gs_out.axis = axis;
        gs_out.corner0 = s[0];
        gs_out.corner1 = s[1];
        gs_out.corner2 = s[2];
        // Orthographic: voxel units [0, N] → NDC [-1, 1]; window depth = depth / N.
        gl_Position = vec4(vec3(q, depth) / n * 2.0 - 1.0, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
