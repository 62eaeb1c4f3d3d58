// The reference path tracer's BRDF with KHR_materials_ior, KHR_materials_specular,
// KHR_materials_sheen and KHR_materials_clearcoat (docs/MATERIALS.md), label cpu: the default
// factors give the metal-rough BRDF bit for bit, the three-lobe sampling density against a
// histogram of its own samples (with and without a sheen), white furnaces (under a coat; the
// sheen lobe against its albedo table, and the base's albedo scaling under a sheen), the
// dielectric F0, and renders against closed forms. A few seconds on 2 cores.
#include "reference/MicrofacetBrdf.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceBsdf.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/SceneBuilder.h"
#include "scene/SheenAlbedo.h"
#include "QuietLog.h"
#include "ReferenceTestScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace lit::reference {
namespace {

using lit::testing::QuietLog;
using testing::BoxUnderSky;
using testing::boxUnderSky;

// Uniform floats in [0, 1) from a fixed-seed Mersenne twister (24 bits, the same on every platform).
struct Uniform {
    std::mt19937 engine;
    explicit Uniform(std::uint32_t seed) : engine(seed) {}
    float operator()() { return static_cast<float>(engine() >> 8) * (1.0f / 16777216.0f); }
};

glm::vec3 unitFromAngles(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// A hit with the given material factors, resolved the way ReferenceScene resolves it, at the
// origin with interpolated normal +z (tangent +x).
struct ResolvedHit {
    Scene scene;
    std::unique_ptr<ReferenceScene> reference;
    SurfaceHit hit;
};

std::unique_ptr<ResolvedHit> resolve(const Material& material, bool frontFacing = true,
                                     const glm::vec3& normal = glm::vec3(0, 0, 1)) {
    auto r = std::make_unique<ResolvedHit>();
    r->scene.materials.push_back(material);
    addMeshNode(r->scene, makeBoxMesh("box", glm::vec3(1.0f), 0), glm::vec3(0.0f));  // Embree wants a geometry
    r->scene.updateWorldTransforms();
    QuietLog log;
    r->reference = std::make_unique<ReferenceScene>(r->scene, log);
    r->hit.geometricNormal = frontFacing ? normal : -normal;
    r->reference->resolveMaterial(0, glm::vec4(0.5f), normal, glm::vec4(1, 0, 0, 1), frontFacing, r->hit);
    return r;
}

// ---- Default factors: the metal-rough BRDF -----------------------------------------------------

// The metal-rough BRDF and its two-lobe sampling density, written out: Lambert + GGX with
// F0 = mix(0.04, c, m), F90 = 1, the lobe chosen by Fresnel luminance against diffuse albedo.
struct MetalRough {
    glm::vec3 n, v, c;
    float m, alpha;
    glm::vec3 f0() const { return glm::mix(glm::vec3(0.04f), c, m); }
    glm::vec3 f(const glm::vec3& l) const {
        const glm::vec3 h = glm::normalize(v + l);
        const float nl = std::max(glm::dot(n, l), 1e-4f), nv = std::max(glm::dot(n, v), 1e-4f);
        const float nh = std::max(glm::dot(n, h), 0.0f), vh = std::max(glm::dot(v, h), 0.0f);
        const float a2 = alpha * alpha;
        const float d = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0f) + 1.0f, 2.0f));
        const float g = 2.0f * nl * nv / (nl * std::sqrt(nv * nv * (1.0f - a2) + a2) + nv * std::sqrt(nl * nl * (1.0f - a2) + a2));
        const glm::vec3 fresnel = f0() + (glm::vec3(1.0f) - f0()) * std::pow(1.0f - vh, 5.0f);
        return c * (1.0f - m) / kPi + d * g * fresnel / (4.0f * nl * nv);
    }
    float pdf(const glm::vec3& l) const {
        const float nl = glm::dot(n, l);
        if (nl <= 0.0f) return 0.0f;
        const auto lum = [](const glm::vec3& x) { return 0.2126f * x.r + 0.7152f * x.g + 0.0722f * x.b; };
        const float nv = glm::dot(n, v);
        const float specular = lum(f0() + (glm::vec3(1.0f) - f0()) * std::pow(1.0f - nv, 5.0f));
        const float diffuse = lum(c * (1.0f - m));
        const float p = specular / (specular + diffuse);
        const glm::vec3 h = glm::normalize(v + l);
        const float nh = glm::dot(n, h), a2 = alpha * alpha;
        const float d = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0f) + 1.0f, 2.0f));
        const float g1 = 2.0f * nv / (nv + std::sqrt(a2 + (1.0f - a2) * nv * nv));
        return (1.0f - p) * nl / kPi + p * g1 * d / (4.0f * nv);
    }
};

