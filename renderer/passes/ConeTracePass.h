#pragma once
// Cone-tracing pass: the indirect lighting terms L_ID (diffuse) and L_IS (specular) of every
// pixel, by marching cones through the mipmapped radiance volume (cone_trace.frag.glsl,
// shaders/include/cone.glsl; docs/GI.md explains the method and its parameters).
//
// Two ways (docs/GI.md, "Reduced resolution and temporal accumulation"):
//  - execute: every pixel at full resolution (IndirectSettings::scale 1 without temporal
//    accumulation: the reference path). Writes terms.indirectFramebuffer(): attachment 0 = L_ID,
//    attachment 1 = L_IS (RGBA16F, linear radiance W/(sr·m²)), both already scaled by the
//    indirect intensity and the material's ambient occlusion; background pixels get 0.
//  - executeReduced: one pixel per indirectScale² block (indirect_trace.frag.glsl), demodulated,
//    into this pass's own low-resolution targets; IndirectResolvePass turns them into the terms.

#include <cstdint>
#include <glm/glm.hpp>

#include "gi/ConeProgram.h"
#include "passes/ConeStrataFilterPass.h"
#include "passes/Pass.h"
#include "passes/TargetsBySize.h"

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
    // are neither shown (settings.debug.view) nor switched on are written as 0 without tracing them.
    // `materialLayers`: whether the scene's materials have specular layers (GpuScene::hasMaterialLayers;
    // then the material table must be bound too).
    void execute(const LightingTerms& terms, const VoxelVolume& volume, const RenderSettings& settings,
                 bool materialLayers = true);

    // Which pixel of each block is traced and how the cone sets are turned this frame (temporal
    // accumulation varies both; a still without it uses the defaults).
    struct Sampling {
        glm::ivec2 jitter{0};   // pixel inside the indirectScale² block (0..scale−1 each)
        float rotation = 0.0f;  // rad, turn of the cone sets about the normal
        // −1: every texel traces the whole diffuse cone set; 0..4: the phase of the cone subsets
        // (indirect_trace.frag.glsl, LIT_CONE_SUBSETS): the normal cone and two side cones per texel.
        int coneSubset = -1;
    };
    // The sampling of temporal frame `frame` at indirect scale `scale`: the jitter runs through
    // the block's pixels (a Latin square, so successive frames move diagonally), the rotation
    // through LIT_DIFFUSE_ROTATION_STEPS steps of the side cones' 72° period, and, with
    // `coneSubsets`, the subset phase through frame mod 5.
    static Sampling samplingFor(std::uint64_t frame, int scale, bool coneSubsets = false);
    // Whether a temporal frame with `settings` traces cone subsets (IndirectSettings::temporalConeSubsets
    // and temporal accumulation on; in either GI mode: with footprint-bounded cones the subsets are
    // pairs of the texel's stratified set).
    static bool coneSubsets(const RenderSettings& settings);
    // Whether a frame with `settings` takes the reduced path (executeReduced + IndirectResolvePass).
    // Always with footprint-bounded cones (the accurate mode): their stratified cone sets need
    // ConeStrataFilterPass, which runs on the reduced trace (at indirect scale 1 too).
    static bool reducedPath(const RenderSettings& settings);
    // IndirectSettings::scale made valid: 1, 2 or 4.
    static int indirectScale(const RenderSettings& settings);

    // The low-resolution trace (same bindings as execute): ⌈width/s⌉ × ⌈height/s⌉ texels of
    // demodulated L_ID and rough L_IS and of the traced pixels' positions and normals, packed
    // (indirect.glsl), read by IndirectResolvePass. With footprint-bounded cones each texel traces
    // its stratified cone set and lowPacked() holds the trace after ConeStrataFilterPass.
    void executeReduced(const VoxelVolume& volume, const RenderSettings& settings, const Sampling& sampling,
                        bool materialLayers = true);
    const gl::Texture& lowPacked() const { return low_->packed; }  // RGBA32UI
    const gl::Texture& lowGuide() const { return low_->guide; }    // RGBA32UI

    // Which of the two terms a frame with `settings` needs traced.
    struct Work {
        bool diffuse = false;   // L_ID
        bool specular = false;  // L_IS
    };
    static Work workFor(const RenderSettings& settings);

    // The GGX directional albedo table (RG16F, LIT_SPECULAR_ALBEDO_SIZE², x = n·v, y = roughness):
    // E = F0·r + g. Exposed for tests.
    const gl::Texture& specularAlbedoTable() const { return albedoTable_; }

    std::vector<gl::Program*> programs() override;
    // Binds the albedo table to LIT_TEX_SPECULAR_ALBEDO (rebuilt first after a shader reload).
    void bindAlbedoTable();

private:
    // (Re)integrates the table with albedoProgram_; called at construction and after a reload.
    void buildAlbedoTable();

    ConeProgram program_;
    gl::Program albedoProgram_;
    ConeProgram reducedProgram_;
    ConeProgram reducedSubsetProgram_;  // indirect_trace.frag.glsl with LIT_CONE_SUBSETS 1
    // The cached GI mode's texels whose specular lobe needs cones (indirect_trace.frag.glsl with
    // LIT_TRACE_LOBES 1): the main trace has no cone code and marks them in the lobe mask. On
    // llvmpipe the cone code behind an untaken branch cost the ½-scale trace of the full-frame
    // Cornell box 40 % of its time (docs/PERFORMANCE.md, "llvmpipe").
    ConeProgram reducedLobeProgram_;
    // The low-resolution targets of one size, kept for two sizes (the editor's interactive render
    // scale switches back and forth; TargetsBySize): RGBA32UI, ⌈width/s⌉ × ⌈height/s⌉.
    struct LowTargets {
        int width = 0, height = 0;
        gl::Texture packed, guide;
        // Depth: 0 where the cached mode's lobe pass traces the texel, 1 elsewhere (reducedLobeProgram_).
        gl::Texture lobeMask;
        gl::Framebuffer target;
        // Footprint-bounded cones: the trace goes to tracedPacked (+ guide), the strata filter
        // writes packed from it (allocated on first use).
        gl::Texture tracedPacked;
        gl::Framebuffer tracedTarget, filteredTarget;
    };
    TargetsBySize<LowTargets> low_;
    ConeStrataFilterPass strataFilter_;
    GLuint albedoTableBuiltWith_ = 0;  // albedoProgram_ id the table was built with (hot reload)
    gl::Texture albedoTable_;
    gl::Framebuffer albedoTarget_;
    FullscreenTriangle triangle_;
};

}  // namespace lit
