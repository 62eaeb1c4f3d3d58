#include "passes/ConeTracePass.h"

#include "RenderSettings.h"
#include "passes/LightingTerms.h"
#include "passes/VoxelVolume.h"

#include <shared.h>

namespace lit {

ConeTracePass::ConeTracePass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "cone trace",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "cone_trace.frag.glsl"}}),
      albedoProgram_(shaderRoot, "specular albedo table",
                     {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "specular_albedo.frag.glsl"}}) {
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
    if (!settings.gi) return work;
    work.diffuse = settings.view == View::IndirectDiffuse || (settings.view == View::Final && settings.indirectDiffuse);
    work.specular =
        settings.view == View::IndirectSpecular || (settings.view == View::Final && settings.indirectSpecular);
    return work;
}

void ConeTracePass::execute(const LightingTerms& terms, const VoxelVolume& volume, const RenderSettings& settings) {
    const Work work = workFor(settings);
    if ((!work.diffuse && !work.specular) || !volume.radiance()) {
        terms.clearIndirect();
        return;
    }
    if (albedoTableBuiltWith_ != albedoProgram_.id()) buildAlbedoTable();
    terms.indirectFramebuffer().bind();
    glViewport(0, 0, terms.width(), terms.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    volume.radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    albedoTable_.bind(LIT_TEX_SPECULAR_ALBEDO);
    program_.use();
    glProgramUniform2i(program_.id(), program_.location("uTraceTerms"), work.diffuse ? 1 : 0, work.specular ? 1 : 0);
    triangle_.draw();
}

}  // namespace lit
