// Voxel cone tracing through the radiance volume (Crassin et al. 2011, "Interactive Indirect
// Illumination Using Voxel Cone Tracing", Computer Graphics Forum 30(7)). docs/GI.md explains the
// whole pipeline; this file holds the marching loop, the diffuse cone table and the specular
// importance sampling.
//
// The radiance volume (VoxelVolume.h) holds, per voxel and mip level, opacity a (0..1) and
// opacity-PREMULTIPLIED outgoing radiance rgb = a·L. Level 0 voxels are either opaque (a = 1,
// rgb = L) or empty (0), so premultiplied and straight colour agree there; every mip level (the
// isotropic stacked chain and the six directional chains, mipmap*.comp.glsl) is a weighted mean of
// premultiplied children, and trilinear filtering is a plain weighted average too, so every
// filtered sample stays premultiplied and rgb / a is its straight colour. (A straight-
// colour mip chain cannot be filtered correctly: trilinear mixing with empty texels would darken
// it, and dividing it by a filtered opacity below 1 would brighten it by 1/a.)
#include "voxel.glsl"
#include "brdf.glsl"
#include "sky.glsl"

// Compile-time cone features (renderer/passes/ConeProgram.h builds one program per combination):
// llvmpipe executes both sides of a branch, even a uniform one, so a runtime switch would make
// every cone pay for the directional lookups and the footprint bound whether they are on or not.
//   LIT_CONE_ANISOTROPIC 1: levels ≥ 1 read the six directional volumes (GiSettings::anisotropicVoxels())
//   LIT_CONE_FOOTPRINT   1: diffuse cones are footprint-bounded (GiSettings::coneFootprintPerHeight > 0)
#ifndef LIT_CONE_ANISOTROPIC
#define LIT_CONE_ANISOTROPIC 0
#endif
#ifndef LIT_CONE_FOOTPRINT
#define LIT_CONE_FOOTPRINT 0
#endif

layout(binding = LIT_TEX_VOXEL_RADIANCE) uniform sampler3D voxelRadianceTexture;
#if LIT_CONE_ANISOTROPIC
// Anisotropic levels ≥ 1, one volume per axis (VoxelVolume::directional): the +axis face at
// x ∈ [0, ⅓), an empty gap, the −axis face at x ∈ [⅔, 1).
layout(binding = LIT_TEX_VOXEL_DIRECTIONAL_FIRST + 0) uniform sampler3D voxelDirectionalX;
layout(binding = LIT_TEX_VOXEL_DIRECTIONAL_FIRST + 1) uniform sampler3D voxelDirectionalY;
layout(binding = LIT_TEX_VOXEL_DIRECTIONAL_FIRST + 2) uniform sampler3D voxelDirectionalZ;

// Texture coordinate x of volume coordinate x in the region of the face at `faceOffset` (0 for
// +axis, 2 for −axis). Clamped to [−½, 3/2]: beyond the volume a sample reads the gap or the
// border (both empty, as outside the volume), never the other face (the march goes one sampled
// voxel past the volume's face, and the gap is only one texel wide at the coarsest level).
float faceX(float x, float faceOffset) {
    return (clamp(x, -0.5, 1.5) + faceOffset) * (1.0 / 3.0);
}
#endif

// A cone stops once it is this opaque: the rest (≤ 5 % of its transmittance) would change the
// result by less than the filtering error and costs as many steps again.
const float kConeStopOpacity = 0.95;
// Samples below this opacity are empty space (a 16F/8-bit zero after filtering).
const float kConeMinOpacity = 1.0 / 1024.0;
// Upper bound on the steps of one cone, so a bad uniform (zero voxel size) cannot hang the GPU.
// The shortest step is half a voxel: 2·512·√3 ≈ 1774 steps cross the largest (512³) volume.
const int kConeMaxSteps = 1800;

// Start of every cone, to keep it out of the voxels of its own surface (self-occlusion):
//  - the origin moves along the surface normal by √3 voxels, the diagonal of one voxel, so the
//    voxel that holds the surface (whose centre may be up to √3/2 voxel away in any direction)
//    and its trilinear footprint (one more voxel) lie behind the first sample;
//  - the march starts one voxel along the cone axis (t = voxelSize), and its first sample is
//    the middle of the first step, so it lies 2.4 (side cones) to 3 (normal cone) voxels off the
//    surface.
// The price is that occluders closer than that to a surface are missed (contact shadows are left
// to direct lighting) and light may leak through walls thinner than that (docs/GI.md, "Marching a
// cone").
const float kConeNormalOffsetVoxels = LIT_CONE_NORMAL_OFFSET_VOXELS;
const float kConeStartVoxels = 1.0;

