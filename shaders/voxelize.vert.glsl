#version 450 core
// Voxelization, vertex stage: world-space attributes only. The geometry shader picks each
// triangle's projection (its dominant axis), so nothing is projected here.
#include "shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec2 inUv1;

layout(location = LIT_LOC_MODEL) uniform mat4 uModel;
layout(location = LIT_LOC_NORMAL_MATRIX) uniform mat4 uNormalMatrix;

out VoxelVertex {
    vec3 worldPosition;  // metres
    vec3 worldNormal;    // not normalized
    vec4 uv;             // xy TEXCOORD_0, zw TEXCOORD_1
} vs;

void main() {
    vs.worldPosition = (uModel * vec4(inPosition, 1.0)).xyz;
    vs.worldNormal = mat3(uNormalMatrix) * inNormal;
    vs.uv = vec4(inUv, inUv1);
    gl_Position = vec4(vs.worldPosition, 1.0);
}
