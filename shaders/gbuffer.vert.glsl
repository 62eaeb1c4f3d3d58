#version 450 core
// G-buffer pass: transforms scene geometry to clip space and passes world-space attributes.
#include "frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec2 inUv1;
layout(location = 3) in vec4 inTangent;

layout(location = LIT_LOC_MODEL) uniform mat4 uModel;
layout(location = LIT_LOC_NORMAL_MATRIX) uniform mat4 uNormalMatrix;
// The model matrix of the last frame, set where nodes moved (GBufferPass): the motion target.
layout(location = LIT_LOC_PREVIOUS_MODEL) uniform mat4 uPreviousModel;

out VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    vec4 uv;  // xy TEXCOORD_0, zw TEXCOORD_1 (material.glsl materialUv)
    vec4 worldTangent;
    vec3 worldMotion;
} vs;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vs.worldPosition = world.xyz;
    vs.worldMotion = world.xyz - (uPreviousModel * vec4(inPosition, 1.0)).xyz;
    vs.worldNormal = mat3(uNormalMatrix) * inNormal;
    vs.worldTangent = vec4(mat3(uModel) * inTangent.xyz, inTangent.w);
    vs.uv = vec4(inUv, inUv1);
    gl_Position = frame.viewProjection * world;
}
