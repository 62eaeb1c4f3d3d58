#version 450 core
// Transmissive sheets into the 2D shadow maps' sheet layers (ShadowPass, shadow_sheet.frag.glsl).
#include "shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec2 inUv1;

layout(location = LIT_LOC_MODEL) uniform mat4 uModel;
layout(location = LIT_LOC_NORMAL_MATRIX) uniform mat4 uNormalMatrix;

layout(std140, binding = LIT_UBO_SHADOW_PASS) uniform ShadowBlock {
    ShadowPassUniforms shadowPass;
};

out vec4 vUv;  // xy TEXCOORD_0, zw TEXCOORD_1
out vec3 vWorldPosition;
out vec3 vWorldNormal;

void main() {
    vUv = vec4(inUv, inUv1);
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = mat3(uNormalMatrix) * inNormal;
    gl_Position = shadowPass.viewProjection * world;
}
