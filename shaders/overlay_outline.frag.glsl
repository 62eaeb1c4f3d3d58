#version 450 core
// Selection outline (OverlayPass): a pixel that does not show the highlighted node but lies within
// kOutlineRadius pixels of one that does gets the outline colour; every other pixel is discarded.
// The outline therefore sits outside the object's visible silhouette and never covers the object.
#include "shared.h"

layout(binding = LIT_TEX_GBUFFER_ID) uniform usampler2D nodeIds;  // node index + 1, 0 = background

uniform uint uNodeId;  // the highlighted node's ID (index + 1)
uniform vec4 uColor;   // linear RGBA

layout(location = 0) out vec4 outColor;

const int kOutlineRadius = LIT_OUTLINE_RADIUS;  // pixels

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(nodeIds, pixel, 0).r == uNodeId) discard;
    ivec2 size = textureSize(nodeIds, 0);
    for (int dy = -kOutlineRadius; dy <= kOutlineRadius; ++dy) {
        for (int dx = -kOutlineRadius; dx <= kOutlineRadius; ++dx) {
            // A disc of radius 2 (the 5×5 square without its corners): rounder corners.
            if (dx * dx + dy * dy > kOutlineRadius * kOutlineRadius + 1) continue;
            ivec2 q = pixel + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            if (texelFetch(nodeIds, q, 0).r == uNodeId) {
                outColor = uColor;
                return;
            }
        }
    }
    discard;
}
