// Microfacet BRDF terms, named after the math.
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (GGX D, eq. 33);
// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"
// (height-correlated Smith G2, eq. 99); Schlick 1994 (Fresnel approximation).
// Roughness is glTF's perceptual roughness; α = roughness².

const float PI = 3.14159265358979323846;

// GGX / Trowbridge-Reitz normal distribution D(h).
float D_GGX(float NdotH, float alpha) {
    float a2 = alpha * alpha;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// Height-correlated Smith masking-shadowing G2(l, v, h) for GGX.
float G_SmithGGXCorrelated(float NdotL, float NdotV, float alpha) {
    float a2 = alpha * alpha;
    float lambdaV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float lambdaL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    // G2 = 2 NdotL NdotV / (lambdaV + lambdaL) in this form (Heitz eq. 99 rearranged).
    return 2.0 * NdotL * NdotV / max(lambdaV + lambdaL, 1e-7);
}

// Schlick's Fresnel approximation F(v, h) between F0 (normal incidence) and F90 (grazing).
vec3 F_Schlick(vec3 f0, float f90, float VdotH) {
    float f = pow(1.0 - clamp(VdotH, 0.0, 1.0), 5.0);
    return f0 + (f90 - f0) * f;
}

// Metalness workflow (docs/MATERIALS.md): dielectrics reflect their F0 (4 % without
// KHR_materials_ior / _specular) and F90 at grazing, metals their base colour and 1.
vec3 specularF0(vec3 baseColor, float metalness, vec3 dielectricF0) { return mix(dielectricF0, baseColor, metalness); }
float specularF90(float metalness, float dielectricF90) { return mix(dielectricF90, 1.0, metalness); }
vec3 diffuseAlbedo(vec3 baseColor, float metalness) { return baseColor * (1.0 - metalness); }

// KHR_materials_transmission as a thin sheet (docs/MATERIALS.md, "Transmission"; MicrofacetBrdf.h
// transmittanceOfSheet): what passes straight through at cosθ to the normal,
// T = t·(1 − m)·c·(1 − F_Schlick(F0_d, F90_d, |cosθ|)); the diffuse lobe keeps (1 − t) of its albedo.
vec3 transmittanceOfSheet(vec3 baseColor, float metalness, float transmission, vec3 dielectricF0, float dielectricF90,
                          float cosTheta) {
    if (transmission <= 0.0 || metalness >= 1.0) return vec3(0.0);
    return transmission * (1.0 - metalness) * baseColor *
           (vec3(1.0) - F_Schlick(dielectricF0, dielectricF90, abs(cosTheta)));
}

// Clamp roughness so α never reaches 0 (a perfect mirror makes D a delta: infinite highlights).
float alphaFromRoughness(float roughness) {
    float r = clamp(roughness, 0.03, 1.0);
    return r * r;
}

// Perceptual roughness widened by `footprint`, an increment of α² = r⁴ (specular anti-aliasing,
// specular_footprint.glsl): r = (r⁴ + footprint)^¼, at most 1.
float widenedRoughness(float roughness, float footprint) {
    float alphaSquared = roughness * roughness * roughness * roughness;
    return sqrt(sqrt(min(alphaSquared + footprint, 1.0)));
}

// The specular microfacet BRDF f_s = D·G·F / (4 (n·l)(n·v)).
vec3 specularBrdf(vec3 n, vec3 v, vec3 l, vec3 f0, float f90, float alpha) {
    vec3 h = normalize(v + l);
    float NdotL = max(dot(n, l), 1e-4);
    float NdotV = max(dot(n, v), 1e-4);
    float NdotH = max(dot(n, h), 0.0);
    float VdotH = max(dot(v, h), 0.0);
    return D_GGX(NdotH, alpha) * G_SmithGGXCorrelated(NdotL, NdotV, alpha) * F_Schlick(f0, f90, VdotH) /
           (4.0 * NdotL * NdotV);
}

// KHR_materials_sheen (docs/MATERIALS.md; scene/SheenAlbedo.h on the CPU): the Charlie
// distribution and Neubelt & Pettineo's visibility; α_s of perceptual roughness clamped to 0.07.
float sheenAlpha(float roughness) {
    float r = clamp(roughness, 0.07, 1.0);
    return r * r;
}
float D_Charlie(float NdotH, float alpha) {
    float invAlpha = 1.0 / alpha;
    float sin2 = max(1.0 - NdotH * NdotH, 0.0);
    return (2.0 + invAlpha) * pow(sin2, 0.5 * invAlpha) / (2.0 * PI);
}
float V_Neubelt(float NdotL, float NdotV) { return 1.0 / max(4.0 * (NdotL + NdotV - NdotL * NdotV), 1e-6); }

// KHR_materials_clearcoat: a dielectric coat of η 1.5 (F0 0.04) over the base. The base's light
// is scaled by 1 − weight · Fc(n·v) (clearcoatBaseScale), and the coat adds its GGX lobe
// weight · D·G·Fc / (4 (n·l)(n·v)) (docs/MATERIALS.md).
const vec3 kClearcoatF0 = vec3(0.04);
float clearcoatBaseScale(float weight, float NdotV) { return 1.0 - weight * F_Schlick(kClearcoatF0, 1.0, NdotV).x; }
// The hemispherical mean of Fc under a cosine-weighted view: 0.04 + 0.96 · ∫(1 − μ)⁵ 2μ dμ = 0.04 + 0.96/21.
const float kClearcoatMeanFresnel = 0.04 + 0.96 / 21.0;
