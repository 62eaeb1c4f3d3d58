#version 450 core
// The directional albedo table of the GGX specular lobe, read by cone.glsl's specularAlbedo:
//   E(n·v, roughness, F0) = ∫ f_s(l, v) (n·l) dl = F0·A + B
// with Schlick's F = F0·(1 − Fc) + Fc, Fc = (1 − v·h)^5, so
//   A = E_h[w·(1 − Fc)],  B = E_h[w·Fc],  w = G(l, v)·(v·h) / ((n·h)(n·v))
// estimated over half vectors h drawn from D(h)(n·h) (Karis 2013, "Real Shading in Unreal
// Engine 4": the split-sum table, here with Lit's height-correlated Smith G so that it matches
// the BRDF of the direct pass). Drawn once by ConeTracePass into a LIT_SPECULAR_ALBEDO_SIZE²
// RG16F target: x = n·v and y = perceptual roughness at texel centres (i + ½)/size.
#include "cone.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outAlbedo;

// Stratified in u.x (k/N) and u.y (radical inverse): 1024 samples leave < 0.5 % error at the
// roughest, most grazing texel.
const int kSamples = 1024;

void main() {
    float NdotV = vUv.x;
    float alpha = alphaFromRoughness(vUv.y);
    vec3 n = vec3(0.0, 0.0, 1.0);
    vec3 v = vec3(sqrt(max(1.0 - NdotV * NdotV, 0.0)), 0.0, NdotV);
    vec2 ab = vec2(0.0);
    for (int k = 0; k < kSamples; ++k) {
        vec2 u = vec2((float(k) + 0.5) / float(kSamples), radicalInverse(uint(k)));
        vec3 h = sampleGgxHalfVector(u, alpha);
        vec3 l;
        float w = ggxSampleWeight(n, v, h, alpha, l);
        float fc = pow(1.0 - clamp(dot(v, h), 0.0, 1.0), 5.0);
        ab += w * vec2(1.0 - fc, fc);
    }
    outAlbedo = vec4(ab / float(kSamples), 0.0, 1.0);
}
