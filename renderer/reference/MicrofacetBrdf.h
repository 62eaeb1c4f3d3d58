#pragma once
// The BRDF of shaders/include/brdf.glsl on the CPU, term for term, for the reference path tracer,
// plus the importance sampling the path tracer needs (which the shaders do not).
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (GGX D, eq. 33);
// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"
// (height-correlated Smith G2, eq. 99; G1, eq. 43); Heitz 2018, "Sampling the GGX Distribution of
// Visible Normals" (JCGT 7(4)); Schlick 1994 (Fresnel approximation).
// Roughness is glTF's perceptual roughness; α = roughness². Keep every function identical to its
// GLSL namesake: the GL consistency test (tests/gl/test_reference.cpp) compares the two renderers.
// The material model, with KHR_materials_ior, KHR_materials_specular, KHR_materials_sheen and
// KHR_materials_clearcoat, is docs/MATERIALS.md; the path tracer's Bsdf (ReferenceBsdf.h) puts
// these terms together. The sheen's terms and its albedo table are scene/SheenAlbedo.h's, shared
// with the rasterizer.

#include "scene/SheenAlbedo.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lit::reference {

inline constexpr float kPi = 3.14159265358979323846f;

// GGX / Trowbridge-Reitz normal distribution D(h).
inline float D_GGX(float NdotH, float alpha) {
    const float a2 = alpha * alpha;
    const float d = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}

// Height-correlated Smith masking-shadowing G2(l, v, h) for GGX (brdf.glsl's form).
inline float G_SmithGGXCorrelated(float NdotL, float NdotV, float alpha) {
    const float a2 = alpha * alpha;
    const float lambdaV = NdotL * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
    const float lambdaL = NdotV * std::sqrt(NdotL * NdotL * (1.0f - a2) + a2);
    return 2.0f * NdotL * NdotV / std::max(lambdaV + lambdaL, 1e-7f);
}

// Smith G1(v) for GGX: the masking of one direction (Heitz 2014, eq. 43 with Λ of GGX).
inline float G1_SmithGGX(float NdotV, float alpha) {
    const float a2 = alpha * alpha;
    return 2.0f * NdotV / (NdotV + std::sqrt(a2 + (1.0f - a2) * NdotV * NdotV));
}

// Schlick's Fresnel approximation F(v, h) = F0 + (F90 − F0)(1 − v·h)⁵.
inline glm::vec3 F_Schlick(const glm::vec3& f0, float f90, float VdotH) {
    const float f = std::pow(1.0f - std::clamp(VdotH, 0.0f, 1.0f), 5.0f);
    return f0 + (f90 - f0) * f;
}
// The same with F90 = 1 (every metal; a dielectric of specular weight 1).
inline glm::vec3 F_Schlick(const glm::vec3& f0, float VdotH) { return F_Schlick(f0, 1.0f, VdotH); }

// The clear coat's Fresnel term: a dielectric of η 1.5, Fc(x) = 0.04 + 0.96 (1 − x)⁵.
inline float F_Clearcoat(float VdotH) {
    const float f = std::pow(1.0f - std::clamp(VdotH, 0.0f, 1.0f), 5.0f);
    return 0.04f + 0.96f * f;
}
// The share of the base's light that the coat lets through: 1 − cc·Fc(n_c·v) (brdf.glsl).
inline float clearcoatBaseScale(float weight, float NdotV) { return 1.0f - weight * F_Clearcoat(NdotV); }

// A dielectric's normal-incidence reflectance (KHR_materials_ior, KHR_materials_specular):
// min(((η − 1)/(η + 1))² · k, 1) · s per channel. Computed in double so that η 1.5 gives exactly
// 0.04f (the metalness workflow's constant). η 0 is a mirror (F0 = 1), as the extension defines.
inline glm::vec3 dielectricF0(float ior, float specularFactor, const glm::vec3& specularColor) {
    const double r = (static_cast<double>(ior) - 1.0) / (static_cast<double>(ior) + 1.0);
    const auto f0 = static_cast<float>(r * r);
    return glm::min(f0 * specularColor, glm::vec3(1.0f)) * specularFactor;
}
// A dielectric's grazing reflectance: the specular weight s.
inline float dielectricF90(float specularFactor) { return specularFactor; }

