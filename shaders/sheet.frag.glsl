#version 450 core
// Transmissive sheets (KHR_materials_transmission drawn as a thin sheet, docs/MATERIALS.md,
// "Transmission"): drawn after the composite over its HDR image, farthest first, with dual-source
// blending
//   image = own + T(n·v) · image,   T = t·(1 − m)·c·(1 − F(n·v))   (brdf.glsl transmittanceOfSheet)
// (times its medium's share for a volume that does not bend, materialVolumeTransmittance), where
// `own` is the sheet's own light, term by term as the view shows them:
//   L_DD = Σ V·E·(albedo_d·(1 − t)/π · t_s + f_sheen)·(n·l) · b + emission     (direct_lighting)
//   L_DS = Σ V·E·(f_spec · t_s · b + cc·f_coat)·(n·l)
//   L_ID = albedo_d·(1 − t) (and the sheen's) × the six diffuse cones' irradiance/π    (cone_trace)
//   L_IS = E_spec × one cone along the mirror direction
// The lighting passes see what lies behind the sheet (the G-buffer, the shadow maps and the voxels
// leave sheets out), so the image under it is what the sheet lets through.
// A refracting volume's face (KHR_materials_volume, GpuMaterial::alpha.z: its η) draws the whole
// crossing at its front face instead, its back faces discarded: the view ray bends into the
// volume, crosses a slab of its thickness and leaves it, and what lies there is read from the
// image before the sheets (LIT_TEX_SHEET_BEHIND) where that exit point projects:
//   own += T(n·v)² · exp(−σ_a · d / cosθ_t) · behind(exit),   T · image = 0
// (docs/MATERIALS.md, "Volume").
#include "frame.glsl"
#include "material.glsl"
#include "gbuffer.glsl"
#include "specular_footprint.glsl"
#include "brdf.glsl"
#define LIT_SHADOW_CASCADES 1  // the camera's cascades sharpen the directional lights' shadows
#include "lights.glsl"
#include "direct_light.glsl"
#include "cone.glsl"

#include "geometry_varyings.glsl"

layout(location = 0, index = 0) out vec4 outOwn;
layout(location = 0, index = 1) out vec4 outTransmittance;

layout(location = LIT_LOC_MODEL) uniform mat4 uModel;
layout(binding = LIT_TEX_SHEET_BEHIND) uniform sampler2D sheetBehind;
layout(binding = LIT_TEX_SHEET_BEHIND_DEPTH) uniform sampler2D sheetBehindDepth;

// The texel of the image before the sheets where world point `p` projects (clamped to the image).
ivec2 behindTexel(vec3 p) {
    vec4 clip = frame.viewProjection * vec4(p, 1.0);
    ivec2 size = textureSize(sheetBehind, 0);
    vec2 uv = clip.w > 0.0 ? clip.xy / clip.w * 0.5 + 0.5 : gl_FragCoord.xy / vec2(size);
    return clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
}

