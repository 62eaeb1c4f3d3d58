#pragma once
// The BRDF of one surface point as the path tracer evaluates, samples and weighs it: the material
// model of docs/MATERIALS.md (MicrofacetBrdf.h's terms) with its four lobes,
//   f = (f_sheen + f_base · t_s) · (1 − cc·Fc(n_c·v)) + cc · f_coat,   f_base = f_diffuse + f_specular,
//   t_s = 1 − max(s_c)·E_s(n·v, r_s)   (what the sheen leaves of the base; 1 without a sheen),
// each lobe with its own cosine (f_sheen and f_base × n·l, f_coat × n_c·l). Split by lobe for
// Lit's terms: the base's diffuse lobe and the sheen are "diffuse", the base's specular lobe and
// the coat are "specular". Sampling draws one lobe (cosine hemisphere around n, which also covers
// the sheen, GGX visible normals around n with α, GGX visible normals around n_c with α_c) and
// pdf() is the density of the whole mixture.

#include "reference/MicrofacetBrdf.h"
#include "reference/ReferenceScene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lit::reference {

inline float bsdfLuminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline float bsdfMaxComponent(const glm::vec3& c) { return std::max(c.r, std::max(c.g, c.b)); }

// gbuffer.glsl shadingNormal: a normal facing away from v is bent just past perpendicular.
inline glm::vec3 shadingNormal(const glm::vec3& n, const glm::vec3& v) {
    const float nv = glm::dot(n, v);
    return nv < 0.0f ? glm::normalize(n - v * (nv * 1.01f)) : n;
}

// Light reflected towards v at a surface, or a path weight, split by lobe (diffuse, specular).
struct Split {
    glm::vec3 diffuse{0.0f}, specular{0.0f};
};

struct Bsdf {
    glm::vec3 n{0.0f}, v{0.0f}, ng{0.0f};
    glm::vec3 albedo{0.0f}, f0{0.0f};
    float f90 = 1.0f;
    float alpha = 1.0f;
    // The clear coat: weight cc (0: no coat lobe), its normal and α, and the base's share
    // 1 − cc·Fc(n_c·v) (exactly 1 without a coat).
    glm::vec3 nc{0.0f};
    float coat = 0.0f, coatAlpha = 1.0f, baseScale = 1.0f;
    // The sheen: colour s_c (0: no sheen lobe), α_s, and what it leaves of the base under it,
    // sheenScale = 1 − max(s_c)·E_s(n·v, r_s) (exactly 1 without a sheen). The sheen lies under the
    // coat: baseScale applies to it, sheenScale does not.
    glm::vec3 sheen{0.0f};
    float sheenAlpha = 1.0f, sheenScale = 1.0f;
    // Chances of sampling each lobe: GGX base, GGX coat, and the rest the cosine lobe.
    float specularProbability = 0.0f, coatProbability = 0.0f, diffuseProbability = 1.0f;

    Bsdf(const SurfaceHit& hit, const glm::vec3& view) {
        v = view;
        n = shadingNormal(hit.normal, v);
        ng = hit.geometricNormal;
        // A transmissive sheet's diffuse lobe keeps (1 − t) of the albedo; the rest passes through
        // (PathTracer, ReferenceScene::transmittance).
        albedo = diffuseAlbedo(hit.baseColor, hit.metalness) * sheetDiffuseShare(hit.transmission);
        f0 = specularF0(hit.baseColor, hit.metalness, hit.dielectricF0);
        f90 = specularF90(hit.metalness, hit.dielectricF90);
        alpha = alphaFromRoughness(hit.roughness);
        float coatShare = 0.0f;
        if (hit.clearcoat > 0.0f) {
            coat = hit.clearcoat;
            nc = shadingNormal(glm::dot(hit.clearcoatNormal, hit.clearcoatNormal) > 0.0f ? hit.clearcoatNormal : hit.normal, v);
            coatAlpha = alphaFromRoughness(hit.clearcoatRoughness);
            const float NcdotV = std::max(glm::dot(nc, v), 0.0f);
            coatShare = coat * F_Clearcoat(NcdotV);
            baseScale = clearcoatBaseScale(coat, NcdotV);
        }
        const float NdotV = std::max(glm::dot(n, v), 0.0f);
        float sheenShare = 0.0f;
        if (bsdfMaxComponent(hit.sheenColor) > 0.0f) {
            sheen = hit.sheenColor;
            sheenAlpha = lit::sheenAlpha(hit.sheenRoughness);
            sheenScale = sheenBaseScale(sheen, hit.sheenRoughness, NdotV);
            sheenShare = bsdfLuminance(sheen) * sheenAlbedo(NdotV, hit.sheenRoughness) * baseScale;
        }
        // Lobe choice by each lobe's rough share of the reflected energy: the Fresnel factors at
        // the view angle and the diffuse albedo, the base's lobes times the sheen's t_s and the
        // coat's 1 − cc·Fc. The cosine lobe also draws the sheen's directions: its share adds the
        // sheen's directional albedo lum(s_c)·E_s(n·v) (under the coat).
        const float specular = bsdfLuminance(F_Schlick(f0, f90, NdotV)) * sheenScale * baseScale;
        const float diffuse = bsdfLuminance(albedo) * sheenScale * baseScale + sheenShare;
        const float total = specular + diffuse + coatShare;
        if (total > 0.0f) {
            specularProbability = specular / total;
            coatProbability = coatShare / total;
        }
        diffuseProbability = std::max(0.0f, 1.0f - specularProbability - coatProbability);
    }