// Metalness workflow: dielectrics reflect their dielectric F0 at normal incidence (0.04 for η 1.5,
// s = 1, k = 1), metals their base colour; at grazing dielectrics reach F90 = s, metals 1.
inline glm::vec3 specularF0(const glm::vec3& baseColor, float metalness, const glm::vec3& dielectricF0) {
    return glm::mix(dielectricF0, baseColor, metalness);
}
inline glm::vec3 specularF0(const glm::vec3& baseColor, float metalness) {
    return specularF0(baseColor, metalness, glm::vec3(0.04f));
}
// mix(F90_dielectric, 1, m), written so that F90_dielectric = 1 gives exactly 1.
inline float specularF90(float metalness, float dielectricF90) { return dielectricF90 + metalness * (1.0f - dielectricF90); }
inline glm::vec3 diffuseAlbedo(const glm::vec3& baseColor, float metalness) { return baseColor * (1.0f - metalness); }

// KHR_materials_transmission as a thin sheet (docs/MATERIALS.md, "Transmission"): light crossing
// the surface at cosθ to its normal passes straight through, weighted by
//   T = t · (1 − m) · c · (1 − F_Schlick(F0_d, F90_d, |cosθ|)),
// the dielectric's transmitted share of the light its specular lobe does not reflect, tinted by
// the base colour; the diffuse lobe keeps (1 − t) of its albedo (diffuseAlbedo × sheetDiffuseShare).
inline glm::vec3 transmittanceOfSheet(const glm::vec3& baseColor, float metalness, float transmission,
                                      const glm::vec3& dielectricF0, float dielectricF90, float cosTheta) {
    if (transmission <= 0.0f || metalness >= 1.0f) return glm::vec3(0.0f);
    return transmission * (1.0f - metalness) * baseColor *
           (glm::vec3(1.0f) - F_Schlick(dielectricF0, dielectricF90, std::abs(cosTheta)));
}
inline float sheetDiffuseShare(float transmission) { return 1.0f - transmission; }

// Roughness clamped so α never reaches 0 (brdf.glsl: a perfect mirror makes D a delta).
inline float alphaFromRoughness(float roughness) {
    const float r = std::clamp(roughness, 0.03f, 1.0f);
    return r * r;
}

// The specular microfacet BRDF f_s = D·G·F / (4 (n·l)(n·v)), with brdf.glsl's clamps.
inline glm::vec3 specularBrdf(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, const glm::vec3& f0, float f90,
                              float alpha) {
    const glm::vec3 h = glm::normalize(v + l);
    const float NdotL = std::max(glm::dot(n, l), 1e-4f);
    const float NdotV = std::max(glm::dot(n, v), 1e-4f);
    const float NdotH = std::max(glm::dot(n, h), 0.0f);
    const float VdotH = std::max(glm::dot(v, h), 0.0f);
    return D_GGX(NdotH, alpha) * G_SmithGGXCorrelated(NdotL, NdotV, alpha) * F_Schlick(f0, f90, VdotH) /
           (4.0f * NdotL * NdotV);
}
inline glm::vec3 specularBrdf(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, const glm::vec3& f0,
                              float alpha) {
    return specularBrdf(n, v, l, f0, 1.0f, alpha);
}

