#version 450 core
// Selection outline (OverlayPass): a pixel that does not show an outlined node but lies within
// kOutlineRadius pixels of one that does gets the outline colour, the active node's colour when
// one of those is active (as in Blender); every other pixel is discarded. The outline therefore
// sits outside the objects' visible silhouettes and never covers one of them.
#include "shared.h"

// r: node index + 1 (0 = background), g: the primitive of its mesh.
layout(binding = LIT_TEX_GBUFFER_ID) uniform usampler2D nodeIds;

// Per node ID: 0 not outlined, 1 selected, 2 active. IDs past the end are not outlined.
layout(std430, binding = LIT_SSBO_OUTLINE_CLASSES) readonly buffer OutlineClasses {
    uint outlineClass[];
};

uniform vec4 uActiveColor;    // linear RGBA
uniform vec4 uSelectedColor;  // linear RGBA
// A picked primitive (ViewportOverlay::activePrimitive): of node ID uPrimitiveNode (0: none) only
// primitive uPrimitive is outlined, as active.
uniform uint uPrimitiveNode;
uniform uint uPrimitive;

layout(location = 0) out vec4 outColor;

const int kOutlineRadius = LIT_OUTLINE_RADIUS;  // pixels

uint classOf(uvec2 id) {
    if (uPrimitiveNode != 0u && id.r == uPrimitiveNode) return id.g == uPrimitive ? 2u : 0u;
    return id.r < uint(outlineClass.length()) ? outlineClass[id.r] : 0u;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (classOf(texelFetch(nodeIds, pixel, 0).rg) != 0u) discard;
    ivec2 size = textureSize(nodeIds, 0);
    uint best = 0u;
    for (int dy = -kOutlineRadius; dy <= kOutlineRadius; ++dy) {
        for (int dx = -kOutlineRadius; dx <= kOutlineRadius; ++dx) {
            // A disc of radius 2 (the 5×5 square without its corners): rounder corners.
            if (dx * dx + dy * dy > kOutlineRadius * kOutlineRadius + 1) continue;
            ivec2 q = pixel + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            best = max(best, classOf(texelFetch(nodeIds, q, 0).rg));
        }
    }
    if (best == 0u) discard;
    outColor = best == 2u ? uActiveColor : uSelectedColor;
}