    bool hasCoat() const { return coat > 0.0f; }
    bool hasSheen() const { return bsdfMaxComponent(sheen) > 0.0f; }

    // The diffuse share: the base's Lambert lobe × t_s plus the sheen lobe, both scaled by the
    // coat's 1 − cc·Fc; multiply by n·l.
    glm::vec3 diffuse(const glm::vec3& l) const {
        if (glm::dot(n, l) <= 0.0f) return glm::vec3(0.0f);
        glm::vec3 f = albedo / kPi * sheenScale * baseScale;
        if (hasSheen()) f += sheenLobe(l);
        return f;
    }
    // The base's specular lobe × t_s × (1 − cc·Fc); multiply by n·l.
    glm::vec3 specular(const glm::vec3& l) const {
        return glm::dot(n, l) > 0.0f ? specularBrdf(n, v, l, f0, f90, alpha) * sheenScale * baseScale : glm::vec3(0.0f);
    }
    // The sheen lobe alone, s_c·D_s·V_s × (1 − cc·Fc) (part of diffuse()); multiply by n·l.
    glm::vec3 sheenLobe(const glm::vec3& l) const {
        return hasSheen() && glm::dot(n, l) > 0.0f ? sheenBrdf(n, v, l, sheen, sheenAlpha) * baseScale : glm::vec3(0.0f);
    }
    // The coat lobe with its weight, cc·f_coat; multiply by n_c·l.
    glm::vec3 coatLobe(const glm::vec3& l) const {
        return hasCoat() && glm::dot(nc, l) > 0.0f ? glm::vec3(coat * clearcoatBrdf(nc, v, l, coatAlpha)) : glm::vec3(0.0f);
    }

    // f·cos / pdf split by lobe: the weight of a direction l drawn with density pdf.
    Split weight(const glm::vec3& l, float pdf) const {
        Split s;
        const float NdotL = glm::dot(n, l);
        s.diffuse = diffuse(l) * (NdotL / pdf);
        s.specular = specular(l) * (NdotL / pdf);
        if (hasCoat()) s.specular += coatLobe(l) * (glm::dot(nc, l) / pdf);
        return s;
    }

    // True when some lobe reflects light towards l (so that light from l counts).
    bool above(const glm::vec3& l) const { return glm::dot(n, l) > 0.0f || (hasCoat() && glm::dot(nc, l) > 0.0f); }

    // Density (per solid angle) with which sample() draws l: the three sampled lobes' mixture (the
    // cosine lobe stands for the Lambert lobe and the sheen, both on n's hemisphere). Each GGX
    // lobe's density counts wherever its reflected directions land (n·h > 0), also below the other
    // normal's horizon, because sample() keeps a direction any lobe reflects into.
    float pdf(const glm::vec3& l) const {
        const float NdotL = glm::dot(n, l);
        float p = 0.0f;
        if (NdotL > 0.0f) {
            p = diffuseProbability * NdotL / kPi + specularProbability * ggxVisibleNormalReflectionPdf(n, v, l, alpha);
        } else if (hasCoat() && glm::dot(nc, l) > 0.0f && specularProbability > 0.0f &&
                   glm::dot(n, glm::normalize(v + l)) > 0.0f) {
            p = specularProbability * ggxVisibleNormalReflectionPdf(n, v, l, alpha);
        }
        if (hasCoat() && above(l) && coatProbability > 0.0f && glm::dot(nc, glm::normalize(v + l)) > 0.0f)
            p += coatProbability * ggxVisibleNormalReflectionPdf(nc, v, l, coatAlpha);
        return p;
    }

    // False for a surface that reflects nothing (black, no specular, no sheen and no coat): the
    // path ends.
    bool reflects() const {
        return bsdfMaxComponent(albedo) > 0.0f || bsdfMaxComponent(f0) > 0.0f || f90 > 0.0f ||
               hasSheen() || hasCoat();
    }

    // A direction drawn from pdf() with `choice` ∈ [0,1) picking the lobe and u ∈ [0,1)² the
    // direction in it; false when it falls below the geometric surface or where no lobe
    // reflects (the path ends).
    bool sample(float choice, const glm::vec2& u, glm::vec3& l) const {
        if (choice < specularProbability) {
            l = reflectGgx(n, alpha, u);
        } else if (choice < specularProbability + coatProbability) {
            l = reflectGgx(nc, coatAlpha, u);
        } else {
            l = Frame(n).toWorld(sampleCosineHemisphere(u));
        }
        return above(l) && glm::dot(ng, l) > 0.0f;
    }

private:
    // v reflected about a GGX visible normal of the lobe around `normal` with roughness `a`.
    glm::vec3 reflectGgx(const glm::vec3& normal, float a, const glm::vec2& u) const {
        const Frame frame(normal);
        glm::vec3 localV = frame.toLocal(v);
        localV.z = std::max(localV.z, 1e-4f);
        localV = glm::normalize(localV);
        const glm::vec3 h = frame.toWorld(sampleGgxVisibleNormal(localV, a, u));
        return 2.0f * glm::dot(v, h) * h - v;
    }
};

}  // namespace lit::reference