// What the view ray that leaves a refracting volume at `exitPoint` along `direction` meets, read
// from the image before the sheets: the pixel of the exit point, then twice the pixel of the point
// along the ray as far as the surface seen there lies along it (a secant step on the depth).
vec3 seenBehind(vec3 exitPoint, vec3 direction) {
    ivec2 texel = behindTexel(exitPoint);
    ivec2 size = textureSize(sheetBehind, 0);
    for (int i = 0; i < 2; ++i) {
        float depth = texelFetch(sheetBehindDepth, texel, 0).r;
        if (depth >= 1.0) break;  // the sky: no surface to step to
        vec4 ndc = vec4((vec2(texel) + 0.5) / vec2(size) * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
        vec4 world = frame.inverseViewProjection * ndc;
        float along = max(dot(world.xyz / world.w - exitPoint, direction), 0.0);
        texel = behindTexel(exitPoint + direction * along);
    }
    return texelFetch(sheetBehind, texel, 0).rgb;
}

uniform ivec4 uTerms;              // which of DD, ID, DS, IS the view adds (1/0)
uniform int uIndirect;             // 1: the voxel volume is bound (GI on)
uniform float uShadowNormalOffset; // shadow lookup offset along the normal, in shadow texels

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    vec4 baseColor = materialBaseColor(m, fs.uv);
    // Taken before any discard: the derivatives need the whole quad.
    float footprint = footprintAlphaSquared(normalize(fs.worldNormal));
    if (materialAlphaDiscard(m, baseColor.a)) discard;

    Surface s;
    s.valid = true;
    s.position = fs.worldPosition;
    s.baseColor = baseColor.rgb;
    s.occlusion = 1.0;
    s.metalness = m.params.x;
    s.roughness = m.params.y;
    if (m.textures.y != 0) {
        vec4 mr = texture(metallicRoughnessTexture, materialUv(LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS, fs.uv));
        s.roughness *= mr.g;
        s.metalness *= mr.b;
    }
    s.roughness = clamp(s.roughness, 0.0, 1.0);
    s.footprint = footprint;
    s.metalness = clamp(s.metalness, 0.0, 1.0);
    s.emissive = m.emissive.rgb;
    if (m.textures.w != 0) s.emissive *= texture(emissiveTexture, materialUv(LIT_MATERIAL_SLOT_EMISSIVE, fs.uv)).rgb;
    LayerTexels layerTexels = materialLayerTexels(m, fs.uv);
    setMaterialLayers(m, layerTexels, s);
    float transmission = materialTransmission(m, fs.uv);

    vec3 v = normalize(frame.cameraPosition.xyz - s.position);
    vec3 n = normalize(fs.worldNormal);
    float eta = m.alpha.z;  // a refracting volume's index of refraction, 0: a thin sheet
    if (eta > 0.0 && dot(n, v) < 0.0) discard;  // its front face draws the crossing
    if (dot(n, v) < 0.0) n = -n;  // a sheet is seen from either side
    s.normal = n;
    float NdotV = max(dot(n, v), 0.0);
    vec3 albedo = diffuseAlbedo(s.baseColor, s.metalness) * (1.0 - transmission);
    vec3 directDiffuse, directSpecular;
    directLight(s, n, v, albedo, uShadowNormalOffset, directDiffuse, directSpecular);
    directDiffuse += s.emissive;
    float coatScale = clearcoatBaseScale(s.clearcoat, NdotV);

    vec3 indirectDiffuse = vec3(0.0), indirectSpecular = vec3(0.0);
    if (uIndirect != 0) {
        float scale = voxel.traceParams.x;
        vec3 origin = coneOrigin(s.position, n);
        float maxDistance = voxel.traceParams.y;
        vec3 diffuseAlbedoUnderLayers = (albedo * sheenBaseScale(s, NdotV) + s.sheenColor * sheenAlbedo(NdotV, s.sheenRoughness)) *
                                        coatScale;
        vec3 cones[kDiffuseConeCount];
        for (int i = 0; i < kDiffuseConeCount; ++i) cones[i] = vec3(0.0);
        if (uTerms.y != 0 && max(diffuseAlbedoUnderLayers.r, max(diffuseAlbedoUnderLayers.g, diffuseAlbedoUnderLayers.b)) > 0.0)
            indirectDiffuse = diffuseAlbedoUnderLayers * traceDiffuse(origin, n, voxel.traceParams.w, maxDistance) * scale;
        if (uTerms.w != 0)
            indirectSpecular = indirectSpecularWeight(s.f0, s.f90, s.roughness, sheenBaseScale(s, NdotV), s.clearcoat,
                                                      s.clearcoatRoughness, NdotV, NdotV) *
                               traceSpecular(origin, n, v, specularLobeRoughness(s), 1, gl_FragCoord.xy, 0, maxDistance,
                                             false, cones) *
                               scale;
    }

    vec3 own = float(uTerms.x) * directDiffuse + float(uTerms.y) * indirectDiffuse + float(uTerms.z) * directSpecular +
               float(uTerms.w) * indirectSpecular;
    vec3 through = transmittanceOfSheet(s.baseColor, s.metalness, transmission, materialDielectricF0(m, layerTexels),
                                        materialDielectricF90(m, layerTexels), NdotV);
    if (eta > 0.0) {
        // Into the volume by Snell's law, across a slab of its thickness, out again at the same
        // angle to the normal (a slab's far face), where the image before the sheets is read.
        vec3 bent = refract(-v, n, 1.0 / eta);
        float cosBent = max(-dot(bent, n), 0.1);
        float path = materialThickness(m, fs.uv, meshLengthScale(uModel)) / cosBent;
        own += through * through * exp(-m.volume.rgb * path) * seenBehind(s.position + bent * path, -v);
        through = vec3(0.0);
    } else {
        through *= materialVolumeTransmittance(m, fs.uv, NdotV, meshLengthScale(uModel));
    }
    outOwn = vec4(own, 0.0);
    outTransmittance = vec4(through, 1.0);
}
