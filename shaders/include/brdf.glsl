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

// Schlick's Fresnel approximation F(v, h).
vec3 F_Schlick(vec3 f0, float VdotH) {
    float f = pow(1.0 - clamp(VdotH, 0.0, 1.0), 5.0);
    return f0 + (1.0 - f0) * f;
}

// Metalness workflow: dielectrics reflect 4% at normal incidence, metals their base colour.
vec3 specularF0(vec3 baseColor, float metalness) { return mix(vec3(0.04), baseColor, metalness); }
vec3 diffuseAlbedo(vec3 baseColor, float metalness) { return baseColor * (1.0 - metalness); }

// Clamp roughness so α never reaches 0 (a perfect mirror makes D a delta: infinite highlights).
float alphaFromRoughness(float roughness) {
    float r = clamp(roughness, 0.03, 1.0);
    return r * r;
}

// The specular microfacet BRDF f_s = D·G·F / (4 (n·l)(n·v)).
vec3 specularBrdf(vec3 n, vec3 v, vec3 l, vec3 f0, float alpha) {
    vec3 h = normalize(v + l);
    float NdotL = max(dot(n, l), 1e-4);
    float NdotV = max(dot(n, v), 1e-4);
    float NdotH = max(dot(n, h), 0.0);
    float VdotH = max(dot(v, h), 0.0);
    return D_GGX(NdotH, alpha) * G_SmithGGXCorrelated(NdotL, NdotV, alpha) * F_Schlick(f0, VdotH) /
           (4.0 * NdotL * NdotV);
}