TEST(ReferenceBrdf, DefaultExtensionFactorsGiveTheMetalRoughBrdf) {
    Material material;  // ior 1.5, specular 1, specular colour 1, no sheen, no clear coat
    Uniform random(7);
    int compared = 0;
    for (const float metalness : {0.0f, 0.3f, 1.0f})
        for (const float roughness : {0.05f, 0.4f, 1.0f}) {
            material.baseColorFactor = glm::vec4(0.9f, 0.45f, 0.1f, 1.0f);
            material.metallic = metalness;
            material.roughness = roughness;
            const auto resolved = resolve(material);
            const SurfaceHit& hit = resolved->hit;
            EXPECT_EQ(hit.dielectricF0, glm::vec3(0.04f)) << "η 1.5 must give 0.04 exactly";
            EXPECT_EQ(hit.dielectricF90, 1.0f);
            EXPECT_EQ(hit.clearcoat, 0.0f);
            EXPECT_EQ(hit.sheenColor, glm::vec3(0.0f));
            EXPECT_EQ(hit.sheenRoughness, 0.0f);
            for (int k = 0; k < 40; ++k) {
                const glm::vec3 v = unitFromAngles(std::acos(0.02f + 0.98f * random()), 2.0f * kPi * random());
                const glm::vec3 l = unitFromAngles(std::acos(0.02f + 0.98f * random()), 2.0f * kPi * random());
                const Bsdf bsdf(hit, v);
                const MetalRough metalRough{hit.normal, v, hit.baseColor, hit.metalness, alphaFromRoughness(hit.roughness)};
                // Bit for bit against the metal-rough functions, and against the formula written out.
                EXPECT_EQ(bsdf.f0, specularF0(hit.baseColor, hit.metalness));
                EXPECT_EQ(bsdf.f90, 1.0f);
                EXPECT_EQ(bsdf.baseScale, 1.0f);
                EXPECT_EQ(bsdf.sheenScale, 1.0f);
                EXPECT_FALSE(bsdf.hasSheen());
                EXPECT_EQ(bsdf.coatProbability, 0.0f);
                EXPECT_EQ(bsdf.diffuseProbability, 1.0f - bsdf.specularProbability);
                // The lobe choice of the two metal-rough lobes, bit for bit.
                const float specularShare = bsdfLuminance(
                    F_Schlick(specularF0(hit.baseColor, hit.metalness), 1.0f, std::max(glm::dot(hit.normal, v), 0.0f)));
                const float diffuseShare = bsdfLuminance(diffuseAlbedo(hit.baseColor, hit.metalness));
                EXPECT_EQ(bsdf.specularProbability, specularShare / (specularShare + diffuseShare));
                EXPECT_EQ(bsdf.specular(l), specularBrdf(hit.normal, v, l, specularF0(hit.baseColor, hit.metalness), metalRough.alpha));
                EXPECT_EQ(bsdf.diffuse(l), diffuseAlbedo(hit.baseColor, hit.metalness) / kPi);
                EXPECT_EQ(bsdf.coatLobe(l), glm::vec3(0.0f));
                EXPECT_EQ(bsdf.sheenLobe(l), glm::vec3(0.0f));
                const glm::vec3 f = bsdf.diffuse(l) + bsdf.specular(l), expected = metalRough.f(l);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], expected[c], 2e-5f * expected[c] + 1e-7f);
                EXPECT_NEAR(bsdf.pdf(l), metalRough.pdf(l), 2e-5f * metalRough.pdf(l));
                // The sampler draws the metal-rough directions: GGX visible normals around n below
                // the specular probability, the cosine lobe above.
                const float choice = random();
                const glm::vec2 u(random(), random());
                glm::vec3 got, want;
                bsdf.sample(choice, u, got);
                const Frame frame(hit.normal);
                if (choice < bsdf.specularProbability) {
                    const glm::vec3 local = glm::normalize(glm::vec3(glm::vec2(frame.toLocal(v)), std::max(frame.toLocal(v).z, 1e-4f)));
                    const glm::vec3 h = frame.toWorld(sampleGgxVisibleNormal(local, metalRough.alpha, u));
                    want = 2.0f * glm::dot(v, h) * h - v;
                } else {
                    want = frame.toWorld(sampleCosineHemisphere(u));
                }
                EXPECT_EQ(got, want);
                ++compared;
            }
        }
    EXPECT_EQ(compared, 360);
}

// ---- The three-lobe sampling density ------------------------------------------------------------

// A clear-coated, normal-mapped hit (shading normal tilted 20° from the coat's normal towards
// the viewer), seen at 60°: the coat's lobe is sharp (α_c = 0.0625), the base's rough; all three
// lobes are drawn, and the coat's and the base's GGX lobes both reach the wedge above the coat's
// horizon and below the shading normal's.
SurfaceHit coatedHit() {
    SurfaceHit hit;
    hit.geometricNormal = glm::vec3(0, 0, 1);
    hit.clearcoatNormal = glm::vec3(0, 0, 1);
    hit.normal = glm::vec3(std::sin(0.35f), 0.0f, std::cos(0.35f));
    hit.baseColor = glm::vec3(0.8f, 0.5f, 0.3f);
    hit.metalness = 0.2f;
    hit.roughness = 0.8f;
    hit.clearcoat = 0.8f;
    hit.clearcoatRoughness = 0.25f;
    return hit;
}

