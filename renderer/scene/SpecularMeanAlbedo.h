#pragma once
// The hemispherical mean of the GGX specular lobe's directional albedo, for a voxel: a voxel's
// light leaves in every direction and arrives from every direction, so what its surface's
// specular lobe sends back of the light it receives is the lobe's albedo averaged over the
// cosine-weighted hemisphere, not its value for one view (docs/GI.md, "Voxelization"). With
// Schlick's F = F0·(1 − Fc) + F90·Fc, Fc = (1 − v·h)⁵, the directional albedo is
// E(μ) = F0·A(μ, r) + F90·B(μ, r), and its mean Ē = F0·Ā(r) + F90·B̄(r) with
// Ā(r) = 2∫ A(μ, r) μ dμ, B̄ likewise. The lobe is the reference's (reference/MicrofacetBrdf.h):
// GGX D, height-correlated Smith G, α = max(r, 0.03)².

#include <glm/glm.hpp>

#include <array>

#include <shared.h>

namespace lit {

inline constexpr int kSpecularMeanAlbedoSize = LIT_SPECULAR_MEAN_ALBEDO_SIZE;

// (Ā, B̄) at perceptual roughness r = j/(size − 1), j = 0..size−1; computed once by importance
// sampling the visible normals (Heitz 2018) at 64 view angles, 1024 samples each.
const std::array<glm::vec2, kSpecularMeanAlbedoSize>& specularMeanAlbedoTable();
// The table linearly interpolated in roughness (what voxelize.frag.glsl reads).
glm::vec2 specularMeanAlbedo(float roughness);

}  // namespace lit
