#include "passes/IndirectFallbackPass.h"

#include "RenderSettings.h"
#include "passes/IndirectResolvePass.h"

namespace lit {

IndirectFallbackPass::IndirectFallbackPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "indirect fallback",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_fallback.frag.glsl"}}, {},
               ConeFeatures::of(RenderSettings{})) {}

std::vector<gl::Program*> IndirectFallbackPass::programs() {
    std::vector<gl::Program*> programs;
    program_.appendBuilt(programs);
    return programs;
}

void IndirectFallbackPass::execute(const IndirectResolvePass& resolve, ConeFeatures features) {
    const gl::Program& program = program_.get(features);
    if (!resolve.bindForFallback(program)) return;
    // The triangle lies at window depth 0.5 (z = 0 in clip space, default depth range); the mask
    // holds 0 where the resolve wants a trace and 1 elsewhere, so GREATER passes the marked
    // pixels only. The mask is read, not written.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    program.use();
    triangle_.draw();
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace lit