// Directions binned uniformly in (cos θ, φ) around +z, over the whole sphere (equal solid angles).
constexpr int kBinsTheta = 128, kBinsPhi = 128;
int binOf(const glm::vec3& l) {
    const int i = std::clamp(static_cast<int>((l.z + 1.0f) * 0.5f * kBinsTheta), 0, kBinsTheta - 1);
    float phi = std::atan2(l.y, l.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const int j = std::clamp(static_cast<int>(phi / (2.0f * kPi) * kBinsPhi), 0, kBinsPhi - 1);
    return i * kBinsPhi + j;
}

// ∫ pdf over each bin, by the midpoint rule on 8 × 8 points per bin.
std::vector<double> binIntegrals(const std::function<float(const glm::vec3&)>& pdf) {
    constexpr int kSub = 8;
    std::vector<double> out(kBinsTheta * kBinsPhi, 0.0);
    const double cell = 4.0 * kPi / (kBinsTheta * kBinsPhi * kSub * kSub);
    for (int i = 0; i < kBinsTheta * kSub; ++i) {
        const float z = -1.0f + 2.0f * (static_cast<float>(i) + 0.5f) / (kBinsTheta * kSub);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        for (int j = 0; j < kBinsPhi * kSub; ++j) {
            const float phi = 2.0f * kPi * (static_cast<float>(j) + 0.5f) / (kBinsPhi * kSub);
            out[static_cast<std::size_t>((i / kSub) * kBinsPhi + j / kSub)] +=
                pdf(glm::vec3(r * std::cos(phi), r * std::sin(phi), z)) * cell;
        }
    }
    return out;
}

// Pearson's χ² per degree of freedom of the counts against N × the bins' integrals (bins expecting
// fewer than 20 samples pooled into one).
double chiSquarePerBin(const std::vector<int>& counts, const std::vector<double>& integrals, int n) {
    double chi2 = 0.0, pooledExpected = 0.0, pooledCount = 0.0;
    int bins = 0;
    for (std::size_t b = 0; b < counts.size(); ++b) {
        const double expected = integrals[b] * n;
        if (expected < 20.0) {
            pooledExpected += expected;
            pooledCount += counts[b];
            continue;
        }
        chi2 += (counts[b] - expected) * (counts[b] - expected) / expected;
        ++bins;
    }
    if (pooledExpected > 0.0) {
        chi2 += (pooledCount - pooledExpected) * (pooledCount - pooledExpected) / pooledExpected;
        ++bins;
    }
    return chi2 / std::max(bins - 1, 1);
}

// A histogram of the Bsdf's samples over the bins, and how many of them land where pdf() counts
// them (above some lobe's horizon) and below the shading normal's horizon.
struct SampleHistogram {
    static constexpr int kSamples = 4 << 20;
    std::vector<int> counts = std::vector<int>(kBinsTheta * kBinsPhi, 0);
    int inside = 0, belowShadingHorizon = 0;
    double fraction() const { return static_cast<double>(inside) / kSamples; }
};

SampleHistogram sampleHistogram(const Bsdf& bsdf, std::uint32_t seed) {
    SampleHistogram h;
    Uniform random(seed);
    for (int s = 0; s < SampleHistogram::kSamples; ++s) {
        const float choice = random();
        const glm::vec2 u(random(), random());
        glm::vec3 l;
        bsdf.sample(choice, u, l);
        if (!bsdf.above(l)) continue;  // where pdf() is 0: the sampler's lost mass
        ++h.inside;
        if (glm::dot(bsdf.n, l) <= 0.0f) ++h.belowShadingHorizon;
        ++h.counts[static_cast<std::size_t>(binOf(glm::normalize(l)))];
    }
    return h;
}

double sum(const std::vector<double>& xs) {
    double total = 0.0;
    for (const double x : xs) total += x;
    return total;
}

TEST(ReferenceBrdf, ClearcoatSamplingDensityMatchesItsSamples) {
    const SurfaceHit hit = coatedHit();
    const glm::vec3 v = unitFromAngles(1.047f, 0.0f);  // 60° from the coat normal, on +x
    const Bsdf bsdf(hit, v);
    ASSERT_TRUE(bsdf.hasCoat());
    ASSERT_GT(bsdf.coatProbability, 0.05f);
    ASSERT_GT(bsdf.specularProbability, 0.05f);

    constexpr int kSamples = SampleHistogram::kSamples;
    const SampleHistogram histogram = sampleHistogram(bsdf, 11);
    const std::vector<int>& counts = histogram.counts;
    const int belowShadingHorizon = histogram.belowShadingHorizon;
    const std::vector<double> integrals = binIntegrals([&](const glm::vec3& l) { return bsdf.pdf(l); });
    const double total = sum(integrals);
    const double fraction = histogram.fraction();
    // The density integrates to the share of samples it covers (GGX reflections below both
    // horizons are lost): within 0.3 %.
    EXPECT_NEAR(total, fraction, 0.003) << "∫pdf " << total << ", samples inside " << fraction;
    EXPECT_GT(fraction, 0.9);
    EXPECT_LE(fraction, 1.0);
    EXPECT_GT(belowShadingHorizon, 1000) << "the coat reflects where the normal-mapped base does not";
    const double chi2 = chiSquarePerBin(counts, integrals, kSamples);
    EXPECT_LT(chi2, 1.3) << "χ²/bin of the sample histogram against pdf()";

    // The same histogram against the density without the coat's lobe (what pdf() would be if it
    // left the coat out) fails by far: the test sees a missing lobe.
    Bsdf withoutCoat = bsdf;
    withoutCoat.coat = 0.0f;
    const double chi2Wrong =
        chiSquarePerBin(counts, binIntegrals([&](const glm::vec3& l) { return withoutCoat.pdf(l); }), kSamples);
    EXPECT_GT(chi2Wrong, 20.0);
    std::printf("[ measured ] ∫pdf %.5f, samples inside %.5f, χ²/bin %.3f (without the coat lobe in pdf: %.1f)\n",
                total, fraction, chi2, chi2Wrong);
}

// The same clear-coated hit with a dark base (a coated velvet) under a sheen: the cosine lobe
// also draws the sheen's directions, so its share grows by the sheen's albedo and the base's
// lobes shrink by t_s; pdf() is the same mixture with those chances, and it still matches the
// samples.
TEST(ReferenceBrdf, SheenSamplingDensityMatchesItsSamples) {
    SurfaceHit hit = coatedHit();
    hit.baseColor = glm::vec3(0.1f, 0.06f, 0.04f);
    hit.metalness = 0.0f;
    const glm::vec3 v = unitFromAngles(1.047f, 0.0f);
    const Bsdf plain(hit, v);
    hit.sheenColor = glm::vec3(0.9f, 0.6f, 0.8f);
    hit.sheenRoughness = 0.8f;
    const Bsdf bsdf(hit, v);
    ASSERT_TRUE(bsdf.hasSheen());
    ASSERT_TRUE(bsdf.reflects());
    const float NdotV = glm::dot(bsdf.n, v);
    EXPECT_FLOAT_EQ(bsdf.sheenScale, 1.0f - 0.9f * sheenAlbedo(NdotV, 0.8f));
    EXPECT_EQ(bsdf.sheenAlpha, 0.8f * 0.8f);
    EXPECT_GT(bsdf.diffuseProbability, plain.diffuseProbability + 0.05f) << "the sheen's share is drawn by the cosine lobe";
    EXPECT_LT(bsdf.specularProbability, plain.specularProbability);
    EXPECT_LT(bsdf.coatProbability, plain.coatProbability);

    constexpr int kSamples = SampleHistogram::kSamples;
    const SampleHistogram histogram = sampleHistogram(bsdf, 13);
    const std::vector<double> integrals = binIntegrals([&](const glm::vec3& l) { return bsdf.pdf(l); });
    const double total = sum(integrals), fraction = histogram.fraction();
    EXPECT_NEAR(total, fraction, 0.003) << "∫pdf " << total << ", samples inside " << fraction;
    EXPECT_GT(fraction, 0.9);
    const double chi2 = chiSquarePerBin(histogram.counts, integrals, kSamples);
    EXPECT_LT(chi2, 1.3) << "χ²/bin of the sample histogram against pdf()";

    // Against the density with the lobe chances of the hit without a sheen, the histogram fails:
    // the test sees the chances that pdf() weighs its lobes with.
    Bsdf wrongChances = bsdf;
    wrongChances.specularProbability = plain.specularProbability;
    wrongChances.coatProbability = plain.coatProbability;
    wrongChances.diffuseProbability = plain.diffuseProbability;
    const double chi2Wrong =
        chiSquarePerBin(histogram.counts, binIntegrals([&](const glm::vec3& l) { return wrongChances.pdf(l); }), kSamples);
    EXPECT_GT(chi2Wrong, 20.0);
    std::printf("[ measured ] sheen: lobe chances diffuse %.3f (%.3f without the sheen), ∫pdf %.5f, samples inside %.5f, "
                "χ²/bin %.3f (with the chances of the hit without a sheen: %.1f)\n",
                bsdf.diffuseProbability, plain.diffuseProbability, total, fraction, chi2, chi2Wrong);
}

// ---- White furnaces ------------------------------------------------------------------------------

struct Albedo {
    double diffuse = 0.0, specular = 0.0;
    double total() const { return diffuse + specular; }
};

// ∫ f cos dω split by lobe (the coat in specular, the sheen in diffuse), by the Bsdf's own
// sampling and pdf.
Albedo directionalAlbedo(const Bsdf& bsdf, std::uint32_t seed, int samples = 1 << 16) {
    Uniform random(seed);
    Albedo a;
    for (int s = 0; s < samples; ++s) {
        const float choice = random();
        const glm::vec2 u(random(), random());
        glm::vec3 l;
        if (!bsdf.sample(choice, u, l)) continue;
        const float pdf = bsdf.pdf(l);
        if (pdf <= 0.0f) continue;
        const Split w = bsdf.weight(l, pdf);
        a.diffuse += w.diffuse.g;
        a.specular += w.specular.g;
    }
    a.diffuse /= samples;
    a.specular /= samples;
    return a;
}
Albedo directionalAlbedo(const SurfaceHit& hit, const glm::vec3& v, std::uint32_t seed) {
    return directionalAlbedo(Bsdf(hit, v), seed);
}

TEST(ReferenceFurnace, ClearcoatOnWhiteDoesNotCreateLight) {
    double worst = 0.0, worstGain = -1.0;
    for (const float NdotV : {0.1f, 0.3f, 0.6f, 1.0f})
        for (const float roughness : {0.2f, 0.6f, 1.0f})
            for (const float coatRoughness : {0.0f, 0.3f, 0.7f}) {
                const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV);
                SurfaceHit hit;
                hit.geometricNormal = hit.normal = hit.clearcoatNormal = glm::vec3(0, 0, 1);
                hit.baseColor = glm::vec3(1.0f);
                hit.metalness = 0.0f;
                hit.roughness = roughness;
                hit.clearcoatRoughness = coatRoughness;
                const float fc = 0.04f + 0.96f * std::pow(1.0f - NdotV, 5.0f);
                const std::string where = "n·v " + std::to_string(NdotV) + ", roughness " + std::to_string(roughness) +
                                          ", coat roughness " + std::to_string(coatRoughness);

                // A white Lambertian base (specular weight 0: no dielectric reflection) reflects
                // everything; under a coat it keeps 1 − Fc(n·v) and the coat adds its own GGX
                // albedo of F0 0.04. The layering (glTF's) attenuates by Fc(n·v), not by the
                // coat's directional albedo, so the sum is 1 only nearly (1 % allowed, with the
                // estimate's noise). Without the base's 1 − cc·Fc it would reach 1.6 at grazing.
                hit.dielectricF0 = dielectricF0(1.5f, 0.0f, glm::vec3(1.0f));
                hit.dielectricF90 = dielectricF90(0.0f);
                hit.clearcoat = 0.0f;
                const Albedo lambert = directionalAlbedo(hit, v, 1);
                EXPECT_NEAR(lambert.total(), 1.0, 0.01) << where;
                hit.clearcoat = 1.0f;
                const Albedo coated = directionalAlbedo(hit, v, 2);
                EXPECT_LE(coated.total(), 1.01) << where;
                EXPECT_NEAR(coated.diffuse, 1.0 - fc, 0.01) << where;
                worst = std::max(worst, coated.total());
                if (coatRoughness == 0.0f && NdotV >= 0.3f) {  // a near-mirror coat reflects Fc(n·v)
                    EXPECT_NEAR(coated.specular, fc, 0.03 * fc + 0.002) << where;
                }

                // The white glTF dielectric (specular weight 1): its diffuse share falls by the
                // coat's 1 − Fc(n·v); the coat adds no light to the bare base's total.
                hit.dielectricF0 = dielectricF0(1.5f, 1.0f, glm::vec3(1.0f));
                hit.dielectricF90 = dielectricF90(1.0f);
                hit.clearcoat = 0.0f;
                const Albedo bare = directionalAlbedo(hit, v, 3);
                hit.clearcoat = 1.0f;
                const Albedo dielectric = directionalAlbedo(hit, v, 4);
                EXPECT_LT(dielectric.diffuse, bare.diffuse) << where;
                EXPECT_NEAR(dielectric.diffuse / bare.diffuse, 1.0 - fc, 0.01) << where;
                EXPECT_LE(dielectric.total(), bare.total() + 0.01) << where;
                worstGain = std::max(worstGain, dielectric.total() - bare.total());
            }
    std::printf("[ measured ] white Lambert base under a coat: largest directional albedo %.4f; white dielectric: "
                "largest gain of the coated over the bare albedo %.4f\n",
                worst, worstGain);
}

