#include "passes/LightingTerms.h"

#include <shared.h>

#include <utility>

namespace lit {

void LightingTerms::resize(int width, int height) {
    const auto selected = targets_.select(width, height);
    if (selected == TargetsBySize<Targets>::Selected::Unchanged) return;
    if (selected == TargetsBySize<Targets>::Selected::Reused) {
        clearIndirect();  // as after an allocation: no indirect terms of an earlier frame
        return;
    }
    Targets& t = targets_.current();
    const char* names[4] = {"term direct diffuse", "term direct specular", "term indirect diffuse",
                            "term indirect specular"};
    for (int i = 0; i < 4; ++i) {
        t.textures[i] = gl::Texture(names[i], {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
        t.textures[i].setFilter(GL_NEAREST, GL_NEAREST);
    }
    t.direct = gl::Framebuffer::withColours("direct lighting terms", {&t.textures[0], &t.textures[1]});
    t.indirect = gl::Framebuffer::withColours("indirect lighting terms", {&t.textures[2], &t.textures[3]});
    clearIndirect();
}

void LightingTerms::clearIndirect() const {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(targets_->indirect.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(targets_->indirect.id(), GL_COLOR, 1, zero);
}

void LightingTerms::bind() const {
    targets_->textures[0].bind(LIT_TEX_TERM_DIRECT_DIFFUSE);
    targets_->textures[1].bind(LIT_TEX_TERM_DIRECT_SPECULAR);
    targets_->textures[2].bind(LIT_TEX_TERM_INDIRECT_DIFFUSE);
    targets_->textures[3].bind(LIT_TEX_TERM_INDIRECT_SPECULAR);
}

}  // namespace lit