vec3 coneOrigin(vec3 position, vec3 normal) {
    return position + normal * (kConeNormalOffsetVoxels * voxel.voxelInfo.z);
}

// The ray uvw(t) = uvwOrigin + t · uvwPerMetre inside the unit cube [0,1]³ of the volume:
// t ∈ [span.x, span.y] (an empty span, x > y, when it misses). Slab test; an axis the ray runs
// parallel to gets a huge but finite slope, so no division by zero.
vec2 volumeSpan(vec3 uvwOrigin, vec3 uvwPerMetre) {
    vec3 slope = mix(vec3(1e-20), uvwPerMetre, greaterThan(abs(uvwPerMetre), vec3(1e-20)));
    vec3 t0 = -uvwOrigin / slope;
    vec3 t1 = (vec3(1.0) - uvwOrigin) / slope;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    return vec2(max(max(tNear.x, tNear.y), tNear.z), min(min(tFar.x, tFar.y), tFar.z));
}

// Front-to-back marching of one cone through the mipmapped radiance volume.
//   origin       world position (m) where the cone's apex is (use coneOrigin)
//   direction    unit world direction of the axis
//   aperture     full apex angle (rad)
//   maxDistance  world distance (m) after which the cone stops
// Returns rgb: radiance arriving along the cone (W/(sr·m²)), averaged over its solid angle;
// a: how much of the cone was blocked (0 open, 1 occluded). Space outside the volume is empty;
// what is left of the cone when it leaves the volume or reaches maxDistance sees the sky.
//
// At distance t the cone is d = max(voxelSize, 2·t·tan(aperture/2)) wide and is sampled with one
// trilinear lookup at mip level log2(d / voxelSize), whose voxels are d wide. Steps are
// max(stepScale·d, voxelSize/2) long. Opacity is corrected for the step length: a voxel of size
// s with opacity a blocks a ray through it with probability a, so a step of length Δ through it
// blocks 1 − (1 − a)^(Δ/s). Without the correction a step scale of 0.25 would sample every voxel
// twice as often as 0.5 and make the same wall twice as opaque; with it the result depends on the
// step scale only through sampling error.
//
// Per step the loop does one texture fetch and a little scalar math; what can be done once per
// cone is hoisted out of it (measured on llvmpipe, where every instruction runs on the CPU; see
// docs/PERFORMANCE.md, "llvmpipe"): the volume is clipped against the ray once (volumeSpan) instead of
// testing each sample's coordinates, sample coordinates step linearly in volume space, and the
// sampled level's voxel size is the cone diameter itself (clamped to the coarsest level) rather
// than exp2 of the log2 that chose the level.
// Transmittance below which a face counts as opaque when faces are combined (log2 of 0 is −∞).
const float kFaceMinTransmittance = 1.0 / 4096.0;
// Opacity correction exponent per sampled voxel width. Trilinear filtering spreads an opaque
// voxel's opacity over a tent two voxels wide (a(x) = 1 − |x|), and the optical depth of that tent,
// ∫ −ln(1 − a(x)) dx = 2 voxel widths, lets e^−2 = 13.5 % of a cone through a wall one voxel thick
// (more when the steps miss the peak), so light leaks out of closed rooms. Counting each sampled
// width k times lets e^−2k through. Partially covered voxels (a surface seen edge-on) block more
// than their coverage; uniform opaque fields are unchanged (the furnace stays exact).
// The fast mode (no cone feature on) keeps k = 1 and ends the march at the volume's face: with
// isotropic coarse voxels a larger k makes the side cones' self-occlusion by their own surface's
// voxels worse. Footprint-bounded cones (the accurate and cached modes) take k = 2: with the
// stratified cone sets (cone_strata.glsl) integrating the hemisphere, k = 3 over-reads the Cornell
// ceiling by 21 % at 64³; directional voxels with unbounded cones take 3. docs/GI.md, "Marching a
// cone" (k per sampled voxel width).
#if LIT_CONE_FOOTPRINT
const float kOpacityPerVoxel = 2.0;
const float kPastFaceVoxels = 1.0;  // sampled voxels marched past the volume's face (below)
#elif LIT_CONE_ANISOTROPIC
const float kOpacityPerVoxel = 3.0;
const float kPastFaceVoxels = 1.0;
#else
const float kOpacityPerVoxel = 1.0;
const float kPastFaceVoxels = 0.0;
#endif

