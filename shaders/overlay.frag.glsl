#version 450 core
// Overlay lines (OverlayPass). The output target has no depth buffer: depth-tested lines compare
// their own depth with the G-buffer's here, and where the scene is in front they are drawn with
// LIT_HIDDEN_LINE_OPACITY × their alpha instead of being dropped, so a light inside a wall stays
// visible.
#include "frame.glsl"

layout(binding = LIT_TEX_GBUFFER_DEPTH) uniform sampler2D gbufferDepth;

uniform int uDepthTested;  // 1: faint where the scene hides the line; 0: always at full opacity

in vec4 vColor;
layout(location = 0) out vec4 outColor;

// Distance (m) along the view axis of a window-space depth, for a perspective projection (finite
// or infinite far plane): z_ndc = (P22·z + P32) / −z  ⇒  −z = P32 / (z_ndc + P22).
float viewDistance(float windowDepth) {
    float ndc = windowDepth * 2.0 - 1.0;
    return frame.projection[3][2] / (ndc + frame.projection[2][2]);
}

void main() {
    float alpha = vColor.a;
    if (uDepthTested != 0) {
        float sceneDepth = texelFetch(gbufferDepth, ivec2(gl_FragCoord.xy), 0).r;
        // Lines lying on a surface must not flicker between hidden and visible: they count as
        // hidden only when 0.2 % + 1 mm farther than the scene.
        if (sceneDepth < 1.0) {
            float scene = viewDistance(sceneDepth);
            float line = viewDistance(gl_FragCoord.z);
            if (line > scene * 1.002 + 0.001) alpha *= LIT_HIDDEN_LINE_OPACITY;
        }
    }
    outColor = vec4(vColor.rgb, alpha);
}
