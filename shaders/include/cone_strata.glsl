// Stratified diffuse cone sets for the footprint-bounded cones of the accurate mode (docs/GI.md,
// "Stratified cone sets"). Needs cone.glsl.
//
// Why. A footprint-bounded cone reads voxels at most coneFootprintPerHeight × its height above
// the surface wide (traceConeFromSurface): a side cone of the six-cone set is a pencil ~9° wide
// standing for a 72° × 60° sector of the hemisphere, and sees what lies along its axis only.
// With one fixed set the light of a small region depends on where the axes land (the Cornell
// box's red-wall nook got 0.25–0.96 of the reference as the set turned; docs/GI.md,
// "Footprint-bounded cones").
//
// What. The six regions of the hemisphere and their weights stay those of cone.glsl (the cap
// θ < 30°, weight ¼, and five 72° ring sectors 30° < θ < 90°, weight 3/20 each: projected solid
// angles / π). Each region is cut into LIT_CONE_STRATA² cells of equal projected solid angle:
// LIT_CONE_STRATA azimuth strata × LIT_CONE_STRATA strata of sin²θ (uniform in projected solid
// angle, so cosine-weighted). The cone of a region points at the median of one cell (its middle
// in azimuth and in sin²θ). LIT_CONE_STRATA² sets each take a different cell of every region, and
// the sets are laid out as a LIT_CONE_STRATA × LIT_CONE_STRATA pattern over the low-resolution
// trace's texels (stable from frame to frame: a still camera traces the same set in each texel).
// ConeStrataFilterPass averages each texel with its neighbours over exactly one period of the
// pattern, so a flat surface's result is the midpoint rule over LIT_CONE_STRATA² cells per region
// (16 × 6 = 96 directions at LIT_CONE_STRATA 4) for the cost of six cones per traced pixel.
// In a uniform field every cone sees the field whatever its direction, so the furnace stays exact.

const int kConeStrata = LIT_CONE_STRATA;
const int kConeSetCount = LIT_CONE_STRATA * LIT_CONE_STRATA;

// The set a low-resolution texel traces. The 4-periodic coordinates are bit-reversed (0, 2, 1, 3)
// so that a 2 × 2 block of texels holds cells far apart in azimuth and in θ: where the filter
// keeps only part of its window (at a depth or normal edge) the texels left still spread over
// the region.
int coneSetIndex(ivec2 low) {
    ivec2 cell = ivec2(uvec2(low) % uint(kConeStrata));
    if (kConeStrata == 4) cell = ivec2((cell & 1) << 1) | (cell >> 1);
    return cell.x + kConeStrata * cell.y;
}

// The set voxel v traces in a bounce pass (bounce.comp.glsl), `normal` its surface's (averaged)
// normal: the texels' pattern over the two coordinates that run along the surface (the axes other
// than the normal's dominant one), so each 4 × 4 patch of a wall's or floor's voxels holds every
// set once and the mip levels that pixels' cones read average the sets.
int voxelConeSetIndex(ivec3 v, vec3 normal) {
    vec3 a = abs(normal);
    ivec2 along = a.x >= a.y && a.x >= a.z ? v.yz : (a.y >= a.z ? v.xz : v.xy);
    return coneSetIndex(along);
}

// Tangent-space direction (z = normal) of diffuse cone i of set `setIndex` (0 ≤ setIndex < kConeSetCount).
vec3 stratifiedDiffuseConeDirection(int i, int setIndex) {
    float n = float(kConeStrata);
    if (i == 0) {
        // The cap: the disk sinθ < ½ of the cosine-weighted (Malley) projection, cells of equal
        // area: sin²θ ∈ ¼ [p, p + 1) / n, azimuth 2π [a, a + 1) / n, each ring shifted by a fraction
        // of a cell so that the rings' cells do not line up.
        int a = setIndex % kConeStrata, p = setIndex / kConeStrata;
        float sin2 = 0.25 * (float(p) + 0.5) / n;
        float phi = 2.0 * PI * (float(a) + (float(p) + 0.5) / n) / n;
        float s = sqrt(sin2);
        return vec3(s * cos(phi), s * sin(phi), sqrt(1.0 - sin2));
    }
    // Side region i: azimuth within ±36° of the fixed set's axis (72° (i − 1)), sin²θ ∈ [¼, 1).
    // The five side cones of one set take cells (setIndex + (n + 1)(i − 1)) mod n²: different
    // azimuth and θ strata within the set, and over the n² sets every cell of every region once.
    int cell = (setIndex + (kConeStrata + 1) * (i - 1)) % kConeSetCount;
    int a = cell % kConeStrata, p = cell / kConeStrata;
    float sin2 = 0.25 + 0.75 * (float(p) + 0.5) / n;
    float phi = radians(72.0) * (float(i - 1) + (float(a) + 0.5) / n - 0.5);
    float s = sqrt(sin2);
    return vec3(s * cos(phi), s * sin(phi), sqrt(1.0 - sin2));
}

// The radiance C_i of cone i of set `setIndex` (traceDiffuseCone of cone.glsl for the stratified
// sets; the cone subsets of indirect_trace.frag.glsl trace three of them).
vec3 traceStratifiedDiffuseCone(vec3 origin, mat3 basis, int i, int setIndex, float aperture, float maxDistance) {
    vec3 d = stratifiedDiffuseConeDirection(i, setIndex);
    return traceConeFromSurface(origin, basis * d, aperture, maxDistance, kConeNormalOffsetVoxels * voxel.voxelInfo.z,
                                d.z).rgb;
}

// traceDiffuseInFrame (indirect.glsl) with the cones of set `setIndex`: irradiance/π, and each
// region's radiance in cones[] (rough specular blends them by the regions' fixed axes).
vec3 traceDiffuseStratified(vec3 origin, mat3 basis, int setIndex, float aperture, float maxDistance,
                            out vec3 cones[kDiffuseConeCount]) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < kDiffuseConeCount; ++i) {
        cones[i] = traceStratifiedDiffuseCone(origin, basis, i, setIndex, aperture, maxDistance);
        sum += kDiffuseConeWeights[i] * cones[i];
    }
    return sum;
}