// One sample of the radiance volume at texture coordinate uvw and (fractional) mip level `level`
// for a cone travelling along `direction`. Isotropic volume (LIT_CONE_ANISOTROPIC 0): one
// trilinear lookup. Anisotropic (Crassin et al. 2011, section 5.1): levels ≥ 1 come from the three
// directional volumes whose faces the cone looks through, blended with weights direction²
// (they sum to 1); below level 1 that blend is mixed with the isotropic level 0.
// `faceWeights` = direction², `faceOffsets` = 2 where direction < 0, else 0 (per cone, hoisted out
// of the loop): each axis's face is picked by a coordinate offset in its volume, not by a branch
// (llvmpipe runs both sides of a branch: two texture reads per axis; measured 1.5× the trace).
vec4 sampleRadiance(vec3 uvw, float level, vec3 faceWeights, vec3 faceOffsets) {
#if !LIT_CONE_ANISOTROPIC
    return textureLod(voxelRadianceTexture, uvw, level);
#else
    float faceLevel = max(level - 1.0, 0.0);
    vec4 x = textureLod(voxelDirectionalX, vec3(faceX(uvw.x, faceOffsets.x), uvw.yz), faceLevel);
    vec4 y = textureLod(voxelDirectionalY, vec3(faceX(uvw.x, faceOffsets.y), uvw.yz), faceLevel);
    vec4 z = textureLod(voxelDirectionalZ, vec3(faceX(uvw.x, faceOffsets.z), uvw.yz), faceLevel);
    // Opacity: the three faces' transmittances combined as a weighted geometric mean (their optical
    // depths averaged), not their opacities averaged: a wall met at 45° is opaque face-on and
    // nearly transparent edge-on, and the plain average (½) let half of every oblique cone through
    // it (a closed box's cones lost 30 % of their light; leaks). Colour: the faces' straight colours
    // averaged by weight × opacity, premultiplied by the combined opacity. Both reduce to the face
    // value when the faces agree (the furnace stays exact).
    vec3 opacities = vec3(x.a, y.a, z.a);
    float weightedOpacity = dot(faceWeights, opacities);
    float opacity = 1.0 - exp2(dot(faceWeights, log2(max(vec3(1.0) - opacities, vec3(kFaceMinTransmittance)))));
    vec3 rgb = faceWeights.x * x.rgb + faceWeights.y * y.rgb + faceWeights.z * z.rgb;
    return weightedOpacity > 0.0 ? vec4(rgb * (opacity / weightedOpacity), opacity) : vec4(0.0);
#endif
}

#if LIT_CONE_ANISOTROPIC
// A sample below level 1 (level ∈ [0, 1)): the directional blend of level 1 mixed with the isotropic
// level 0. The march reads it only while its samples are finer than level 1 (the first of
// traceConeFromSurface's two loops): llvmpipe runs both sides of a branch, so a `level < 1` test
// inside sampleRadiance made every sample pay for this fourth lookup (docs/GI.md, "Anisotropic
// voxels").
vec4 sampleRadianceBelowLevel1(vec3 uvw, float level, vec3 faceWeights, vec3 faceOffsets) {
    return mix(textureLod(voxelRadianceTexture, uvw, 0.0), sampleRadiance(uvw, level, faceWeights, faceOffsets), level);
}
#endif