// The clear coat's microfacet lobe around the coat normal nc, without the coat weight cc:
// D(nc·h; α_c)·G2(nc·l, nc·v; α_c)·Fc(v·h) / (4 (nc·l)(nc·v)), with specularBrdf's clamps.
inline float clearcoatBrdf(const glm::vec3& nc, const glm::vec3& v, const glm::vec3& l, float alpha) {
    const glm::vec3 h = glm::normalize(v + l);
    const float NdotL = std::max(glm::dot(nc, l), 1e-4f);
    const float NdotV = std::max(glm::dot(nc, v), 1e-4f);
    const float NdotH = std::max(glm::dot(nc, h), 0.0f);
    const float VdotH = std::max(glm::dot(v, h), 0.0f);
    return D_GGX(NdotH, alpha) * G_SmithGGXCorrelated(NdotL, NdotV, alpha) * F_Clearcoat(VdotH) / (4.0f * NdotL * NdotV);
}

// The sheen lobe f_sheen = s_c·D_s(n·h; α_s)·V_s(n·l, n·v) (KHR_materials_sheen: Charlie
// distribution, Neubelt visibility), with direct_lighting.frag.glsl's clamps; `alpha` is
// sheenAlpha(r_s). Multiply by n·l.
inline glm::vec3 sheenBrdf(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, const glm::vec3& sheenColor,
                           float alpha) {
    const glm::vec3 h = glm::normalize(v + l);
    const float NdotL = std::max(glm::dot(n, l), 0.0f);
    const float NdotV = std::max(glm::dot(n, v), 1e-4f);
    const float NdotH = std::max(glm::dot(n, h), 0.0f);
    return sheenColor * (sheenDistribution(NdotH, alpha) * sheenVisibility(NdotL, NdotV));
}
// What a sheen leaves of the base under it: 1 − max(s_c)·E_s(n·v, r_s), exactly 1 without a sheen.
inline float sheenBaseScale(const glm::vec3& sheenColor, float sheenRoughness, float NdotV) {
    const float strength = std::max(sheenColor.r, std::max(sheenColor.g, sheenColor.b));
    return strength > 0.0f ? 1.0f - strength * sheenAlbedo(std::max(NdotV, 0.0f), sheenRoughness) : 1.0f;
}

// ---- Sampling (path tracer only) ----------------------------------------------------------

// An orthonormal basis around unit n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
struct Frame {
    glm::vec3 t, b, n;
    explicit Frame(const glm::vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float bb = n.x * n.y * a;
        t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * bb, -sign * n.x);
        b = glm::vec3(bb, sign + n.y * n.y * a, -n.y);
    }
    glm::vec3 toWorld(const glm::vec3& local) const { return t * local.x + b * local.y + n * local.z; }
    glm::vec3 toLocal(const glm::vec3& world) const { return {glm::dot(world, t), glm::dot(world, b), glm::dot(world, n)}; }
};

// Cosine-weighted hemisphere direction (local, z up) from u ∈ [0,1)²; pdf = cosθ/π.
inline glm::vec3 sampleCosineHemisphere(const glm::vec2& u) {
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
}

// A GGX visible normal for view direction v (local, z up, v.z > 0) from u ∈ [0,1)²
// (Heitz 2018, listing 1). Its density over h is G1(v)·max(v·h, 0)·D(h) / (n·v).
inline glm::vec3 sampleGgxVisibleNormal(const glm::vec3& v, float alpha, const glm::vec2& u) {
    const glm::vec3 vh = glm::normalize(glm::vec3(alpha * v.x, alpha * v.y, v.z));
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lensq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + vh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

// Density (per solid angle of l) of l = reflect(−v, h) with h from sampleGgxVisibleNormal:
// D_v(h) / (4 v·h) = G1(v)·D(h) / (4 n·v). n·v and n·h clamped as in specularBrdf.
inline float ggxVisibleNormalReflectionPdf(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, float alpha) {
    const glm::vec3 h = glm::normalize(v + l);
    const float NdotV = std::max(glm::dot(n, v), 1e-4f);
    const float NdotH = std::max(glm::dot(n, h), 0.0f);
    return G1_SmithGGX(NdotV, alpha) * D_GGX(NdotH, alpha) / (4.0f * NdotV);
}

}  // namespace lit::reference
