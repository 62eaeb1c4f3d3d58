#version 450 core
// Voxel debug views (VoxelDebugPass): one slice of the volume, or the volume ray-marched voxel by
// voxel, at mip level uMip, showing channel uChannel as display values in [0,1].
#include "frame.glsl"
#include "tonemap.glsl"
#include "voxel.glsl"
#include "voxel_walk.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outColor;

// The radiance volume (radiance, opacity) or the decoded channel volume (albedo, normal,
// emission); both hold rgb premultiplied by a (opacity or occupancy).
layout(binding = LIT_TEX_DEBUG_INPUT) uniform sampler3D source;

uniform int uSlice;       // 1: slice view, 0: 3D view
uniform int uChannel;     // LIT_VOXEL_CHANNEL_*
uniform int uMip;         // mip level shown (already clamped to the volume's levels)
uniform int uAxis;        // slice view: 0 X, 1 Y, 2 Z
uniform int uSliceIndex;  // slice view: slice along uAxis at level uMip

// Empty voxels (a below this) are skipped by the 3D view.
const float kOccupied = 1.0 / 255.0;

vec3 display(vec4 v) {
    if (uChannel == LIT_VOXEL_CHANNEL_OPACITY) return vec3(clamp(v.a, 0.0, 1.0));
    if (v.a <= 0.0) return vec3(0.0);
    vec3 value = v.rgb / v.a;
    if (uChannel == LIT_VOXEL_CHANNEL_RADIANCE) return acesFilmic(max(decodeRadiance(value), 0.0) * frame.exposure.x);
    if (uChannel == LIT_VOXEL_CHANNEL_EMISSION) return acesFilmic(max(value, 0.0) * frame.exposure.x);
    if (uChannel == LIT_VOXEL_CHANNEL_NORMAL) return clamp(value * 0.5 + 0.5, 0.0, 1.0);
    return clamp(value, 0.0, 1.0);  // albedo
}

// The slice seen from the positive side of its axis: Z slices with X right and Y up, X slices
// with −Z right and Y up, Y slices with X right and −Z up. Square, letterboxed into the viewport.
vec3 sliceView(int n) {
    vec2 size = frame.viewport.xy;
    float side = min(size.x, size.y);
    vec2 uv = (gl_FragCoord.xy - 0.5 * (size - side)) / side;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return vec3(0.0);
    vec2 cell = uv * float(n);
    ivec2 ij = clamp(ivec2(floor(cell)), ivec2(0), ivec2(n - 1));
    ivec3 v = uAxis == 0   ? ivec3(uSliceIndex, ij.y, n - 1 - ij.x)
              : uAxis == 1 ? ivec3(ij.x, uSliceIndex, n - 1 - ij.y)
                           : ivec3(ij.x, ij.y, uSliceIndex);
    vec3 color = display(texelFetch(source, v, uMip));
    // A one-pixel grid on each voxel's lower edges once voxels are large enough to keep some
    // colour between the lines.
    float pixelsPerVoxel = side / float(n);
    if (pixelsPerVoxel >= 4.0 && any(lessThan(fract(cell) * pixelsPerVoxel, vec2(1.0))))
        color = mix(color, vec3(0.5), 0.5);
    return color;
}

// Walks the camera ray through the level's voxel grid (voxel_walk.glsl) and shows the first
// occupied voxel as a cube: the face it was entered through is shaded by its axis so neighbouring
// cubes read apart.
vec3 volumeView(int n) {
    vec4 nearH = frame.inverseViewProjection * vec4(vUv * 2.0 - 1.0, -1.0, 1.0);
    vec4 farH = frame.inverseViewProjection * vec4(vUv * 2.0 - 1.0, 1.0, 1.0);
    vec3 originWorld = nearH.xyz / nearH.w;
    // In voxel units of this level: the grid is [0, n]³.
    vec3 origin = worldToVolume(originWorld) * float(n);
    vec3 dir = normalize(farH.xyz / farH.w - originWorld);
    dir = mix(dir, vec3(1e-7), lessThan(abs(dir), vec3(1e-7)));
    VoxelWalk walk;
    if (!beginVoxelWalk(origin, dir, n, walk)) return vec3(0.0);
    const vec3 faceShade = vec3(0.8, 1.0, 0.9);  // faces across X, Y, Z
    for (int i = 0; i < 3 * n; ++i) {
        vec4 value = texelFetch(source, walk.voxel, uMip);
        if (value.a >= kOccupied) return display(value) * (walk.face < 0 ? 1.0 : faceShade[walk.face]);
        if (!stepVoxelWalk(walk, n)) break;
    }
    return vec3(0.0);
}

void main() {
    int n = max(int(voxel.voxelInfo.x) >> uMip, 1);
    outColor = vec4(uSlice != 0 ? sliceView(n) : volumeView(n), 1.0);
}