// traceCone for a cone that leaves a surface: `startHeight` (m) is the apex's height above the
// surface and `heightPerDistance` = n·direction how fast the axis rises above it. The voxels a
// sample reads are at most giParams.x × (its height above the surface) wide (0 = no bound):
// a wide cone near its surface would otherwise read coarse voxels that hold the surface itself,
// and a lit surface would light itself, an unlit one hide its surroundings behind its own dark
// voxels (self-illumination; docs/GI.md, "Footprint-bounded cones"). Steps shrink with the
// sampled width, so a bounded cone takes more, narrower samples near the surface.
vec4 traceConeFromSurface(vec3 origin, vec3 direction, float aperture, float maxDistance, float startHeight,
                          float heightPerDistance) {
    float voxelSize = voxel.voxelInfo.z;
    float maxLevel = voxel.voxelInfo.w - 1.0;
    float maxLevelVoxelSize = voxelSize * exp2(maxLevel);
    float stepScale = voxel.traceParams.z;
    float widthPerDistance = 2.0 * tan(0.5 * clamp(aperture, 0.0, LIT_CONE_APERTURE_MAX));
#if LIT_CONE_FOOTPRINT
    float footprintPerHeight = voxel.giParams.x > 0.0 ? voxel.giParams.x : 1e30;
#endif
    vec3 faceWeights = direction * direction;
    vec3 faceOffsets = 2.0 * vec3(lessThan(direction, vec3(0.0)));
    // Samples at tMid in [span.x, span.y] lie inside the volume; the first one outside ends the
    // march (space outside the volume is empty and black).
    vec3 uvwOrigin = worldToVolume(origin);
    vec3 uvwPerMetre = direction / voxel.volumeMin.w;
    vec2 span = volumeSpan(uvwOrigin, uvwPerMetre);
    vec3 radiance = vec3(0.0);
    float opacity = 0.0;
    float t = kConeStartVoxels * voxelSize;
    int i = 0;
    // One step [t, t + Δ] of the march, as two macros so that the anisotropic variant can run it in
    // two loops (samples below level 1, then from level 1 on) with different sample functions and no
    // branch between them. Each step is sampled at its middle (midpoint rule): the cone widens along
    // the step, and sampling its start would use a footprint too fine for the rest of it and
    // overestimate the opacity of thin layers by up to 2× at step scale 1. Level log2(d / voxelSize)
    // has voxels d wide (clamped to the coarsest level).
#if LIT_CONE_FOOTPRINT
#define LIT_CONE_STEP_GEOMETRY                                                                                \
    float bound = footprintPerHeight * (startHeight + heightPerDistance * t);                                \
    float stepLength = max(stepScale * max(voxelSize, min(widthPerDistance * t, bound)), 0.5 * voxelSize);   \
    float tMid = t + 0.5 * stepLength;                                                                       \
    float diameter = max(voxelSize, min(widthPerDistance * tMid,                                             \
                                        footprintPerHeight * (startHeight + heightPerDistance * tMid)));     \
    float levelVoxelSize = min(diameter, maxLevelVoxelSize);
#else
#define LIT_CONE_STEP_GEOMETRY                                                                     \
    float stepLength = max(stepScale * max(voxelSize, widthPerDistance * t), 0.5 * voxelSize);    \
    float tMid = t + 0.5 * stepLength;                                                             \
    float diameter = max(voxelSize, widthPerDistance * tMid);                                      \
    float levelVoxelSize = min(diameter, maxLevelVoxelSize);
#endif
    // The march goes on one sampled voxel past the volume's face (accurate mode): trilinear filtering
    // spreads a surface on the face over a voxel on either side, and a cone stopped at the face would
    // see only half of its opacity (a closed room whose walls are the volume's faces lost 45 % of its
    // bounce light). Straight colour = rgb / a of the premultiplied sample, weighted by the corrected
    // opacity. Once the cone is opaque, the last ≤ 5 % of it would see more of what it has been seeing
    // (its radiance averaged by opacity), not black: counted so, which keeps a closed room's cones
    // unbiased and makes the furnace exact for any opacity.
#define LIT_CONE_STEP_SAMPLE(SAMPLE)                                                                            \
    if (tMid < span.x || tMid > span.y + kPastFaceVoxels * levelVoxelSize) break;                               \
    vec4 s = SAMPLE(uvwOrigin + tMid * uvwPerMetre, log2(levelVoxelSize / voxelSize), faceWeights, faceOffsets); \
    if (s.a > kConeMinOpacity) {                                                                                \
        float a = 1.0 - pow(max(1.0 - s.a, 0.0), kOpacityPerVoxel * stepLength / levelVoxelSize);               \
        radiance += (1.0 - opacity) * (a / s.a) * decodeRadiance(s.rgb);                                        \
        opacity += (1.0 - opacity) * a;                                                                         \
        if (opacity >= kConeStopOpacity) return vec4(radiance / opacity, 1.0);                                  \
    }                                                                                                           \
    t += stepLength;
#if LIT_CONE_ANISOTROPIC
    // Samples finer than level 1 blend in the isotropic level 0. The sampled width only grows along
    // the march (t and the height above the surface both grow), so once a step reaches level 1
    // every later one does: the second loop reads the three directional volumes only.
    for (; i < kConeMaxSteps && t <= maxDistance; ++i) {
        LIT_CONE_STEP_GEOMETRY
        if (levelVoxelSize >= 2.0 * voxelSize) break;
        LIT_CONE_STEP_SAMPLE(sampleRadianceBelowLevel1)
    }
#endif
    for (; i < kConeMaxSteps && t <= maxDistance; ++i) {
        LIT_CONE_STEP_GEOMETRY
        LIT_CONE_STEP_SAMPLE(sampleRadiance)
    }
#undef LIT_CONE_STEP_GEOMETRY
#undef LIT_CONE_STEP_SAMPLE
    // Left the volume or reached maxDistance: the unblocked rest of the cone sees the sky (sky.glsl).
    return vec4(radiance + (1.0 - opacity) * skyConeRadiance(direction, aperture), opacity);
}