// A surface at the origin with normal +z, seen from v in the xz plane at n·v, reflecting only
// through the lobes set: base colour `base`, specular weight 0 (no dielectric reflection), and a
// sheen of colour `sheen` and roughness `sheenRoughness`.
SurfaceHit sheenedHit(float base, float sheen, float sheenRoughness) {
    SurfaceHit hit;
    hit.geometricNormal = hit.normal = hit.clearcoatNormal = glm::vec3(0, 0, 1);
    hit.baseColor = glm::vec3(base);
    hit.metalness = 0.0f;
    hit.dielectricF0 = dielectricF0(1.5f, 0.0f, glm::vec3(1.0f));
    hit.dielectricF90 = dielectricF90(0.0f);
    hit.sheenColor = glm::vec3(sheen);
    hit.sheenRoughness = sheenRoughness;
    return hit;
}
glm::vec3 viewAt(float NdotV) { return {std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV}; }

// The sheen lobe alone (a black base without specular reflection under a white sheen): its
// directional albedo, integrated by the path tracer's own sampling of the lobe it evaluates, is
// the shared table's E_s(n·v, r_s) (scene/SheenAlbedo.h), so the base's scaling by
// 1 − max(s_c)·E_s removes what the lobe reflects. All of it is diffuse. (Below r_s 0.3 the
// lobe is a grazing ridge and E_s far from grazing falls under 0.06, where the bilinear table
// departs from it by up to 0.003.)
// What the voxels reflect of a sheen (voxelize.frag.glsl): the table's cosine-weighted mean over
// the view directions, between the table's extremes, and growing with roughness as E_s does
// at normal incidence.
TEST(SheenAlbedo, MeanAlbedoIsTheCosineWeightedMeanOfTheTable) {
    float previous = 0.0f;
    for (const float roughness : {0.2f, 0.5f, 0.8f, 1.0f}) {
        double mean = 0.0;
        constexpr int kSteps = 4000;
        for (int i = 0; i < kSteps; ++i) {
            const float mu = (static_cast<float>(i) + 0.5f) / kSteps;
            mean += 2.0 * sheenAlbedo(mu, roughness) * mu / kSteps;
        }
        const float got = sheenMeanAlbedo(roughness);
        std::printf("[ measured ] sheen roughness %.1f: mean albedo %.4f (fine quadrature %.4f)\n", roughness, got, mean);
        EXPECT_NEAR(got, mean, 1e-3);
        EXPECT_GT(got, 0.0f);
        EXPECT_LT(got, 1.0f);
        EXPECT_GT(got, previous) << "rougher sheens reflect more";
        previous = got;
    }
}

