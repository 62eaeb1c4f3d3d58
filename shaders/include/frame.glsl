// Per-frame uniforms and helpers shared by every pass that works in screen or world space.
#include "shared.h"

layout(std140, binding = LIT_UBO_FRAME) uniform FrameBlock {
    FrameUniforms frame;
};

// World position of a pixel from its window-space depth ([0,1]) and uv ([0,1]²).
vec3 worldPositionFromDepth(vec2 uv, float depth) {
    vec4 clip = vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 world = frame.inverseViewProjection * clip;
    return world.xyz / world.w;
}