vec4 traceCone(vec3 origin, vec3 direction, float aperture, float maxDistance) {
    return traceConeFromSurface(origin, direction, aperture, maxDistance, 1e30, 1.0);
}

// An orthonormal basis (t, b, n) around a unit normal, continuous except at n.z = −1
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1), listing 3).
mat3 tangentFrame(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

// ---- Indirect diffuse: six cones -----------------------------------------------------------
// Layout: one cone along the normal and five around it at 60° from the normal, 72° apart in
// azimuth, each 60° wide. This is the six-cone layout used by many VXGI renderers after Crassin
// et al. 2011, e.g. jose-villegas/VCTRenderer (engine/assets/shaders/light_pass.frag, which has
// the same directions with the axes permuted and the weights π/4, 3π/20).
//
// Weights: the irradiance E = ∫_hemisphere L(ω) cosθ dω is split into six regions, and each cone
// estimates the mean radiance C_i of its region, so E ≈ Σ C_i · W_i with W_i = ∫_region cosθ dω
// (the region's projected solid angle). The normal cone owns the cap θ < 30° (its own half
// aperture): W_0 = 2π ∫_0^{30°} cosθ sinθ dθ = π sin²30° = π/4. The five side cones share the ring
// 30° < θ < 90° (the side cones' axes at 60° sit in its middle): W_i = (π − π/4) / 5 = 3π/20.
// Σ W_i = π exactly, so in a uniform field L (every C_i = L) E = π·L and
//   L_ID = albedo_d/π · E = albedo_d · L   (the furnace test, tests/gl/test_cone_trace.cpp).
// In the "w_i·(n·c_i)" form the same weights are w_0 = π/4 and w_i = (3π/20)/cos60° = 3π/10.
// The table stores W_i / π, so L_ID = albedo_d · Σ kDiffuseConeWeights[i] · C_i.
// The regions stay fixed when the user changes the aperture (traceParams.w): a wider or narrower
// cone only blurs or sharpens each estimate, and the furnace still holds.
// The table lives in shared.h so that C++ (the cone-direction debug view) draws the same cones.
// Tangent space: x, y along the surface, z along the normal; azimuths 0°, 72°, ... 288°.
const int kDiffuseConeCount = LIT_DIFFUSE_CONE_COUNT;
const vec3 kDiffuseConeDirections[kDiffuseConeCount] = vec3[](LIT_DIFFUSE_CONE_DIRECTIONS);
const float kDiffuseConeWeights[kDiffuseConeCount] = float[](LIT_DIFFUSE_CONE_WEIGHTS);

// Irradiance / π at a surface point: Σ W_i/π · C_i, so that L_ID = albedo_d · traceDiffuse(...).
// `origin` from coneOrigin(), `n` the unit surface normal.
// `cones` receives each cone's C_i, for rough specular to reuse (radianceFromDiffuseCones).
// Diffuse cone i of the set in the tangent frame `basis` (its z = the normal), from an apex
// coneOrigin() puts kConeNormalOffsetVoxels voxels above the surface: footprint-bounded.
vec3 traceDiffuseCone(vec3 origin, mat3 basis, int i, float aperture, float maxDistance) {
    return traceConeFromSurface(origin, basis * kDiffuseConeDirections[i], aperture, maxDistance,
                                kConeNormalOffsetVoxels * voxel.voxelInfo.z, kDiffuseConeDirections[i].z).rgb;
}

vec3 traceDiffuse(vec3 origin, vec3 n, float aperture, float maxDistance, out vec3 cones[kDiffuseConeCount]) {
    mat3 basis = tangentFrame(n);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < kDiffuseConeCount; ++i) {
        cones[i] = traceDiffuseCone(origin, basis, i, aperture, maxDistance);
        sum += kDiffuseConeWeights[i] * cones[i];
    }
    return sum;
}

vec3 traceDiffuse(vec3 origin, vec3 n, float aperture, float maxDistance) {
    vec3 cones[kDiffuseConeCount];
    return traceDiffuse(origin, n, aperture, maxDistance, cones);
}