TEST(ReferenceFurnace, SheenLobeAlbedoIsTheSheenAlbedoTable) {
    double worst = 0.0;
    for (const float NdotV : {0.1f, 0.3f, 0.6f, 0.9f})
        for (const float roughness : {0.3f, 0.5f, 0.8f, 1.0f}) {
            const Bsdf bsdf(sheenedHit(0.0f, 1.0f, roughness), viewAt(NdotV));
            ASSERT_TRUE(bsdf.reflects());
            ASSERT_EQ(bsdf.diffuseProbability, 1.0f);
            const Albedo a = directionalAlbedo(bsdf, 21, 1 << 17);
            const double table = sheenAlbedo(NdotV, roughness);
            const std::string where = "n·v " + std::to_string(NdotV) + ", sheen roughness " + std::to_string(roughness);
            EXPECT_EQ(a.specular, 0.0) << where;
            EXPECT_NEAR(a.diffuse, table, 0.02 * table + 0.001) << where << ": lobe " << a.diffuse << ", table " << table;
            worst = std::max(worst, std::abs(a.diffuse / table - 1.0));
        }
    // The black base with no sheen reflects nothing: the path ends there.
    EXPECT_FALSE(Bsdf(sheenedHit(0.0f, 0.0f, 0.5f), viewAt(0.5f)).reflects());
    std::printf("[ measured ] sheen lobe's directional albedo against E_s: largest relative difference %.4f\n", worst);
}

// A white Lambertian base under a white sheen reflects E_s + (1 − E_s) = 1: the albedo scaling
// keeps the energy (2 % allowed for the table's interpolation and the estimate's noise), and all of
// it is diffuse. Without the scaling the sum would exceed 1 by E_s (checked, so that the test sees
// a missing scale). Under a clear coat the sum stays below 1.02 as well.
TEST(ReferenceFurnace, SheenOnWhiteDoesNotCreateLight) {
    double worst = 0.0, leastUnscaled = 1e9;
    for (const float NdotV : {0.1f, 0.3f, 0.6f, 1.0f})
        for (const float roughness : {0.3f, 0.6f, 1.0f}) {
            const std::string where = "n·v " + std::to_string(NdotV) + ", sheen roughness " + std::to_string(roughness);
            SurfaceHit hit = sheenedHit(1.0f, 1.0f, roughness);
            const Bsdf bsdf(hit, viewAt(NdotV));
            const float table = sheenAlbedo(NdotV, roughness);
            EXPECT_FLOAT_EQ(bsdf.sheenScale, 1.0f - table) << where;
            const Albedo a = directionalAlbedo(bsdf, 31, 1 << 17);
            EXPECT_EQ(a.specular, 0.0) << where;
            EXPECT_LE(a.total(), 1.02) << where;
            EXPECT_GE(a.total(), 0.98) << where;
            worst = std::max(worst, a.total());

            // The same lobes with the base left whole: E_s more light than arrives.
            Bsdf unscaled = bsdf;
            unscaled.sheenScale = 1.0f;
            const Albedo u = directionalAlbedo(unscaled, 31, 1 << 17);
            if (table > 0.05f) {
                EXPECT_GT(u.total(), 1.02) << where;
                EXPECT_NEAR(u.total() - a.total(), table, 0.01) << where;
                leastUnscaled = std::min(leastUnscaled, u.total());
            }

            // Under a clear coat of roughness 0.3.
            hit.clearcoat = 1.0f;
            hit.clearcoatRoughness = 0.3f;
            const Albedo coated = directionalAlbedo(Bsdf(hit, viewAt(NdotV)), 32, 1 << 17);
            EXPECT_LE(coated.total(), 1.02) << where << ", under a coat";
            worst = std::max(worst, coated.total());
        }
    ASSERT_LT(leastUnscaled, 1e9);
    std::printf("[ measured ] white Lambert base under a white sheen: largest directional albedo %.4f (under a coat "
                "included); without the base's scaling at least %.4f\n",
                worst, leastUnscaled);
}

