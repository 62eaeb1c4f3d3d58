#version 450 core
// A transmissive sheet seen from a light with a 2D shadow map (ShadowPass): writes its
// transmittance T(cosθ) for the light's direction (brdf.glsl transmittanceOfSheet, times its
// volume's, material.glsl materialVolumeTransmittance) and its linear
// depth; the blend multiplies the sheets' T and keeps the nearest depth (LIT_TEX_SHADOW_SHEETS).
// Opaque materials write nothing: the depth test against the layer's opaque depth keeps only the
// sheets in front of the nearest opaque surface.
#include "material.glsl"
#include "brdf.glsl"

in vec4 vUv;
in vec3 vWorldPosition;
in vec3 vWorldNormal;

layout(location = 0) out vec4 outSheet;

layout(location = LIT_LOC_MODEL) uniform mat4 uModel;
// xyz: the direction the light travels (directional lights), or w = 1: the light's position (spot).
uniform vec4 uLight;
// Near and far plane (m) of a perspective (spot) map, to write linear depth; 0, 0 for orthographic.
uniform vec2 uNearFar;

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    if (!materialIsSheet(m)) discard;
    vec4 baseColor = materialBaseColor(m, vUv);
    if (materialAlphaDiscard(m, baseColor.a)) discard;
    float metalness = m.params.x;
    if (m.textures.y != 0) metalness *= texture(metallicRoughnessTexture, materialUv(LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS, vUv)).b;
    vec3 travel = uLight.w > 0.0 ? vWorldPosition - uLight.xyz : uLight.xyz;
    float cosine = dot(normalize(vWorldNormal), normalize(travel));
    LayerTexels layerTexels = materialLayerTexels(m, vUv);
    vec3 through = transmittanceOfSheet(baseColor.rgb, clamp(metalness, 0.0, 1.0), materialTransmission(m, vUv),
                                        materialDielectricF0(m, layerTexels), materialDielectricF90(m, layerTexels),
                                        cosine) *
                   materialVolumeTransmittance(m, vUv, cosine, meshLengthScale(uModel));
    float depth = uNearFar.y > 0.0 ? (1.0 / gl_FragCoord.w - uNearFar.x) / (uNearFar.y - uNearFar.x) : gl_FragCoord.z;
    outSheet = vec4(through, depth);
}
