// Geometric specular anti-aliasing (Tokuyoshi & Kaplanyan, "Improved Geometric Specular
// Antialiasing", 2019): a pixel sees its surface's normal spread over its footprint, so a lobe
// narrower than that spread is under-sampled at any one point of the pixel (a sub-pixel
// highlight that comes and goes as the camera moves). The spread, from the screen-space
// derivatives of the normal, widens GGX's α² by 2σ²(|∂n/∂x|² + |∂n/∂y|²), capped at κ, for
// the direct light's lobes (brdf.glsl widenedRoughness; docs/MATERIALS.md, "Specular
// anti-aliasing").
#include "frame.glsl"

// σ²: the pixel filter's variance, pixels² (the paper's value; a one-pixel box's 1/12 left a
// highlight's total varying by 16 % with where the pixels fall, docs/MATERIALS.md).
const float kFootprintVariance = 0.25;
// κ: the most α² a footprint adds, so silhouettes, where the normal swings across a pixel, do
// not turn a mirror matte.
const float kFootprintMaxAlphaSquared = 0.18;

// The α² a pixel's footprint adds for unit normal `n`; 0 with output.specularAntialiasing off
// (LIT_FRAME_SPECULAR_ANTIALIASING). Call it in uniform control flow: it takes derivatives.
float footprintAlphaSquared(vec3 n) {
    vec3 dx = dFdx(n), dy = dFdy(n);
    float on = (frame.counts.w & LIT_FRAME_SPECULAR_ANTIALIASING) != 0 ? 1.0 : 0.0;
    return on * min(2.0 * kFootprintVariance * (dot(dx, dx) + dot(dy, dy)), kFootprintMaxAlphaSquared);
}
