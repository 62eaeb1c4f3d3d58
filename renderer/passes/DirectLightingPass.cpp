#include "passes/DirectLightingPass.h"

#include "RenderSettings.h"
#include "passes/LightingTerms.h"

namespace lit {

DirectLightingPass::DirectLightingPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "direct lighting",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "direct_lighting.frag.glsl"}}) {}

void DirectLightingPass::execute(const LightingTerms& terms, const RenderSettings& settings) {
    terms.directFramebuffer().bind();
    glViewport(0, 0, terms.width(), terms.height());
    glDisable(GL_DEPTH_TEST);
    program_.use();
    program_.set("uShadowNormalOffset", settings.shadowNormalOffset);
    triangle_.draw();
}

}  // namespace lit
