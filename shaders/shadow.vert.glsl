#version 450 core
// Shadow pass: depth from the light's point of view.
#include "shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec2 inUv1;

layout(location = LIT_LOC_MODEL) uniform mat4 uModel;

layout(std140, binding = LIT_UBO_SHADOW_PASS) uniform ShadowBlock {
    ShadowPassUniforms shadowPass;
};

out vec4 vUv;  // xy TEXCOORD_0, zw TEXCOORD_1

void main() {
    vUv = vec4(inUv, inUv1);
    gl_Position = shadowPass.viewProjection * (uModel * vec4(inPosition, 1.0));
}
