// Punctual lights (KHR_lights_punctual) and their shadow maps.
// Units (docs/UNITS.md): intensity is candela for point/spot lights and lux for directional
// lights, used as radiometric W/sr and W/m² at exposure 1.
#include "shared.h"

layout(std430, binding = LIT_SSBO_LIGHTS) readonly buffer LightBlock {
    GpuLight lights[];
};

layout(binding = LIT_TEX_SHADOW_2D) uniform sampler2DArrayShadow shadowMaps2d;
layout(binding = LIT_TEX_SHADOW_CUBE) uniform samplerCubeArrayShadow shadowMapsCube;

// The spec's recommended range window: smooth falloff to 0 at `range`, then inverse square.
float rangeAttenuation(float distance, float range) {
    float invSquare = 1.0 / max(distance * distance, 1e-4);
    if (range <= 0.0) return invSquare;
    float ratio = distance / range;
    float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * invSquare;
}

// The spec's spot falloff between inner and outer cone: saturate(cos·scale + offset)².
float spotAttenuation(GpuLight light, vec3 toLight) {
    float cd = dot(light.directionType.xyz, -toLight);
    float a = clamp(cd * light.spotShadow.x + light.spotShadow.y, 0.0, 1.0);
    return a * a;
}

struct LightSample {
    vec3 l;          // unit vector from the surface to the light
    vec3 radiance;   // incident radiance scale: E⊥ = intensity × attenuation × colour (W/m²)
    float distance;  // metres (1e30 for directional lights)
};

LightSample sampleLight(GpuLight light, vec3 position) {
    LightSample s;
    int type = int(light.directionType.w);
    if (type == LIT_LIGHT_DIRECTIONAL) {
        s.l = -light.directionType.xyz;
        s.distance = 1e30;
        s.radiance = light.colorIntensity.rgb * light.colorIntensity.a;
        return s;
    }
    vec3 d = light.positionRange.xyz - position;
    s.distance = length(d);
    s.l = d / max(s.distance, 1e-6);
    float attenuation = rangeAttenuation(s.distance, light.positionRange.w);
    if (type == LIT_LIGHT_SPOT) attenuation *= spotAttenuation(light, s.l);
    s.radiance = light.colorIntensity.rgb * light.colorIntensity.a * attenuation;
    return s;
}

// PCF with four hardware 2×2 (bilinear) comparisons at (±b, ±b)·radius instead of a 3×3 grid at
// {−1, 0, 1}·radius: the same kernel variance per axis (b² = 2/3, the grid's (1 + 0 + 1)/3) for
// less than half the lookups. On llvmpipe the nine lookups made "lighting" the largest pass of a
// GI-off frame; four measured 1.45–1.9× faster there, and the image (full-frame Cornell box,
// 1280×720) moved by 0.034/255 on average, 0.1 % of the pixels (along penumbrae) by more than
// 16/255 (docs/PERFORMANCE.md).
const float kPcfTapOffset = 0.81649658;  // √(2/3)

// Whether some light of the table has a cube (point) or a 2D (directional, spot) shadow map
// (ShadowKinds in LightSetup.h picks the program): the lookups of a kind no light has are compiled
// out, since llvmpipe runs a branch no lane takes with every lane masked off (the cube lookups cost
// a spot-lit full-frame Cornell box's lighting pass 20 of its 65 ms at 1280×720). Both 1 by
// default, which is right for any table.
#ifndef LIT_SHADOWS_CUBE
#define LIT_SHADOWS_CUBE 1
#endif
#ifndef LIT_SHADOWS_2D
#define LIT_SHADOWS_2D 1
#endif
// Whether the maps hold transmissive sheets (ShadowKinds::sheets): compiled in only for scenes
// with sheets, which pay the extra lookup.
#ifndef LIT_SHADOWS_SHEETS
#define LIT_SHADOWS_SHEETS 0
#endif
#if LIT_SHADOWS_SHEETS
layout(binding = LIT_TEX_SHADOW_SHEETS) uniform sampler2DArray sheetShadowMaps2d;
layout(binding = LIT_TEX_SHADOW_SHEETS_CUBE) uniform samplerCubeArray sheetShadowMapsCube;
// Linear depth (share of the light's depth range) a receiver must lie past the nearest sheet to be
// behind it: keeps a sheet from tinting its own light.
const float kSheetShadowDepthBias = 1.0 / 512.0;
#endif

// Whether the camera's cascades of the directional lights are read (LIT_TEX_SHADOW_CASCADES): by the
// passes that light pixels. The voxel injection leaves them out and reads each light's map over the
// whole scene, so the voxels' light does not follow the camera.
#ifndef LIT_SHADOW_CASCADES
#define LIT_SHADOW_CASCADES 0
#endif
#if LIT_SHADOW_CASCADES
layout(binding = LIT_TEX_SHADOW_CASCADES) uniform sampler2DArrayShadow shadowCascades;
layout(std140, binding = LIT_UBO_SHADOW_CASCADES) uniform ShadowCascadeBlock {
    ShadowCascadeUniforms cascadeData;
};
#endif

