#pragma once
// KHR_materials_sheen's lobe (docs/MATERIALS.md): the Charlie distribution, Neubelt & Pettineo's
// visibility, and the directional albedo E_s(n·v, r_s) of a white sheen, which scales the base
// under it. The table is what both the rasterizer (a texture, gbuffer.glsl) and the reference
// read, so the two scale the base identically.

#include <array>

namespace lit {

inline constexpr int kSheenAlbedoSize = 32;  // texels per side: n·v across, sheen roughness down

// α_s of perceptual sheen roughness r_s (clamped to [0.07, 1]: the lobe's exponent 1/α_s stays finite).
float sheenAlpha(float roughness);
// Charlie distribution D_s(h) = (2 + 1/α) sin(θ_h)^(1/α) / (2π), n·h = cos θ_h.
float sheenDistribution(float NdotH, float alpha);
// V_s = 1 / (4 (n·l + n·v − (n·l)(n·v))).
float sheenVisibility(float NdotL, float NdotV);

// E_s at texel (i, j): n·v = (i + ½)/size, r_s = (j + ½)/size, row-major (j rows of i); computed
// once by midpoint quadrature of ∫ D_s V_s (n·l) dl.
const std::array<float, kSheenAlbedoSize * kSheenAlbedoSize>& sheenAlbedoTable();
// The table read as GL's bilinear filter with clamp to edge reads the texture.
float sheenAlbedo(float NdotV, float roughness);
// Its cosine-weighted mean over the view directions, 2∫ E_s(μ, r_s) μ dμ: the share of light from
// everywhere a white sheen reflects (what a voxel's sheen sends back, having no view direction).
float sheenMeanAlbedo(float roughness);

}  // namespace lit
