#include "passes/DirectLightingPass.h"

#include "RenderSettings.h"
#include "passes/LightingTerms.h"

namespace lit {

DirectLightingPass::DirectLightingPass(const std::filesystem::path& shaderRoot)
    : programs_(shaderRoot, "direct lighting",
                {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "direct_lighting.frag.glsl"}}) {
    const ShadowKinds any;
    programs_.get(any.index(), any.defines(), any.label());  // a broken shader fails at start-up
}

std::vector<gl::Program*> DirectLightingPass::programs() {
    std::vector<gl::Program*> built;
    programs_.appendBuilt(built);
    return built;
}

void DirectLightingPass::execute(const LightingTerms& terms, const RenderSettings& settings, ShadowKinds shadows) {
    terms.directFramebuffer().bind();
    glViewport(0, 0, terms.width(), terms.height());
    glDisable(GL_DEPTH_TEST);
    const gl::Program& program = programs_.get(shadows.index(), shadows.defines(), shadows.label());
    program.use();
    program.set("uShadowNormalOffset", settings.shadowNormalOffset);
    triangle_.draw();
}

}  // namespace lit