// The path tracer end to end: a convex box (it never sees itself) of a white Lambertian base
// (specular weight 0) under a near-mirror coat, all bounces, under a uniform white sky. Every
// visible point sends (1 − Fc(n·v)) into the diffuse terms and the coat's albedo ≈ Fc(n·v) into
// the specular terms: the coat's reflection is specular, and the sum is the sky's radiance.
TEST(ReferenceFurnace, ClearcoatedConvexBoxUnderUniformSky) {
    Scene scene;
    addMaterial(scene, glm::vec3(1.0f), 0.7f, 0.0f, "coated");
    scene.materials[0].specularFactor = 0.0f;
    scene.materials[0].clearcoatFactor = 1.0f;
    scene.materials[0].clearcoatRoughness = 0.0f;
    double expectedDiffuse = 0.0, expectedSpecular = 0.0;
    const BoxUnderSky box = boxUnderSky(scene, 1.0f, 256, true, [&](const FirstHit& hit, const glm::vec3& eye) {
        const float NdotV = glm::dot(hit.normal, glm::normalize(eye - hit.position));
        const float fc = 0.04f + 0.96f * std::pow(1.0f - NdotV, 5.0f);
        expectedDiffuse += 1.0f - fc;
        expectedSpecular += fc;
    });
    expectedDiffuse /= box.pixels;
    expectedSpecular /= box.pixels;
    // 1 % of the sky for the sum and the diffuse share, 5 % of the coat's share (the lobe choice
    // makes the split noisy: one standard deviation is about 0.1 % of the sky at 256 spp).
    EXPECT_NEAR(box.diffuse + box.specular, 1.0, 0.01);
    EXPECT_NEAR(box.diffuse, expectedDiffuse, 0.01);
    EXPECT_NEAR(box.specular, expectedSpecular, 0.05 * expectedSpecular);
    std::printf("[ measured ] coated box under a white sky: diffuse %.4f (1 − Fc: %.4f), specular %.4f (Fc: %.4f)\n",
                box.diffuse, expectedDiffuse, box.specular, expectedSpecular);
}

// ---- ior and specular ----------------------------------------------------------------------------

TEST(ReferenceBrdf, IorAndSpecularFactorsSetTheDielectricReflectance) {
    EXPECT_EQ(dielectricF0(1.5f, 1.0f, glm::vec3(1.0f)), glm::vec3(0.04f));
    EXPECT_FLOAT_EQ(dielectricF0(2.0f, 1.0f, glm::vec3(1.0f)).r, 1.0f / 9.0f);
    EXPECT_EQ(dielectricF0(1.0f, 1.0f, glm::vec3(1.0f)), glm::vec3(0.0f));
    EXPECT_EQ(dielectricF0(0.0f, 1.0f, glm::vec3(1.0f)), glm::vec3(1.0f)) << "η 0: a mirror";
    const glm::vec3 tinted = dielectricF0(2.0f, 0.5f, glm::vec3(2.0f, 1.0f, 20.0f));
    EXPECT_FLOAT_EQ(tinted.r, 0.5f * 2.0f / 9.0f);
    EXPECT_FLOAT_EQ(tinted.g, 0.5f / 9.0f);
    EXPECT_FLOAT_EQ(tinted.b, 0.5f) << "the tinted F0 is clamped to 1 before the weight";
    EXPECT_EQ(F_Schlick(glm::vec3(0.25f), 0.5f, 0.0f), glm::vec3(0.5f)) << "grazing: F90";
    EXPECT_EQ(specularF90(0.0f, 0.3f), 0.3f);
    EXPECT_EQ(specularF90(1.0f, 0.3f), 1.0f) << "metals reach 1 at grazing";
    EXPECT_EQ(specularF90(0.37f, 1.0f), 1.0f) << "specular weight 1: F90 is 1 exactly";
    EXPECT_EQ(specularF0(glm::vec3(0.7f), 1.0f, glm::vec3(0.0f)), glm::vec3(0.7f));

    // Through the material resolve: the factors reach the hit.
    Material material;
    material.baseColorFactor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    material.metallic = 0.0f;
    material.ior = 2.0f;
    material.specularFactor = 0.5f;
    material.specularColorFactor = glm::vec3(1.0f, 0.5f, 3.0f);
    material.clearcoatFactor = 0.7f;
    material.clearcoatRoughness = 0.2f;
    const auto resolved = resolve(material);
    EXPECT_FLOAT_EQ(resolved->hit.dielectricF0.r, 0.5f / 9.0f);
    EXPECT_FLOAT_EQ(resolved->hit.dielectricF0.g, 0.25f / 9.0f);
    EXPECT_FLOAT_EQ(resolved->hit.dielectricF0.b, 0.5f / 3.0f);
    EXPECT_EQ(resolved->hit.dielectricF90, 0.5f);
    EXPECT_EQ(resolved->hit.clearcoat, 0.7f);
    EXPECT_EQ(resolved->hit.clearcoatRoughness, 0.2f);

    // Specular weight 0 removes the dielectric's specular lobe (F0 = F90 = 0) and leaves the
    // diffuse one; a metal keeps its F0 = base colour.
    material.specularFactor = 0.0f;
    material.clearcoatFactor = 0.0f;
    const auto matte = resolve(material);
    Uniform random(5);
    for (int k = 0; k < 50; ++k) {
        const glm::vec3 v = unitFromAngles(std::acos(0.05f + 0.95f * random()), 2.0f * kPi * random());
        const glm::vec3 l = unitFromAngles(std::acos(0.05f + 0.95f * random()), 2.0f * kPi * random());
        const Bsdf bsdf(matte->hit, v);
        EXPECT_EQ(bsdf.specular(l), glm::vec3(0.0f));
        EXPECT_EQ(bsdf.specularProbability, 0.0f);
        EXPECT_EQ(bsdf.diffuse(l), glm::vec3(0.6f) / kPi);
    }
    material.metallic = 1.0f;
    const auto metal = resolve(material);
    const Bsdf metalBsdf(metal->hit, glm::vec3(0, 0, 1));
    EXPECT_EQ(metalBsdf.f0, glm::vec3(0.6f));
    EXPECT_GT(metalBsdf.specular(glm::vec3(0, 0, 1)).r, 0.0f);
}

