// A ray's walk through an n³ voxel grid, voxel by voxel (Amanatides & Woo 1987, "A Fast Voxel
// Traversal Algorithm for Ray Tracing"): the voxel debug views' marches. Coordinates are in voxels,
// the grid spanning [0, n]³; `dir` has no zero component (the caller nudges them).
struct VoxelWalk {
    ivec3 voxel;   // the voxel the ray is in
    int face;      // the axis of the face it entered through (0 X, 1 Y, 2 Z), −1: it started inside
    float t;       // the ray parameter where it entered that voxel
    ivec3 stepDir;
    vec3 tDelta;
    vec3 tMax;     // the ray parameter of the next face along each axis
};

// Starts the walk where the ray enters the grid (or at its origin, inside); false when it misses.
bool beginVoxelWalk(vec3 origin, vec3 dir, int n, out VoxelWalk walk) {
    vec3 inv = 1.0 / dir;
    vec3 t0 = (vec3(0.0) - origin) * inv, t1 = (vec3(float(n)) - origin) * inv;
    vec3 tEnter = min(t0, t1);
    float tNear = max(max(tEnter.x, tEnter.y), tEnter.z);
    float tFar = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
    walk.face = tNear < 0.0 ? -1 : (tNear == tEnter.x ? 0 : (tNear == tEnter.y ? 1 : 2));
    walk.t = max(tNear, 0.0);
    walk.voxel = clamp(ivec3(floor(origin + dir * (walk.t + 1e-4))), ivec3(0), ivec3(n - 1));
    walk.stepDir = ivec3(sign(dir));
    walk.tDelta = abs(inv);
    walk.tMax = (vec3(walk.voxel) + max(sign(dir), 0.0) - origin) * inv;
    return tFar >= max(tNear, 0.0);
}

// Steps into the next voxel; false once the walk has left the grid.
bool stepVoxelWalk(inout VoxelWalk walk, int n) {
    int axis = walk.tMax.x < walk.tMax.y && walk.tMax.x < walk.tMax.z ? 0 : (walk.tMax.y < walk.tMax.z ? 1 : 2);
    walk.t = walk.tMax[axis];
    walk.voxel[axis] += walk.stepDir[axis];
    walk.tMax[axis] += walk.tDelta[axis];
    walk.face = axis;
    return all(greaterThanEqual(walk.voxel, ivec3(0))) && all(lessThan(walk.voxel, ivec3(n)));
}
