#include "passes/ConeTracePass.h"

#include <shared.h>

#include <algorithm>

#include "RenderSettings.h"
#include "gi/VoxelVolume.h"
#include "passes/LightingTerms.h"

namespace lit {

ConeTracePass::ConeTracePass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "cone trace",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "cone_trace.frag.glsl"}}, {},
               ConeFeatures::of(RenderSettings{})),
      albedoProgram_(shaderRoot, "specular albedo table",
                     {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "specular_albedo.frag.glsl"}}),
      reducedProgram_(shaderRoot, "indirect trace (reduced)",
                      {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_trace.frag.glsl"}},
                      {}, ConeFeatures::of(RenderSettings{})),
      reducedSubsetProgram_(shaderRoot, "indirect trace (reduced, cone subsets)",
                            {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_trace.frag.glsl"}},
                            // Built for the default settings' features; the other mode's variant on first use.
                            "#define LIT_CONE_SUBSETS 1\n", ConeFeatures::of(RenderSettings{})),
      reducedLobeProgram_(shaderRoot, "indirect trace (reduced, cone lobes)",
                          {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_trace.frag.glsl"}},
                          "#define LIT_TRACE_LOBES 1\n", ConeFeatures::of(RenderSettings{})),
      strataFilter_(shaderRoot) {
    constexpr int size = LIT_SPECULAR_ALBEDO_SIZE;
    albedoTable_ = gl::Texture("specular albedo table", {GL_TEXTURE_2D, GL_RG16F, size, size, 1, 1});
    albedoTable_.setFilter(GL_LINEAR, GL_LINEAR);
    albedoTable_.setWrap(GL_CLAMP_TO_EDGE);  // n·v or roughness beyond the outer texel centres
    albedoTarget_ = gl::Framebuffer("specular albedo table");
    albedoTarget_.attach(GL_COLOR_ATTACHMENT0, albedoTable_);
    albedoTarget_.setDrawBuffers(1);
    albedoTarget_.checkComplete("specular albedo table");
    buildAlbedoTable();
}

std::vector<gl::Program*> ConeTracePass::programs() {
    std::vector<gl::Program*> programs{&albedoProgram_};
    program_.appendBuilt(programs);
    reducedProgram_.appendBuilt(programs);
    reducedSubsetProgram_.appendBuilt(programs);
    reducedLobeProgram_.appendBuilt(programs);
    for (gl::Program* program : strataFilter_.programs()) programs.push_back(program);
    return programs;
}

void ConeTracePass::buildAlbedoTable() {
    albedoTarget_.bind();
    glViewport(0, 0, LIT_SPECULAR_ALBEDO_SIZE, LIT_SPECULAR_ALBEDO_SIZE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    albedoProgram_.use();
    triangle_.draw();
    albedoTableBuiltWith_ = albedoProgram_.id();
}

ConeTracePass::Work ConeTracePass::workFor(const RenderSettings& settings) {
    Work work;
    if (!settings.gi.enabled) return work;
    work.diffuse = settings.debug.view == View::IndirectDiffuse ||
                   (settings.debug.view == View::Final && settings.terms.indirectDiffuse);
    work.specular = settings.debug.view == View::IndirectSpecular ||
                    (settings.debug.view == View::Final && settings.terms.indirectSpecular);
    return work;
}

void ConeTracePass::execute(const LightingTerms& terms, const VoxelVolume& volume, const RenderSettings& settings,
                            bool materialLayers) {
    const Work work = workFor(settings);
    if ((!work.diffuse && !work.specular) || !volume.radiance()) {
        terms.clearIndirect();
        return;
    }
    bindAlbedoTable();
    terms.indirectFramebuffer().bind();
    glViewport(0, 0, terms.width(), terms.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    volume.radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    const ConeFeatures features = ConeFeatures::of(settings, materialLayers);
    if (features.anisotropic) volume.bindDirectional();
    const gl::Program& program = program_.get(features);
    program.use();
    glProgramUniform2i(program.id(), program.location("uTraceTerms"), work.diffuse ? 1 : 0, work.specular ? 1 : 0);
    triangle_.draw();
}

void ConeTracePass::bindAlbedoTable() {
    if (albedoTableBuiltWith_ != albedoProgram_.id()) buildAlbedoTable();
    albedoTable_.bind(LIT_TEX_SPECULAR_ALBEDO);
}

int ConeTracePass::indirectScale(const RenderSettings& settings) {
    return settings.indirect.scale <= 1 ? 1 : (settings.indirect.scale <= 2 ? 2 : 4);
}

bool ConeTracePass::reducedPath(const RenderSettings& settings) {
    // The voxel-irradiance gather (the cached GI mode) exists only in the reduced path's shaders.
    return indirectScale(settings) > 1 || settings.indirect.temporalAccumulation ||
           ConeFeatures::of(settings).footprint || settings.gi.voxelIrradiance();
}

bool ConeTracePass::coneSubsets(const RenderSettings& settings) {
    // With the voxel-irradiance gather there are no diffuse cones to split into subsets.
    return settings.indirect.temporalAccumulation && settings.indirect.temporalConeSubsets &&
           !settings.gi.voxelIrradiance();
}

ConeTracePass::Sampling ConeTracePass::samplingFor(std::uint64_t frame, int scale, bool coneSubsets) {
    Sampling sampling;
    const auto s = static_cast<std::uint64_t>(std::max(scale, 1));
    const std::uint64_t index = frame % (s * s);
    // Row index/s, column shifted by the row: (0,0), (1,1), (0,1), (1,0) at s = 2.
    const std::uint64_t row = index % s, column = (index / s + index % s) % s;
    sampling.jitter = glm::ivec2(static_cast<int>(row), static_cast<int>(column));
    const float sideConePeriod = 2.0f * 3.14159265358979f / 5.0f;  // the five side cones repeat every 72°
    sampling.rotation = sideConePeriod * static_cast<float>(frame % LIT_DIFFUSE_ROTATION_STEPS) /
                        static_cast<float>(LIT_DIFFUSE_ROTATION_STEPS);
    // Five phases (each side cone is in two of the five pairs); 5 is prime to the jitter's s² and
    // the rotation's 8 frames, so the history sees every combination.
    if (coneSubsets) sampling.coneSubset = static_cast<int>(frame % 5);
    return sampling;
}

void ConeTracePass::executeReduced(const VoxelVolume& volume, const RenderSettings& settings,
                                   const Sampling& sampling, bool materialLayers) {
    const int scale = indirectScale(settings);
    const int w = (settings.output.width + scale - 1) / scale, h = (settings.output.height + scale - 1) / scale;
    if (low_.select(w, h) == TargetsBySize<LowTargets>::Selected::Empty) {
        LowTargets& t = low_.current();
        t.packed = gl::Texture("indirect terms (reduced)", {GL_TEXTURE_2D, GL_RGBA32UI, w, h, 1, 1});
        t.guide = gl::Texture("indirect guide (reduced)", {GL_TEXTURE_2D, GL_RGBA32UI, w, h, 1, 1});
        t.packed.setFilter(GL_NEAREST, GL_NEAREST);
        t.guide.setFilter(GL_NEAREST, GL_NEAREST);
        t.lobeMask = gl::Texture("indirect lobe mask (reduced)", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT16, w, h, 1, 1});
        t.target = gl::Framebuffer::withColours("indirect (reduced)", {&t.packed, &t.guide});
        t.target.attach(GL_DEPTH_ATTACHMENT, t.lobeMask);
        t.target.checkComplete("indirect (reduced)");
    }
    LowTargets& t = low_.current();
    const ConeFeatures features = ConeFeatures::of(settings, materialLayers);
    // The strata filter averages the texels' stratified cone sets (the accurate mode). The
    // voxel-irradiance gather traces no sets per texel (the voxels averaged them) and is already a
    // 27-voxel average; rough lobes read the same gather. Filtering it would only blur it, and
    // differently in the term views (a lobe is filtered with its texel's L_ID, which L_IS alone has
    // not), so that the terms would no longer sum to the final image.
    const bool strataFilter = features.footprint && !features.voxelIrradiance;
    if (strataFilter && !t.tracedPacked) {
        t.tracedPacked = gl::Texture("indirect terms (reduced, stratified)", {GL_TEXTURE_2D, GL_RGBA32UI, w, h, 1, 1});
        t.tracedPacked.setFilter(GL_NEAREST, GL_NEAREST);
        t.tracedTarget = gl::Framebuffer::withColours("indirect (reduced, stratified)", {&t.tracedPacked, &t.guide});
        t.filteredTarget = gl::Framebuffer::withColours("indirect (reduced, strata filtered)", {&t.packed});
    }
    const Work work = workFor(settings);
    const GLuint zero[4] = {0, 0, 0, 0};
    if ((!work.diffuse && !work.specular) || !volume.radiance()) {
        glClearNamedFramebufferuiv(t.target.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferuiv(t.target.id(), GL_COLOR, 1, zero);
        return;
    }
    bindAlbedoTable();
    (strataFilter ? t.tracedTarget : t.target).bind();
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    volume.radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    if (features.anisotropic) volume.bindDirectional();
    const bool subsets = sampling.coneSubset >= 0;
    // The uniforms of indirect_trace.frag.glsl, the same for each of its programs.
    const auto useTraceProgram = [&](const gl::Program& program) {
        program.use();
        const GLuint id = program.id();
        glProgramUniform2i(id, program.location("uTraceTerms"), work.diffuse ? 1 : 0, work.specular ? 1 : 0);
        glProgramUniform1f(id, program.location("uSmoothRoughness"), settings.indirect.specularFullResRoughness);
        glProgramUniform1i(id, program.location("uScale"), scale);
        glProgramUniform2i(id, program.location("uJitter"), sampling.jitter.x, sampling.jitter.y);
        glProgramUniform1f(id, program.location("uRotation"), sampling.rotation);
        if (sampling.coneSubset >= 0) glProgramUniform1i(id, program.location("uConeSubset"), sampling.coneSubset);
    };
    useTraceProgram((subsets ? reducedSubsetProgram_ : reducedProgram_).get(features));
    // The cached mode: the gather writes the lobe mask (gl_FragDepth, so the depth test must be on
    // to write it), then the lobe pass redoes the marked texels only: the triangle lies at window
    // depth 0.5 and the mask holds 0 where a lobe needs cones, so GREATER passes those (as
    // IndirectFallbackPass does with the resolve's trace mask).
    const bool lobePass = features.voxelIrradiance && !subsets && !strataFilter;
    if (lobePass) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
    }
    triangle_.draw();
    if (lobePass) {
        useTraceProgram(reducedLobeProgram_.get(features));
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_FALSE);
        triangle_.draw();
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
    }
    if (strataFilter) strataFilter_.execute(t.tracedPacked, t.guide, t.filteredTarget, w, h);
}

}  // namespace lit