// Radiance arriving from unit direction l (tangent space of the diffuse cones, above the surface)
// estimated from the six diffuse cones' C_i: a blend of the cones whose axes lie within 60° of l,
// weighted by (cos∠(l, axis) − ½)². Some axis is always within 46° of a direction above the
// surface, so the weights never all vanish; a uniform field gives exactly its radiance.
vec3 radianceFromDiffuseCones(vec3 l, vec3 cones[kDiffuseConeCount]) {
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int i = 0; i < kDiffuseConeCount; ++i) {
        float w = max(dot(l, kDiffuseConeDirections[i]) - 0.5, 0.0);
        sum += (w * w) * cones[i];
        weightSum += w * w;
    }
    return weightSum > 0.0 ? sum / weightSum : cones[0];
}

// ---- Indirect specular: GGX importance sampling --------------------------------------------
// L_IS = ∫ f_s(l, v) L(l) (n·l) dl with f_s = D·G·F / (4 (n·l)(n·v)) (brdf.glsl).
//
// Importance sampling. Half vectors h are drawn from D(h)(n·h) (which integrates to 1 over the
// hemisphere) and l = reflect(−v, h); the change of variables h → l has Jacobian 1/(4 (v·h)), so
//   p(l) = D(h)(n·h) / (4 (v·h))
// and the Monte Carlo weight of a sample reduces to
//   f_s (n·l) / p(l) = F(v, h) · G(l, v) · (v·h) / ((n·h)(n·v))
// (Karis 2013, "Real Shading in Unreal Engine 4", SIGGRAPH course notes, "Image-based lighting":
// D cancels). The plain estimator 1/N Σ F·w_k·L(l_k) is unbiased, but with N = 2 its weights
// alone scatter by ±15 % on a mirror seen at grazing angles and by ±50 % on rough surfaces, even
// where L is uniform: visible per-pixel noise.
//
// Split sum. Writing L_IS = E · ⟨L⟩ with E = ∫ f_s (n·l) dl (the lobe's directional albedo,
// which depends only on F0, roughness and n·v) and ⟨L⟩ the radiance averaged over the lobe with
// weights f_s (n·l), Lit estimates ⟨L⟩ by self-normalised importance sampling,
//   ⟨L⟩ ≈ Σ w_k L(l_k) / Σ w_k,   w_k = G(l_k, v)·(v·h_k) / ((n·h_k)(n·v))   (F's colour is in E),
// and reads E = F0·A + B from a table integrated once with these same samples and weights
// (ConeTracePass builds it with specular_albedo.frag.glsl). This is the split sum of Karis 2013
// with the lobe weights in place of n·l, so it converges to the exact integral as N grows; at any
// N a uniform field gives exactly E·L (no weight noise), and the noise left comes from radiance
// that varies inside the lobe, which wide cones on rough surfaces smooth out.
// Each sample's radiance L(l_k) is a cone traced along l_k (see specularConeAperture).

layout(binding = LIT_TEX_SPECULAR_ALBEDO) uniform sampler2D specularAlbedoTable;

// Van der Corput radical inverse in base 2 (Hammersley point set).
float radicalInverse(uint bits) { return float(bitfieldReverse(bits)) * 2.3283064365386963e-10; }

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): per-pixel values in [0,1) whose neighbours differ a lot, so the samples of
// neighbouring pixels spread around the lobe and the eye averages them.
float interleavedGradientNoise(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)).
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Share of the GGX lobe (of the D(h)(n·h) probability) the samples are drawn from: the last
// quarter is the long tail, h up to 90° from n, whose rare samples make isolated bright or dark
// pixels at 2 samples per pixel. Dropping it is a bias (reflections lose their faint halo), not
// an energy loss: E from the table still counts the whole lobe. Measured on the Cornell box
// (rough 0.4 metal, 2 samples): visibly fewer speckles than 1.0, the lobe still as wide.
const float kSpecularLobeShare = LIT_SPECULAR_LOBE_SHARE;

