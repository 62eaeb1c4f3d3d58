#version 450 core
// Temporal anti-aliasing (TemporalAntialiasPass): this frame's jittered composite blended with the
// history of the frames before. Still camera: the history is read at the pixel's own texel and not
// clamped, so the image converges to the mean of the cycle's offsets over the pixel. Moving
// camera or nodes: the history is read where this pixel's surface point was (moved back by its
// node's motion, seen through the last frame's unjittered camera; bilinear) and clamped to this
// frame's 3 × 3 neighbourhood. One program
// each (LIT_TAA_MOVING 0 / 1): llvmpipe pays for both sides of a branch, and the still one reads
// two texels where the moving one reads twelve.
#include "frame.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outColor;

layout(binding = LIT_TEX_HDR_INPUT) uniform sampler2D current;
layout(binding = LIT_TEX_GBUFFER_DEPTH) uniform sampler2D depthImage;
layout(binding = LIT_TEX_TAA_HISTORY) uniform sampler2D history;

uniform float uWeight;  // this frame's share: 1 / frames in the history (1: this frame alone, 0: the history)

#if !LIT_TAA_MOVING
void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 color = texelFetch(current, pixel, 0).rgb;
    vec3 kept = texelFetch(history, pixel, 0).rgb;
    outColor = vec4(mix(kept, color, uWeight), 1.0);
}
#else
uniform mat4 uViewProjection;          // this frame's, without the jitter
uniform mat4 uPreviousViewProjection;  // the history's, without the jitter
// 1: nodes moved since the history's frame, and the G-buffer's motion target says how far each
// point did (world m); 0: it holds nothing of this frame.
uniform int uNodesMoved;
layout(binding = LIT_TEX_GBUFFER_MOTION) uniform sampler2D motionImage;
// The history's depth, and its camera's inverse (unjittered: half a pixel off at most).
layout(binding = LIT_TEX_TAA_HISTORY_DEPTH) uniform sampler2D historyDepth;
uniform mat4 uPreviousInverseViewProjection;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 color = texelFetch(current, pixel, 0).rgb;
    // The pixel's point (its jittered sample's depth; the background's at the far plane), where it
    // was before its node moved, seen by the unjittered cameras: the history pixel that saw it.
    float depth = texelFetch(depthImage, pixel, 0).r;
    vec2 uv = (vec2(pixel) + 0.5) * frame.viewport.zw;
    vec3 world = worldPositionFromDepth(uv, depth);
    vec3 was = world - float(uNodesMoved) * texelFetch(motionImage, pixel, 0).xyz;
    vec4 now = uViewProjection * vec4(world, 1.0);
    vec4 before = uPreviousViewProjection * vec4(was, 1.0);
    if (now.w <= 0.0 || before.w <= 0.0) {
        outColor = vec4(color, 1.0);
        return;
    }
    vec2 previousUv = uv + (before.xy / before.w - now.xy / now.w) * 0.5;
    if (any(lessThan(previousUv, vec2(0.0))) || any(greaterThan(previousUv, vec2(1.0)))) {
        outColor = vec4(color, 1.0);  // off the last frame
        return;
    }
    ivec2 last = ivec2(frame.viewport.xy) - 1;
    // A disocclusion: the history texel the point falls in saw another surface (one a moving node
    // covered, one the camera now sees past an edge), farther from the point than 2 % of its
    // distance plus twice the spacing of the surface's points from pixel to pixel (the history's
    // samples lie up to a pixel off): along each axis the nearer of the two neighbours' points,
    // which lies on the same surface where an edge runs by, the larger of the two axes, which is
    // large where the surface is seen at a slant. Its history is not this point's, and the frame is
    // shown alone there.
    ivec2 seenPixel = clamp(ivec2(previousUv * frame.viewport.xy), ivec2(0), last);
    vec4 seen = uPreviousInverseViewProjection *
                vec4((vec2(seenPixel) + 0.5) * frame.viewport.zw * 2.0 - 1.0,
                     texelFetch(historyDepth, seenPixel, 0).r * 2.0 - 1.0, 1.0);
    vec4 apart;  // +x, −x, +y, −y
    for (int i = 0; i < 4; ++i) {
        ivec2 q = clamp(pixel + ivec2(i == 0 ? 1 : (i == 1 ? -1 : 0), i == 2 ? 1 : (i == 3 ? -1 : 0)), ivec2(0), last);
        vec3 neighbour = worldPositionFromDepth((vec2(q) + 0.5) * frame.viewport.zw, texelFetch(depthImage, q, 0).r);
        apart[i] = distance(neighbour, world);
    }
    float spacing = max(min(apart.x, apart.y), min(apart.z, apart.w));
    if (distance(seen.xyz / seen.w, was) > 0.02 * distance(world, frame.cameraPosition.xyz) + 2.0 * spacing) {
        outColor = vec4(color, 1.0);
        return;
    }
    vec3 lo = color, hi = color;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            if (x == 0 && y == 0) continue;
            vec3 c = texelFetch(current, clamp(pixel + ivec2(x, y), ivec2(0), last), 0).rgb;
            lo = min(lo, c);
            hi = max(hi, c);
        }
    vec3 kept = clamp(textureLod(history, previousUv, 0.0).rgb, lo, hi);
    outColor = vec4(mix(kept, color, uWeight), 1.0);
}
#endif