// Four hardware 2×2 comparisons at (±b, ±b) texels (see kPcfTapOffset) around `uv` of `layer`.
float pcf2d(sampler2DArrayShadow maps, vec2 uv, float layer, float depth, vec2 texel, float pcfRadius) {
    vec2 d1 = texel * (max(pcfRadius, 0.0) * kPcfTapOffset), d2 = vec2(d1.x, -d1.y);
    return 0.25 * (texture(maps, vec4(uv + d1, layer, depth)) + texture(maps, vec4(uv - d1, layer, depth)) +
                   texture(maps, vec4(uv + d2, layer, depth)) + texture(maps, vec4(uv - d2, layer, depth)));
}

#if LIT_SHADOW_CASCADES
// The share of a cascade's square, inside its edge, over which it hands over to the next map out:
// the squares move with the camera, and a pixel that changes map changes its shadow gradually.
const float kCascadeBlend = 0.1;

// The visibility from map `c` of cascaded light `slot`, or −1 when its square does not hold
// `position` with the PCF kernel and a texel to spare; `edge` is how far inside that it lies, in
// shares of kCascadeBlend (≥ 1: past the blend).
float cascadeLookup(int slot, int c, vec3 position, vec3 normal, float pcfRadius, float normalOffsetTexels, out float edge) {
    GpuShadowCascade cascade = cascadeData.cascades[slot * LIT_MAX_SHADOW_CASCADES + c];
    vec2 texel = 1.0 / vec2(textureSize(shadowCascades, 0).xy);
    vec2 margin = texel * (max(pcfRadius, 0.0) + 1.0);
    vec3 lookup = position + normal * (cascade.params.x * normalOffsetTexels);
    vec3 uvz = (cascade.viewProjection * vec4(lookup, 1.0)).xyz * 0.5 + 0.5;
    vec2 inside = min(uvz.xy - margin, 1.0 - margin - uvz.xy);
    edge = min(inside.x, inside.y) / kCascadeBlend;
    if (edge < 0.0 || uvz.z > 1.0) return -1.0;
    return pcf2d(shadowCascades, uvz.xy, cascade.params.z, uvz.z - cascade.params.y, texel, pcfRadius);
}
#endif

// The visibility from the finest of the camera's cascades of a directional light that holds
// `position`, blended towards the next one near its edge; −1 when none does (or the light has none).
float cascadeVisibility(GpuLight light, vec3 position, vec3 normal, float pcfRadius, float normalOffsetTexels) {
#if LIT_SHADOW_CASCADES
    int slot = int(light.spotShadow.w);
    if (slot < 0 || int(light.directionType.w) != LIT_LIGHT_DIRECTIONAL) return -1.0;
    int count = cascadeData.counts.x;
    for (int c = 0; c < count; ++c) {
        float edge;
        float lit = cascadeLookup(slot, c, position, normal, pcfRadius, normalOffsetTexels, edge);
        if (lit < 0.0) continue;
        if (edge < 1.0 && c + 1 < count) {
            float nextEdge;
            float next = cascadeLookup(slot, c + 1, position, normal, pcfRadius, normalOffsetTexels, nextEdge);
            if (next >= 0.0) lit = mix(next, lit, edge);
        }
        return lit;
    }
#endif
    return -1.0;
}

// The [0, 1] depth a perspective shadow map (near n, far f) stores for view depth w, the receiver
// moved `bias` of the depth range towards the light first. The constant bias is a share of the
// depth range in linear depth, as an orthographic (directional) map's is: subtracted after the
// projection it grew with w²/n, and with the near plane at 1/1000 of the far one a spot 6 m away
// lit a floor behind a 0.3 m wall (0.0005 of the depth range there is 0.9 m).
float perspectiveShadowDepth(float w, float n, float f, float bias) {
    float biased = max(w - bias * (f - n), n);
    float ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * biased);
    return ndc * 0.5 + 0.5;
}

