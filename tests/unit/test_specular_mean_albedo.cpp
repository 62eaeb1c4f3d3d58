// The GGX lobe's hemispherical mean albedo (scene/SpecularMeanAlbedo.h), which the voxelizer adds
// to a voxel's albedo (label cpu): against a brute-force quadrature of the reference's BRDF over
// both hemispheres, and against the mirror's closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "reference/MicrofacetBrdf.h"
#include "scene/SpecularMeanAlbedo.h"

namespace lit {
namespace {

// 2∫ μ_v ∫ f_s(l, v) (n·l) dl dμ_v for F0 = f0, F90 = f90 by the midpoint rule in the polar
// angles of v and l and the azimuth between them: no sampling shared with the table.
double bruteForceMean(float roughness, float f0, float f90) {
    constexpr int kView = 48, kTheta = 192, kPhi = 96;
    const float alpha = reference::alphaFromRoughness(roughness);
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const double dTheta = 0.5 * std::numbers::pi / kTheta, dPhi = std::numbers::pi / kPhi;
    double mean = 0.0;
    for (int a = 0; a < kView; ++a) {
        const float mu = (static_cast<float>(a) + 0.5f) / kView;
        const glm::vec3 v(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        double e = 0.0;
        for (int t = 0; t < kTheta; ++t) {
            const double theta = (t + 0.5) * dTheta;
            for (int p = 0; p < kPhi; ++p) {
                const double phi = (p + 0.5) * dPhi;  // half the azimuth: the lobe is mirror-symmetric
                const glm::vec3 l(static_cast<float>(std::sin(theta) * std::cos(phi)),
                                  static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
                e += reference::specularBrdf(n, v, l, glm::vec3(f0), f90, alpha).x * l.z * std::sin(theta);
            }
        }
        mean += 2.0 * e * dTheta * dPhi * mu;
    }
    return 2.0 * mean / kView;
}

TEST(SpecularMeanAlbedo, MatchesAQuadratureOfTheReferenceBrdf) {
    for (const float roughness : {0.3f, 0.6f, 1.0f}) {
        const glm::vec2 ab = specularMeanAlbedo(roughness);
        // A white furnace (F0 = F90 = 1) and a dielectric of η 1.5 (F0 0.04, F90 1).
        EXPECT_NEAR(ab.x + ab.y, bruteForceMean(roughness, 1.0f, 1.0f), 0.01) << "roughness " << roughness;
        EXPECT_NEAR(0.04f * ab.x + ab.y, bruteForceMean(roughness, 0.04f, 1.0f), 0.002) << "roughness " << roughness;
    }
}

TEST(SpecularMeanAlbedo, AMirrorReflectsSchlicksMeanFresnel) {
    // α = 0.03²: almost a mirror, whose mean over the cosine-weighted hemisphere of
    // F0 + (F90 − F0)(1 − μ)⁵ is F0·20/21 + F90/21.
    const glm::vec2 ab = specularMeanAlbedo(0.0f);
    EXPECT_NEAR(ab.x, 20.0f / 21.0f, 0.01f);
    EXPECT_NEAR(ab.y, 1.0f / 21.0f, 0.003f);
}

TEST(SpecularMeanAlbedo, RougherLobesLoseEnergyToMaskingAndShadowing) {
    const auto& table = specularMeanAlbedoTable();
    for (std::size_t j = 1; j < table.size(); ++j)
        EXPECT_LE(table[j].x + table[j].y, table[j - 1].x + table[j - 1].y + 1e-3f) << "entry " << j;
    EXPECT_LT(table.back().x + table.back().y, 0.95f);
}

}  // namespace
}  // namespace lit
