#pragma once
// Cone-tracing pass: the indirect lighting terms L_ID (diffuse) and L_IS (specular) of every
// pixel, by marching cones through the mipmapped radiance volume (cone_trace.frag.glsl,
// shaders/include/cone.glsl; docs/GI.md explains the method and its parameters).
//
// Writes terms.indirectFramebuffer(): attachment 0 = L_ID, attachment 1 = L_IS (RGBA16F, linear
// radiance W/(sr·m²)), both already scaled by the indirect intensity and the material's ambient
// occlusion; background pixels get 0.

#include "passes/Pass.h"

namespace lit {

class LightingTerms;
class VoxelVolume;
struct RenderSettings;

class ConeTracePass : public Pass {
public:
    // Builds the programs and the specular albedo table (needs a current GL context).
    explicit ConeTracePass(const std::filesystem::path& shaderRoot);

    // Expects bound by the caller: the G-buffer (GBufferPass::bindTargets), the frame UBO at
    // LIT_UBO_FRAME and the voxel UBO at LIT_UBO_VOXEL (VoxelVolume::updateUniforms, which
    // carries intensity, trace distance, step scale, aperture and specular sample count), and a
    // radiance volume whose mip chain is up to date. Binds volume.radiance() to
    // LIT_TEX_VOXEL_RADIANCE and its albedo table to LIT_TEX_SPECULAR_ALBEDO itself. Terms that
    // are neither shown (settings.view) nor switched on are written as 0 without tracing them.
    void execute(const LightingTerms& terms, const VoxelVolume& volume, const RenderSettings& settings);

    // Which of the two terms a frame with `settings` needs traced.
    struct Work {
        bool diffuse = false;   // L_ID
        bool specular = false;  // L_IS
    };
    static Work workFor(const RenderSettings& settings);

    // The GGX directional albedo table (RG16F, LIT_SPECULAR_ALBEDO_SIZE², x = n·v, y = roughness):
    // E = F0·r + g. Exposed for tests.
    const gl::Texture& specularAlbedoTable() const { return albedoTable_; }

    std::vector<gl::Program*> programs() override { return {&program_, &albedoProgram_}; }

private:
    // (Re)integrates the table with albedoProgram_; called at construction and after a reload.
    void buildAlbedoTable();

    gl::Program program_;
    gl::Program albedoProgram_;
    GLuint albedoTableBuiltWith_ = 0;  // albedoProgram_ id the table was built with (hot reload)
    gl::Texture albedoTable_;
    gl::Framebuffer albedoTarget_;
    FullscreenTriangle triangle_;
};

}  // namespace lit
