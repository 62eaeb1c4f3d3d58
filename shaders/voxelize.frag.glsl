#version 450 core
// Voxelization, fragment stage: one fragment = one voxel the triangle touches. Writes the
// material into the r32ui volumes as running averages (atomicAverageRgb), so every fragment
// that lands in a voxel counts equally, whatever the order.
#include "voxel.glsl"
#include "material.glsl"
#include "brdf.glsl"

in VoxelFragment {
    vec3 worldNormal;
    vec4 uv;
    flat vec4 bounds;
    flat int axis;
    flat vec3 corner0, corner1, corner2;
} fs;

// The point of triangle (a, b, c) nearest p (Ericson, Real-Time Collision Detection, 5.1.5).
vec3 closestPointOnTriangle(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 ab = b - a, ac = c - a, ap = p - a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    vec3 bp = p - b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    vec3 cp = p - c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    float va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    float denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

layout(binding = LIT_IMG_VOXEL_ALBEDO, r32ui) uniform coherent volatile uimage3D voxelAlbedo;
layout(binding = LIT_IMG_VOXEL_NORMAL, r32ui) uniform coherent volatile uimage3D voxelNormal;
layout(binding = LIT_IMG_VOXEL_EMISSION, r32ui) uniform coherent volatile uimage3D voxelEmission;
layout(binding = LIT_IMG_VOXEL_SURFACE, r32ui) uniform coherent volatile uimage3D voxelSurface;
LIT_OCCUPIED_VOXELS_BLOCK();

// (u, v, depth) of the projection along `axis` → voxel space: undoes voxelize.geom.glsl's swizzleForAxis.
vec3 fromAxisSpace(vec3 s, int axis) { return axis == 0 ? s.zxy : (axis == 1 ? s.yzx : s); }
// (Ā, B̄) of the GGX lobe at roughness j/(size − 1) (scene/SpecularMeanAlbedo.h), and a white
// sheen's mean albedo Ē_s at sheen roughness j/(size − 1) (scene/SheenAlbedo.h), set by VoxelizePass.
uniform vec2 uSpecularMeanAlbedo[LIT_SPECULAR_MEAN_ALBEDO_SIZE];
uniform float uSheenMeanAlbedo[LIT_SPECULAR_MEAN_ALBEDO_SIZE];

// The mean over the cosine-weighted hemisphere of the lobe's directional albedo, F0·Ā + F90·B̄.
vec3 specularMeanAlbedo(vec3 f0, float f90, float roughness) {
    float s = roughness * float(LIT_SPECULAR_MEAN_ALBEDO_SIZE - 1);
    int i = min(int(s), LIT_SPECULAR_MEAN_ALBEDO_SIZE - 2);
    vec2 ab = mix(uSpecularMeanAlbedo[i], uSpecularMeanAlbedo[i + 1], s - float(i));
    return f0 * ab.x + f90 * ab.y;
}

float sheenMeanAlbedo(float roughness) {
    float s = roughness * float(LIT_SPECULAR_MEAN_ALBEDO_SIZE - 1);
    int i = min(int(s), LIT_SPECULAR_MEAN_ALBEDO_SIZE - 2);
    return mix(uSheenMeanAlbedo[i], uSheenMeanAlbedo[i + 1], s - float(i));
}

// What a voxel reflects of the light it receives, as one Lambertian albedo: a voxel's light leaves
// in every direction, so each lobe counts with its albedo's hemispherical mean (docs/GI.md,
// "Voxelization"; docs/MATERIALS.md). The base is the diffuse (1 − metalness)·colour plus the
// specular lobe's mean; a sheen reflects its colour × its mean albedo Ē_s and leaves
// 1 − max(colour)·Ē_s of the base; a clear coat passes 1 − weight·F̄c of the light to both and back
// and reflects weight × its own lobe's mean. At most 1 per channel (the packed volume's range).
// The layers' factors are scaled by their texels `t` at the fragment.
vec3 reflectedAlbedo(GpuMaterial m, LayerTexels t, vec3 baseColor, float metalness, float roughness) {
    vec3 f0 = mix(materialDielectricF0(m, t), baseColor, metalness);
    float f90 = mix(materialDielectricF90(m, t), 1.0, metalness);
    vec3 base = baseColor * (1.0 - metalness) + specularMeanAlbedo(f0, f90, roughness);
    vec3 sheenColor = m.sheen.rgb * t.sheen.rgb;
    float sheenMean = max(sheenColor.r, max(sheenColor.g, sheenColor.b)) > 0.0 ?
                      sheenMeanAlbedo(clamp(m.sheen.a * t.sheen.a, 0.0, 1.0)) : 0.0;
    vec3 underCoat = base * (1.0 - max(sheenColor.r, max(sheenColor.g, sheenColor.b)) * sheenMean) +
                     sheenColor * sheenMean;
    float coatWeight = m.clearcoat.x * t.clearcoat;
    vec3 coat = coatWeight * specularMeanAlbedo(kClearcoatF0, 1.0, m.clearcoat.y * t.clearcoatRoughness);
    return clamp(underCoat * (1.0 - coatWeight * kClearcoatMeanFresnel) + coat, 0.0, 1.0);
}

uniform uint uOccupiedCapacity;  // entries the list can hold (VoxelVolume::occupiedCapacity)
// The voxels this draw writes, [min, max): the whole volume, or one box of a voxelization of
// changed boxes (VoxelizePass), whose items also cover voxels outside it that were not cleared.
uniform ivec3 uRegionMin, uRegionMax;
// A bit per voxel: listed already (VoxelVolume::listedVoxels).
layout(std430, binding = LIT_SSBO_LISTED_VOXELS) coherent buffer ListedVoxels { uint listedBits[]; };

void main() {
    // The enlarged triangle overshoots at acute corners: keep pixels that touch its true bounds.
    if (any(lessThan(gl_FragCoord.xy, fs.bounds.xy)) || any(greaterThan(gl_FragCoord.xy, fs.bounds.zw))) discard;

    int n = int(voxel.voxelInfo.x);
    // (u, v, depth) in voxels; undo the geometry shader's swizzle.
    ivec3 s = ivec3(ivec2(gl_FragCoord.xy), int(floor(gl_FragCoord.z * float(n))));
    ivec3 v = ivec3(fromAxisSpace(vec3(s), fs.axis));
    if (any(lessThan(v, max(uRegionMin, ivec3(0)))) || any(greaterThanEqual(v, min(uRegionMax, ivec3(n))))) discard;

    GpuMaterial m = materials[uMaterialIndex];
    if (materialIsSheet(m)) discard;  // light passes through sheets: they occupy no voxel
    vec4 baseColor = materialBaseColor(m, fs.uv);
    if (materialAlphaDiscard(m, baseColor.a)) discard;
    vec3 emissive = m.emissive.rgb;
    if (m.textures.w != 0)
        emissive *= texture(emissiveTexture, materialUv(LIT_MATERIAL_SLOT_EMISSIVE, fs.uv)).rgb;
    float len = length(fs.worldNormal);
    vec3 normal = len > 1e-12 ? fs.worldNormal / len : vec3(0.0);

    float metalness = m.params.x, roughness = m.params.y;
    if (m.textures.y != 0) {
        vec4 mr = texture(metallicRoughnessTexture, materialUv(LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS, fs.uv));
        roughness *= mr.g;
        metalness *= mr.b;
    }
    vec3 albedo = reflectedAlbedo(m, materialLayerTexels(m, fs.uv), clamp(baseColor.rgb, 0.0, 1.0), clamp(metalness, 0.0, 1.0), clamp(roughness, 0.0, 1.0));

    // The first fragment of a voxel (the albedo's compare-and-swap from 0 succeeds, as the first
    // try of atomicAverageRgb would) appends it to the occupied-voxel list unless it is listed
    // already (a voxelization of changed boxes keeps the list); later ones average.
    uint voxelIndex = uint(v.x) + uint(n) * (uint(v.y) + uint(n) * uint(v.z));
    uint listedBit = 1u << (voxelIndex & 31u);
    if (imageAtomicCompSwap(voxelAlbedo, v, 0u, averageRgbAdd(0u, albedo)) == 0u) {
        if ((atomicOr(listedBits[voxelIndex >> 5u], listedBit) & listedBit) == 0u) {
            uint index = atomicAdd(occupiedCount, 1u);
            if (index < uOccupiedCapacity) {
                occupiedVoxels[index] = packVoxelCoord(v);
                atomicMax(dispatchX, index / uint(LIT_INJECT_LIST_GROUP_SIZE) + 1u);
            }
        }
    } else {
        atomicAverageRgb(voxelAlbedo, v, albedo);
    }
    atomicAverageRgb(voxelNormal, v, normal * 0.5 + 0.5);
    atomicAverageRgb(voxelEmission, v, clamp(emissive / LIT_VOXEL_EMISSION_RANGE, 0.0, 1.0));
    // Where in the voxel its surface lies, for the voxel rays (bounce.comp.glsl, voxelSurfacePoint):
    // the point of the triangle nearest the centre of the voxel's column at the depth the plane has
    // there, in [0,1]³ of the voxel. The triangle's own point, not its plane's: the conservative
    // rasterization's fragments beyond an edge (kTouchMargin, the enlarged triangle) record the edge.
    vec3 onPlane = vec3(vec2(s.xy) + 0.5, gl_FragCoord.z * float(n));
    vec3 local = clamp(closestPointOnTriangle(onPlane, fs.corner0, fs.corner1, fs.corner2) - vec3(s), 0.0, 1.0);
    atomicAverageRgb(voxelSurface, v, fromAxisSpace(local, fs.axis));
}
