#include "passes/ConeStrataFilterPass.h"

#include <shared.h>

namespace lit {

ConeStrataFilterPass::ConeStrataFilterPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "cone strata filter",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "cone_strata_filter.frag.glsl"}}) {}

void ConeStrataFilterPass::execute(const gl::Texture& traced, const gl::Texture& guide, const gl::Framebuffer& target,
                                   int w, int h) {
    target.bind();
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    traced.bind(LIT_TEX_INDIRECT_LOW_PACKED);
    guide.bind(LIT_TEX_INDIRECT_LOW_GUIDE);
    program_.use();
    triangle_.draw();
}

}  // namespace lit
