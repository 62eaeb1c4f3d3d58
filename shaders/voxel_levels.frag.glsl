#version 450 core
// The voxel-levels view (VoxelDebugPass::executeLevels): the voxels of every volume running, ray-
// marched from the camera, each drawn as a cube in its level's colour. Volume k (finest first, the
// scene's volume last) is walked voxel by voxel (voxel_walk.glsl) over its own grid, skipping
// the voxels whose centre lies inside volume k − 1 (a finer level holds that space); the nearest
// hit of all the volumes is shown. A face is shaded by the axis it faces, and a darker line marks
// its voxel's edges, so the voxel size of each level reads off the image.
#include "frame.glsl"
#include "voxel_walk.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outColor;

const int kMaxVolumes = LIT_MAX_NEAR_LEVELS + 1;
// Each volume's radiance (its alpha marks the occupied voxels).
layout(binding = LIT_TEX_DEBUG_LEVELS_FIRST) uniform sampler3D uRadiance[kMaxVolumes];

uniform int uVolumeCount;
uniform vec4 uVolume[kMaxVolumes];  // xyz world minimum corner (m), w voxel size (m)
uniform int uResolution[kMaxVolumes];
uniform vec3 uColor[kMaxVolumes];

// Empty voxels (alpha below this) are skipped, as in the voxel view.
const float kOccupied = 1.0 / 255.0;
// The edge line's width, in voxels.
const float kEdge = 0.06;

bool insideVolume(int k, vec3 world) {
    vec3 local = (world - uVolume[k].xyz) / (uVolume[k].w * float(uResolution[k]));
    return all(greaterThanEqual(local, vec3(0.0))) && all(lessThan(local, vec3(1.0)));
}

// The first occupied voxel of volume k along the ray, outside volume k − 1: the distance to it
// (m; a negative value when none) and its shaded colour.
float march(int k, vec3 originWorld, vec3 dir, out vec3 color) {
    color = vec3(0.0);
    int n = uResolution[k];
    float voxelSize = uVolume[k].w;
    vec3 origin = (originWorld - uVolume[k].xyz) / voxelSize;  // voxel units: the grid is [0, n]³
    VoxelWalk walk;
    if (!beginVoxelWalk(origin, dir, n, walk)) return -1.0;
    const vec3 faceShade = vec3(0.8, 1.0, 0.9);  // faces across X, Y, Z
    for (int i = 0; i < 3 * n; ++i) {
        bool finer = k > 0 && insideVolume(k - 1, uVolume[k].xyz + (vec3(walk.voxel) + 0.5) * voxelSize);
        if (!finer && texelFetch(uRadiance[k], walk.voxel, 0).a >= kOccupied) {
            color = uColor[k];
            if (walk.face >= 0) {
                color *= faceShade[walk.face];
                // Where on the face the ray hit, in voxels: dark near its edges.
                vec3 inVoxel = fract(origin + dir * walk.t);
                vec2 across = walk.face == 0 ? inVoxel.yz : (walk.face == 1 ? inVoxel.xz : inVoxel.xy);
                if (any(lessThan(min(across, 1.0 - across), vec2(kEdge)))) color *= 0.55;
            }
            return walk.t * voxelSize;
        }
        if (!stepVoxelWalk(walk, n)) break;
    }
    return -1.0;
}

void main() {
    vec4 nearH = frame.inverseViewProjection * vec4(vUv * 2.0 - 1.0, -1.0, 1.0);
    vec4 farH = frame.inverseViewProjection * vec4(vUv * 2.0 - 1.0, 1.0, 1.0);
    vec3 origin = nearH.xyz / nearH.w;
    vec3 dir = normalize(farH.xyz / farH.w - origin);
    dir = mix(dir, vec3(1e-7), lessThan(abs(dir), vec3(1e-7)));
    vec3 shown = vec3(0.0);
    float nearest = 1e30;
    for (int k = 0; k < kMaxVolumes; ++k) {
        if (k >= uVolumeCount) break;
        vec3 color;
        float distance = march(k, origin, dir, color);
        if (distance >= 0.0 && distance < nearest) {
            nearest = distance;
            shown = color;
        }
    }
    outColor = vec4(shown, 1.0);
}