TEST(ReferenceBrdf, ClearcoatNormalIsTheInterpolatedNormal) {
    // A normal map whose one texel tilts the normal along the tangent: the base's normal follows
    // it, the coat's does not; both are flipped on back faces.
    Material material;
    material.clearcoatFactor = 1.0f;
    Scene scene;
    Image image;
    image.width = image.height = 1;
    image.rgba = {220, 128, 200, 255};  // tangent-space (0.73, 0, 0.57): tilted towards +x
    scene.images.push_back(image);
    Texture texture;
    texture.image = 0;
    scene.textures.push_back(texture);
    material.normalTexture = 0;
    scene.materials.push_back(material);
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), 0), glm::vec3(0.0f));
    scene.updateWorldTransforms();
    QuietLog log;
    const ReferenceScene reference(scene, log);
    for (const bool front : {true, false}) {
        SurfaceHit hit;
        hit.geometricNormal = front ? glm::vec3(0, 0, 1) : glm::vec3(0, 0, -1);
        reference.resolveMaterial(0, glm::vec4(0.5f), glm::vec3(0, 0, 2), glm::vec4(1, 0, 0, 1), front, hit);
        const float side = front ? 1.0f : -1.0f;
        EXPECT_EQ(hit.clearcoatNormal, glm::vec3(0, 0, side));
        EXPECT_GT(hit.normal.x, 0.5f) << "the base is normal-mapped";
        EXPECT_NEAR(hit.normal.z * side, 0.6f, 0.1f);
        EXPECT_EQ(hit.clearcoat, 1.0f);
    }
}

// ---- A render at normal incidence ------------------------------------------------------------------

// The mean direct terms (diffuse, specular) seen straight down on the plane of `scene` (its one
// material, already set) from 5 m above through a narrow camera (±0.1° across 8 × 8 pixels: v = n
// in every pixel), under a sun of `sun` W/m² shining from direction `towardsSun`. A punctual light
// and pixel centres: no noise, one sample.
std::pair<glm::dvec3, glm::dvec3> directTermsFromAbove(Scene& scene, float sun, const glm::vec3& towardsSun) {
    addMeshNode(scene, makePlaneMesh("plane", 20.0f, 0), glm::vec3(0.0f));
    Light light;
    light.type = LightType::Directional;
    light.intensity = sun;
    addLightNode(scene, light, glm::vec3(0.0f, 5.0f, 0.0f), -towardsSun);
    Camera camera;
    camera.yfov = 0.0035f;
    camera.znear = 0.5f;
    camera.zfar = 20.0f;
    addCameraNode(scene, camera, glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f));
    scene.updateWorldTransforms();
    QuietLog log;
    const ReferenceScene reference(scene, log);
    ReferenceSettings settings;
    settings.bounces = 0;
    settings.pixelCentres = true;
    PathTracer tracer(reference, sceneCameraView(scene, 0, 1.0f), 8, 8, settings);
    tracer.addSamples(1);
    glm::dvec3 diffuse(0.0), specular(0.0);
    for (std::size_t p = 0; p < 64; ++p) {
        diffuse += glm::dvec3(tracer.image().mean(Term::DirectDiffuse, p));
        specular += glm::dvec3(tracer.image().mean(Term::DirectSpecular, p));
    }
    return {diffuse / 64.0, specular / 64.0};
}

// A plane seen from straight above under a sun straight above (directTermsFromAbove): every
// pixel sees v = l = n, where D = 1/(πα²), G2 = 1, F = F0 and Fc = 0.04.
TEST(ReferenceClosedForm, ClearcoatedPlaneAtNormalIncidence) {
    constexpr float kSun = 3.0f;  // W/m² (Light::intensity of a directional light)
    const glm::vec3 base(0.5f, 0.3f, 0.2f);
    constexpr float kRoughness = 0.5f, kCoatRoughness = 0.4f;
    struct Case {
        float ior, clearcoat;
    };
    glm::vec3 plainDiffuse(0.0f);
    for (const Case c : {Case{1.5f, 0.0f}, Case{1.5f, 1.0f}, Case{2.0f, 0.5f}}) {
        Scene scene;
        addMaterial(scene, base, kRoughness, 0.0f, "plane");
        scene.materials[0].ior = c.ior;
        scene.materials[0].clearcoatFactor = c.clearcoat;
        scene.materials[0].clearcoatRoughness = kCoatRoughness;
        const auto [meanDiffuse, meanSpecular] = directTermsFromAbove(scene, kSun, glm::vec3(0, 1, 0));

        const float f0 = std::pow((c.ior - 1.0f) / (c.ior + 1.0f), 2.0f);
        const float alpha = kRoughness * kRoughness, alphaC = kCoatRoughness * kCoatRoughness;
        const float baseScale = 1.0f - c.clearcoat * 0.04f;
        const glm::vec3 diffuse = kSun * base / kPi * baseScale;
        const float specular = kSun * (f0 / (kPi * alpha * alpha * 4.0f) * baseScale +
                                       c.clearcoat * 0.04f / (kPi * alphaC * alphaC * 4.0f));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(meanDiffuse[k], diffuse[k], 1e-4 * diffuse[k]) << "ior " << c.ior << ", coat " << c.clearcoat;
            EXPECT_NEAR(meanSpecular[k], specular, 1e-3 * specular) << "ior " << c.ior << ", coat " << c.clearcoat;
        }
        if (c.clearcoat == 0.0f) {
            plainDiffuse = glm::vec3(meanDiffuse);
        } else {
            EXPECT_NEAR(meanDiffuse.r / plainDiffuse.r, baseScale, 1e-5) << "the coat keeps 1 − cc·0.04 of the base";
        }
        std::printf("[ measured ] ior %.1f, coat %.1f: L_DD %.6f (closed form %.6f), L_DS %.6f (closed form %.6f)\n",
                    c.ior, c.clearcoat, meanDiffuse.r, diffuse.r, meanSpecular.r, specular);
    }
}

