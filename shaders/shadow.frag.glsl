#version 450 core
// Shadow pass: alpha-masked materials cast cut-out shadows; transmissive sheets cast none (their
// light passes, docs/MATERIALS.md "Transmission").
#include "material.glsl"

in vec4 vUv;

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    if (materialIsSheet(m)) discard;
    if (m.modes.y == LIT_ALPHA_MASK && materialBaseColor(m, vUv).a < m.alpha.x) discard;
}
