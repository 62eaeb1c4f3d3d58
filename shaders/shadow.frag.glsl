#version 450 core
// Shadow pass: only alpha-masked materials need a fragment shader (cut-outs cast cut-out shadows).
#include "material.glsl"

in vec2 vUv;

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    if (m.modes.y == LIT_ALPHA_MASK && materialBaseColor(m, vUv).a < m.alpha.x) discard;
}