// Fraction of the light reaching `position` per channel (1 = lit), with PCF of four hardware 2×2
// comparisons (above), times what the transmissive sheets between it and the light let through
// (LIT_SHADOWS_SHEETS). `normal` offsets the lookup to avoid acne on grazing surfaces.
vec3 shadowVisibility(GpuLight light, vec3 position, vec3 normal, float pcfRadius, float normalOffsetTexels) {
    float index = light.spotShadow.z;
    if (index < 0.0) return vec3(1.0);
    int type = int(light.directionType.w);
#if LIT_SHADOWS_CUBE
    if (type == LIT_LIGHT_POINT) {
        vec3 fromLight = position - light.positionRange.xyz;
        float dist = length(fromLight);
        float texel = 2.0 * dist / float(textureSize(shadowMapsCube, 0).x);  // world size of one texel at this distance
        vec3 p = position + normal * texel * normalOffsetTexels;
        vec3 v = p - light.positionRange.xyz;
        // Depth the cube face's perspective projection gives this point (major-axis distance).
        float n = light.shadowParams.x, f = light.shadowParams.y;
        float m = max(abs(v.x), max(abs(v.y), abs(v.z)));
        float depth = perspectiveShadowDepth(m, n, f, light.shadowParams.z);
        // PCF on the cube: jitter the direction in the face plane by ±radius texels.
        vec3 major = abs(v.x) >= m ? vec3(1, 0, 0) : (abs(v.y) >= m ? vec3(0, 1, 0) : vec3(0, 0, 1));
        vec3 t1 = normalize(cross(major, abs(major.y) > 0.5 ? vec3(0, 0, 1) : vec3(0, 1, 0)));
        vec3 t2 = cross(major, t1);
        float step = 2.0 * m / float(textureSize(shadowMapsCube, 0).x) * max(pcfRadius, 0.0) * 0.5;
        // Four hardware 2×2 comparisons at (±b, ±b) steps (see kPcfTapOffset).
        vec3 d1 = (t1 + t2) * (step * kPcfTapOffset), d2 = (t1 - t2) * (step * kPcfTapOffset);
        float sum = texture(shadowMapsCube, vec4(v + d1, index), depth) + texture(shadowMapsCube, vec4(v - d1, index), depth) +
                    texture(shadowMapsCube, vec4(v + d2, index), depth) + texture(shadowMapsCube, vec4(v - d2, index), depth);
        vec3 through = vec3(1.0);
#if LIT_SHADOWS_SHEETS
        vec4 sheets = textureLod(sheetShadowMapsCube, vec4(v, index), 0.0);
        if ((m - n) / max(f - n, 1e-6) > sheets.a + kSheetShadowDepthBias) through = sheets.rgb;
#endif
        return (0.25 * sum) * through;
    }
#endif
#if LIT_SHADOWS_2D
    // The camera's cascades where one holds the point, else the map over the whole scene.
    float lit = cascadeVisibility(light, position, normal, pcfRadius, normalOffsetTexels);
#if !LIT_SHADOWS_SHEETS
    if (lit >= 0.0) return vec3(lit);
#endif
    vec2 size = vec2(textureSize(shadowMaps2d, 0).xy);
    // Normal offset scaled by the world size of a texel at this receiver.
    vec4 clip0 = light.shadowViewProjection * vec4(position, 1.0);
    float worldTexel;
    if (type == LIT_LIGHT_DIRECTIONAL) {
        worldTexel = 2.0 / (size.x * length(vec3(light.shadowViewProjection[0][0], light.shadowViewProjection[1][0],
                                                  light.shadowViewProjection[2][0])));
    } else {
        worldTexel = 2.0 * clip0.w / (size.x * length(vec3(light.shadowViewProjection[0][0],
                                                          light.shadowViewProjection[1][0],
                                                          light.shadowViewProjection[2][0])));
    }
    vec4 clip = light.shadowViewProjection * vec4(position + normal * worldTexel * normalOffsetTexels, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    vec3 uvz = ndc * 0.5 + 0.5;
    bool inside = all(greaterThanEqual(uvz.xy, vec2(0.0))) && all(lessThanEqual(uvz.xy, vec2(1.0))) && uvz.z <= 1.0;
    if (lit < 0.0) {
        if (!inside) return vec3(1.0);
        float depth = type == LIT_LIGHT_DIRECTIONAL
                          ? uvz.z - light.shadowParams.z
                          : perspectiveShadowDepth(clip.w, light.shadowParams.x, light.shadowParams.y, light.shadowParams.z);
        lit = pcf2d(shadowMaps2d, uvz.xy, index, depth, 1.0 / size, pcfRadius);
    }
    vec3 through = vec3(1.0);
#if LIT_SHADOWS_SHEETS
    if (inside) {
        vec4 sheets = textureLod(sheetShadowMaps2d, vec3(uvz.xy, index), 0.0);
        float receiver = type == LIT_LIGHT_DIRECTIONAL
                             ? uvz.z
                             : (clip.w - light.shadowParams.x) / max(light.shadowParams.y - light.shadowParams.x, 1e-6);
        if (receiver > sheets.a + kSheetShadowDepthBias) through = sheets.rgb;
    }
#endif
    return lit * through;
#else
    return vec3(1.0);  // no light has a 2D shadow map, so this light has none (index < 0 above)
#endif
}