// Sample k of N: the Hammersley point (k/N, radicalInverse(k)) shifted per pixel
// (Cranley-Patterson rotation) and per frame. The azimuth shift comes from interleaved gradient
// noise, the polar one from a hash: with both from the gradient noise its line structure showed
// as diagonal moiré stripes.
vec2 specularSample(int k, int count, vec2 pixel, int frameIndex) {
    uvec2 p = uvec2(pixel);
    uint hash = pcgHash(p.x + pcgHash(p.y + pcgHash(uint(frameIndex))));
    vec2 rotation = vec2(float(hash) * 2.3283064365386963e-10,
                         interleavedGradientNoise(pixel + vec2(float(frameIndex % 64) * 5.588238)));
    vec2 u = fract(vec2(float(k) / float(count), radicalInverse(uint(k))) + rotation);
    return vec2(u.x * kSpecularLobeShare, u.y);
}

// GGX half vector in tangent space from uniform u ∈ [0,1)²: pdf D(h)(n·h) (Walter et al. 2007,
// eq. 35-36): cos²θ_h = (1 − u.x) / (1 + (α² − 1) u.x), φ = 2π u.y.
vec3 sampleGgxHalfVector(vec2 u, float alpha) {
    float a2 = alpha * alpha;
    float cos2 = (1.0 - u.x) / (1.0 + (a2 - 1.0) * u.x);
    float cosTheta = sqrt(clamp(cos2, 0.0, 1.0));
    float sinTheta = sqrt(clamp(1.0 - cos2, 0.0, 1.0));
    float phi = 2.0 * PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// The importance weight of a GGX sample without F: G(l, v)·(v·h) / ((n·h)(n·v)); 0 when l falls
// below the surface or h faces away from v. Sets `l` to the sampled light direction.
float ggxSampleWeight(vec3 n, vec3 v, vec3 h, float alpha, out vec3 l) {
    float VdotH = dot(v, h);
    l = 2.0 * VdotH * h - v;  // reflect(−v, h)
    float NdotL = dot(n, l);
    if (VdotH <= 0.0 || NdotL <= 0.0) return 0.0;
    float NdotV = max(dot(n, v), 1e-4);
    float NdotH = max(dot(n, h), 1e-4);
    return G_SmithGGXCorrelated(NdotL, NdotV, alpha) * VdotH / (NdotH * NdotV);
}

// Cone k of the `count` that stand for the lobe: sets its axis `l` and returns its weight (0: the
// sample fell below the surface). One cone (count 1) stands for the whole lobe: its core around the
// mirror direction (specularConeAperture), the same for every pixel and frame, so it has no
// sampling noise. More cones are GGX importance samples (specularSample) weighted by
// ggxSampleWeight, which scatter from pixel to pixel (docs/GI.md, "Indirect specular: GGX cones").
float specularLobeCone(int k, int count, vec3 n, vec3 v, mat3 basis, float alpha, vec2 pixel, int frameIndex,
                       out vec3 l) {
    if (count <= 1) {
        l = reflect(-v, n);
        return 1.0;
    }
    vec3 h = basis * sampleGgxHalfVector(specularSample(k, count, pixel, frameIndex), alpha);
    return ggxSampleWeight(n, v, h, alpha, l);
}

// Directional albedo E = ∫ f_s (n·l) dl of the GGX lobe with Schlick's F: E = F0·A + F90·B, where
// A = ∫ w·(1 − (1 − v·h)^5) and B = ∫ w·(1 − v·h)^5 are read from the table (`roughness`
// perceptual, the table's texel centres at (i + ½)/size).
vec3 specularAlbedo(vec3 f0, float f90, float roughness, float NdotV) {
    vec2 ab = textureLod(specularAlbedoTable, vec2(NdotV, roughness), 0.0).rg;
    return f0 * ab.x + f90 * ab.y;
}

// What multiplies the traced indirect specular radiance (docs/MATERIALS.md): the base lobe's
// directional albedo times `baseScale` (what a sheen leaves of it), through what a clear coat of
// weight `clearcoat` lets pass, plus the coat's (NcdotV: seen along the coat's own normal).
vec3 indirectSpecularWeight(vec3 f0, float f90, float roughness, float baseScale, float clearcoat,
                            float clearcoatRoughness, float NdotV, float NcdotV) {
    vec3 base = specularAlbedo(f0, f90, roughness, NdotV) * baseScale;
    if (clearcoat <= 0.0) return base;
    return base * clearcoatBaseScale(clearcoat, NcdotV) +
           clearcoat * specularAlbedo(kClearcoatF0, 1.0, clearcoatRoughness, NcdotV);
}

// Cones narrower than this march half a voxel per step for the whole volume; 0.02 rad is about
// one voxel wide at 50 voxels, so mirror reflections stay sharp at voxel resolution.
const float kMinSpecularAperture = LIT_SPECULAR_APERTURE_MIN;
const float kMaxSpecularAperture = LIT_SPECULAR_APERTURE_MAX;  // π/3: wider lobes are diffuse-like anyway

// Full aperture of the cone that stands for one of `count` samples of a GGX lobe with roughness
// α. The median half-vector angle of GGX is atan(α) (u.x = 1/2 above), so the reflected lobe is
// about 2·atan(α) ≈ 2α wide around the mirror direction; each of N samples covers 1/N of its
// solid angle, a cone of half angle ≈ 2α/√N:
//   aperture = 2·atan(2α/√N), clamped to [0.02, π/3].
// The single cone (count 1, specularLobeCone) is as wide as each of two samples', the lobe's core:
// as wide as the whole lobe it read more of its own surface's voxels at a slant (docs/GI.md,
// "Indirect specular: GGX cones").
float specularConeAperture(float alpha, int count) {
    float halfAngle = atan(2.0 * alpha * inversesqrt(float(max(count, 2))));
    return clamp(2.0 * halfAngle, kMinSpecularAperture, kMaxSpecularAperture);
}

// Whether a lobe with roughness α is at least two diffuse cones (of full aperture
// `diffuseAperture`) wide: its halves' cones, specularConeAperture(α, 2), no narrower than a
// diffuse cone. Its own cones would then only blur what the diffuse cones saw, and rough specular
// reuses them (radianceFromDiffuseCones). With 60° diffuse cones that is perceptual roughness
// ≥ 0.64, as most dielectrics of real scenes are; the march saved is the frame's largest cost on a
// software rasterizer. The cone count (indirect.specularSamples) says how a narrower lobe is
// traced, not whether.
bool specularCanReuseDiffuseCones(float alpha, float diffuseAperture) {
    return specularConeAperture(alpha, 2) >= diffuseAperture - LIT_CONE_REUSE_TOLERANCE;
}

// The lobe-averaged radiance ⟨L⟩ of traceSpecular below, without the directional albedo E, with
// the diffuse cones `cones` traced in `basis` when `reuseDiffuse`. The reduced-resolution pass
// stores it and applies E per pixel.
vec3 traceSpecularLobe(vec3 origin, vec3 n, mat3 basis, vec3 v, float roughness, int count, vec2 pixel, int frameIndex,
                       float maxDistance, bool reuseDiffuse, vec3 cones[kDiffuseConeCount]) {
    float alpha = alphaFromRoughness(roughness);
    float aperture = specularConeAperture(alpha, count);
    vec3 weightedRadiance = vec3(0.0);
    float weightSum = 0.0;
    for (int k = 0; k < count; ++k) {
        vec3 l;
        float w = specularLobeCone(k, count, n, v, basis, alpha, pixel, frameIndex, l);
        if (w <= 0.0) continue;
        vec3 radiance = reuseDiffuse ? radianceFromDiffuseCones(normalize(l * basis), cones)
                                     : traceCone(origin, l, aperture, maxDistance).rgb;
        // Specular cones are not footprint-bounded: one near the horizon stays close to its surface
        // and would march half a voxel at a time across the whole volume; narrow cones rarely
        // reach their surface's voxels anyway.
        weightedRadiance += w * radiance;
        weightSum += w;
    }
    if (weightSum <= 0.0) {
        // Every sample fell below the horizon (rough surface seen edge-on): use the mirror direction.
        vec3 mirror = reflect(-v, n);
        weightedRadiance = reuseDiffuse ? radianceFromDiffuseCones(normalize(mirror * basis), cones)
                                        : traceCone(origin, mirror, aperture, maxDistance).rgb;
        weightSum = 1.0;
    }
    return weightedRadiance / weightSum;
}

// The radiance of the indirect specular lobe of perceptual roughness `roughness` for a surface
// with normal n (unit, facing v) and view vector v (unit, towards the eye), from `count` (1..8)
// cones (specularLobeCone), or when `reuseDiffuse` from the diffuse cones' radiance `cones` in
// the same directions (see specularCanReuseDiffuseCones; the diffuse cones must be traced around
// the same n). L_IS is it times indirectSpecularWeight.
vec3 traceSpecular(vec3 origin, vec3 n, vec3 v, float roughness, int count, vec2 pixel, int frameIndex,
                   float maxDistance, bool reuseDiffuse, vec3 cones[kDiffuseConeCount]) {
    return traceSpecularLobe(origin, n, tangentFrame(n), v, roughness, count, pixel, frameIndex, maxDistance,
                             reuseDiffuse, cones);
}
