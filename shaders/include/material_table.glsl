// The material table (GpuMaterial, shared.h): the passes that draw geometry read their draw's
// material, the lighting passes the one the G-buffer's ID target names per pixel.
#include "shared.h"

layout(std430, binding = LIT_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

// A transmissive sheet (KHR_materials_transmission, docs/MATERIALS.md "Transmission"): SheetPass
// draws it over the lit image; the G-buffer, the shadow maps and the voxelization discard it.
// As GpuScene.h drawnAsSheet.
bool materialIsSheet(GpuMaterial m) { return m.alpha.y > 0.0 && m.params.x < 1.0; }

// The texels of a material's layer textures at a point, 1 where it has none: what multiplies
// each factor (docs/MATERIALS.md). Drawing passes sample them (material.glsl materialLayerTexels),
// the lighting passes read them from the G-buffer (gbuffer.glsl).
struct LayerTexels {
    float clearcoat;           // clearcoatTexture's red
    float clearcoatRoughness;  // clearcoatRoughnessTexture's green
    vec4 specular;             // rgb specularColorTexture (linear), a specularTexture's alpha
    vec4 sheen;                // rgb sheenColorTexture (linear), a sheenRoughnessTexture's alpha
};

LayerTexels noLayerTexels() { return LayerTexels(1.0, 1.0, vec4(1.0), vec4(1.0)); }

// The dielectric's F0 = min(((η − 1)/(η + 1))² · k · k_tex, 1) · s · s_tex and F90 = s · s_tex
// (docs/MATERIALS.md): the table holds ((η − 1)/(η + 1))² · k · s before the clamp, so that the
// colour texel scales it first.
vec3 materialDielectricF0(GpuMaterial m, LayerTexels t) {
    return min(m.specular.rgb * t.specular.rgb, vec3(m.specular.a)) * t.specular.a;
}
float materialDielectricF90(GpuMaterial m, LayerTexels t) { return m.specular.a * t.specular.a; }
