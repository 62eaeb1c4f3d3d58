// Geometric specular anti-aliasing (Tokuyoshi & Kaplanyan, "Improved Geometric Specular
// Antialiasing", 2019): a pixel sees its surface's normal spread over its footprint, so a lobe
// narrower than that spread is under-sampled at any one point of the pixel (a sub-pixel
// highlight that comes and goes as the camera moves). The spread, from the screen-space
// derivatives of the normal, widens GGX's α² by 2σ²(|∂n/∂x|² + |∂n/∂y|²), capped at κ, for
// the direct light's lobes (brdf.glsl widenedRoughness; docs/MATERIALS.md, "Specular
// anti-aliasing").
#include "frame.glsl"

// κ: the most α² a footprint adds, so silhouettes, where the normal swings across a pixel, do
// not turn a mirror matte.
const float kFootprintMaxAlphaSquared = 0.18;

// The α² a pixel's footprint adds for unit normal `n` (frame.exposure.z: σ², the pixel filter's
// variance in pixels²; 0 turns it off). Call it in uniform control flow: it takes derivatives.
float footprintAlphaSquared(vec3 n) {
    vec3 dx = dFdx(n), dy = dFdy(n);
    return min(2.0 * frame.exposure.z * (dot(dx, dx) + dot(dy, dy)), kFootprintMaxAlphaSquared);
}