// The path tracer end to end with a sheen: a convex box of a white Lambertian base (specular
// weight 0) under a white sheen, all bounces, under a uniform white sky. Every visible point
// reflects E_s + (1 − E_s) = the sky's radiance, all of it into the diffuse terms.
TEST(ReferenceFurnace, SheenedConvexBoxUnderUniformSky) {
    Scene scene;
    addMaterial(scene, glm::vec3(1.0f), 0.7f, 0.0f, "sheened");
    scene.materials[0].specularFactor = 0.0f;
    scene.materials[0].sheenColorFactor = glm::vec3(1.0f);
    scene.materials[0].sheenRoughness = 0.5f;
    const BoxUnderSky box = boxUnderSky(scene, 1.0f, 128, true, [](const FirstHit&, const glm::vec3&) {});
    EXPECT_NEAR(box.diffuse, 1.0, 0.015);
    EXPECT_EQ(box.specular, 0.0) << "the sheen's light is diffuse";
    std::printf("[ measured ] sheened box under a white sky: diffuse %.4f, specular %.4f\n", box.diffuse, box.specular);
}

// A sheened plane seen from straight above (directTermsFromAbove: v = n in every pixel) under a
// sun 60° from the normal: h lies 30° from n, so D_s = (2 + 1/α_s)·0.5^(1/α_s)/(2π) and
// V_s = 1/(4(½ + 1 − ½)). Direct diffuse is E·(c/π·t_s + s_c·D_s·V_s), direct specular the
// base's GGX lobe × t_s, with t_s = 1 − max(s_c)·E_s(1, r_s) and E = sun·cos 60°.
TEST(ReferenceClosedForm, SheenedPlaneUnderAnObliqueSun) {
    constexpr float kSun = 3.0f;  // W/m²
    const glm::vec3 base(0.5f, 0.3f, 0.2f), sheenColor(0.9f, 0.5f, 0.2f);
    constexpr float kRoughness = 0.5f, kSheenRoughness = 0.6f;
    const glm::vec3 l(std::sin(kPi / 3.0f), std::cos(kPi / 3.0f), 0.0f);  // towards the sun
    glm::vec3 plainSpecular(0.0f);
    for (const bool withSheen : {false, true}) {
        Scene scene;
        addMaterial(scene, base, kRoughness, 0.0f, "plane");
        if (withSheen) {
            scene.materials[0].sheenColorFactor = sheenColor;
            scene.materials[0].sheenRoughness = kSheenRoughness;
        }
        const auto [meanDiffuse, meanSpecular] = directTermsFromAbove(scene, kSun, l);

        const float E = kSun * 0.5f;
        const float alphaS = kSheenRoughness * kSheenRoughness;
        const float sheenD = (2.0f + 1.0f / alphaS) * std::pow(0.5f, 1.0f / alphaS) / (2.0f * kPi);
        const float sheenV = 1.0f / 4.0f;
        const float scale = withSheen ? 1.0f - 0.9f * sheenAlbedo(1.0f, kSheenRoughness) : 1.0f;
        const glm::vec3 sheenF = withSheen ? sheenColor * sheenD * sheenV : glm::vec3(0.0f);
        const glm::vec3 diffuse = E * (base / kPi * scale + sheenF);
        const glm::vec3 n(0, 1, 0), v(0, 1, 0);
        const glm::vec3 specular = E * specularBrdf(n, v, l, glm::vec3(0.04f), kRoughness * kRoughness) * scale;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(meanDiffuse[k], diffuse[k], 1e-3 * diffuse[k]) << "sheen " << withSheen << ", channel " << k;
            EXPECT_NEAR(meanSpecular[k], specular[k], 1e-3 * specular[k]) << "sheen " << withSheen << ", channel " << k;
        }
        if (!withSheen) {
            plainSpecular = glm::vec3(meanSpecular);
        } else {
            EXPECT_NEAR(meanSpecular.g / plainSpecular.g, scale, 1e-5) << "the sheen keeps t_s of the base's specular";
            EXPECT_GT(sheenF.r / (base.r / kPi * scale), 0.1f) << "the sheen must show in the diffuse term";
        }
        std::printf("[ measured ] sheen %d: L_DD %.6f %.6f %.6f (closed form %.6f %.6f %.6f), L_DS %.6f (closed form %.6f)\n",
                    withSheen ? 1 : 0, meanDiffuse.r, meanDiffuse.g, meanDiffuse.b, diffuse.r, diffuse.g, diffuse.b,
                    meanSpecular.g, specular.g);
    }
}

// The sheen's factors reach the hit, clamped to their ranges (the extension's textures are not drawn).
TEST(ReferenceBrdf, SheenFactorsReachTheHit) {
    Material material;
    material.sheenColorFactor = glm::vec3(0.25f, 0.5f, 1.0f);
    material.sheenRoughness = 0.4f;
    const auto resolved = resolve(material);
    EXPECT_EQ(resolved->hit.sheenColor, glm::vec3(0.25f, 0.5f, 1.0f));
    EXPECT_EQ(resolved->hit.sheenRoughness, 0.4f);
    material.sheenColorFactor = glm::vec3(-0.5f, 0.5f, 3.0f);
    material.sheenRoughness = 2.0f;
    const auto clamped = resolve(material);
    EXPECT_EQ(clamped->hit.sheenColor, glm::vec3(0.0f, 0.5f, 1.0f));
    EXPECT_EQ(clamped->hit.sheenRoughness, 1.0f);
}

}  // namespace
}  // namespace lit::reference
