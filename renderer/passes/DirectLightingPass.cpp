#include "passes/DirectLightingPass.h"

#include "RenderSettings.h"
#include "passes/LightingTerms.h"

namespace lit {

DirectLightingPass::DirectLightingPass(const std::filesystem::path& shaderRoot)
    : programs_(shaderRoot, "direct lighting",
                {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "direct_lighting.frag.glsl"}}) {
    programs_.get(Variant{});  // a broken shader fails at start-up
}

void DirectLightingPass::execute(const LightingTerms& terms, const RenderSettings& settings, Variant variant) {
    terms.directFramebuffer().bind();
    glViewport(0, 0, terms.width(), terms.height());
    glDisable(GL_DEPTH_TEST);
    const gl::Program& program = programs_.get(variant);
    program.use();
    program.set("uShadowNormalOffset", settings.shadows.normalOffset);
    triangle_.draw();
}

}  // namespace lit
