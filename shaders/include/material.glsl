// Material table and textures for passes that draw scene geometry.
#include "shared.h"

layout(std430, binding = LIT_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

layout(location = LIT_LOC_MATERIAL) uniform int uMaterialIndex;

layout(binding = LIT_TEX_BASE_COLOR) uniform sampler2D baseColorTexture;
layout(binding = LIT_TEX_METALLIC_ROUGHNESS) uniform sampler2D metallicRoughnessTexture;
layout(binding = LIT_TEX_NORMAL) uniform sampler2D normalTexture;
layout(binding = LIT_TEX_EMISSIVE) uniform sampler2D emissiveTexture;
layout(binding = LIT_TEX_OCCLUSION) uniform sampler2D occlusionTexture;

// Base colour × texture (linear; sRGB textures are decoded by the sampler).
vec4 materialBaseColor(GpuMaterial m, vec2 uv) {
    vec4 c = m.baseColorFactor;
    if (m.textures.x != 0) c *= texture(baseColorTexture, uv);
    return c;
}

// True when an alpha-masked fragment must be discarded.
bool materialAlphaDiscard(GpuMaterial m, float alpha) {
    return m.modes.y == LIT_ALPHA_MASK && alpha < m.alpha.x;
}
