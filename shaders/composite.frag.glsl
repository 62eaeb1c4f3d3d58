#version 450 core
// Composite pass: writes the linear HDR image of the chosen view.
//   final = L_DD + L_ID + L_DS + L_IS (the terms that are switched on)
// Data views (albedo, normal, roughness/metalness, shadow map) write display values in [0,1]
// and set uDataView so the tone mapper shows them as they are. The voxel views are drawn by
// VoxelDebugPass instead. Background pixels of the final view show the sky (sky.glsl).
#include "frame.glsl"
#include "gbuffer.glsl"
#include "sky.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outColor;

layout(binding = LIT_TEX_TERM_DIRECT_DIFFUSE) uniform sampler2D termDirectDiffuse;
layout(binding = LIT_TEX_TERM_DIRECT_SPECULAR) uniform sampler2D termDirectSpecular;
layout(binding = LIT_TEX_TERM_INDIRECT_DIFFUSE) uniform sampler2D termIndirectDiffuse;
layout(binding = LIT_TEX_TERM_INDIRECT_SPECULAR) uniform sampler2D termIndirectSpecular;
layout(binding = LIT_TEX_DEBUG_INPUT) uniform sampler2DArray debugShadowMap;

// 1: the final view's program (PostPass::composite picks it for View::Final), without the other
// views' branches: llvmpipe runs a uniform branch's body with every lane masked off, and those
// branches cost the post pass 10 of its 30 ms at 1280×720 (docs/PERFORMANCE.md, "llvmpipe").
#ifndef LIT_COMPOSITE_FINAL_ONLY
#define LIT_COMPOSITE_FINAL_ONLY 0
#endif

uniform ivec4 uTerms;        // which of DD, ID, DS, IS are on (1/0)
uniform int uShadowLayer;    // layer of the 2D shadow array for the shadow-map view (-1: none)

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int view = frame.counts.y;
    vec3 dd = texelFetch(termDirectDiffuse, pixel, 0).rgb;
    vec3 ds = texelFetch(termDirectSpecular, pixel, 0).rgb;
    vec3 id = texelFetch(termIndirectDiffuse, pixel, 0).rgb;
    vec3 is = texelFetch(termIndirectSpecular, pixel, 0).rgb;
    vec3 color = vec3(0.0);
    if (view == LIT_VIEW_FINAL) {
        color = float(uTerms.x) * dd + float(uTerms.y) * id + float(uTerms.z) * ds + float(uTerms.w) * is;
        if (texelFetch(gbufferDepth, pixel, 0).r >= 1.0) {
            vec3 farPoint = worldPositionFromDepth(gl_FragCoord.xy * frame.viewport.zw, 1.0);
            color = skyRadiance(farPoint - frame.cameraPosition.xyz);
        }
    }
#if !LIT_COMPOSITE_FINAL_ONLY
    else if (view == LIT_VIEW_DIRECT_DIFFUSE) {
        color = dd;
    } else if (view == LIT_VIEW_INDIRECT_DIFFUSE) {
        color = id;
    } else if (view == LIT_VIEW_DIRECT_SPECULAR) {
        color = ds;
    } else if (view == LIT_VIEW_INDIRECT_SPECULAR) {
        color = is;
    } else if (view == LIT_VIEW_ALBEDO) {
        color = texelFetch(gbufferAlbedo, pixel, 0).rgb;
    } else if (view == LIT_VIEW_NORMAL) {
        float depth = texelFetch(gbufferDepth, pixel, 0).r;
        color = depth < 1.0 ? texelFetch(gbufferNormal, pixel, 0).xyz * 0.5 + 0.5 : vec3(0.0);
    } else if (view == LIT_VIEW_ROUGHNESS_METALNESS) {
        float depth = texelFetch(gbufferDepth, pixel, 0).r;
        color = depth < 1.0 ? vec3(texelFetch(gbufferMaterial, pixel, 0).rg, 0.0) : vec3(0.0);
    } else if (view == LIT_VIEW_SHADOW_MAP) {
        // Depth of the chosen light's shadow map, letterboxed into the viewport as a square.
        vec2 size = frame.viewport.xy;
        float side = min(size.x, size.y);
        vec2 uv = (gl_FragCoord.xy - 0.5 * (size - side)) / side;
        if (uShadowLayer >= 0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))) {
            float d = texture(debugShadowMap, vec3(uv, float(uShadowLayer))).r;
            // Stretch the far end, where perspective depth crowds, so shapes stay readable.
            color = vec3(pow(d, 32.0));
        }
    }
#endif
    outColor = vec4(color, 1.0);
}
