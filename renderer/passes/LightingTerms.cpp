#include "passes/LightingTerms.h"

#include <shared.h>

#include <utility>

namespace lit {

void LightingTerms::swapWithSpare() {
    for (int i = 0; i < 4; ++i) std::swap(textures_[i], spare_.textures[i]);
    std::swap(direct_, spare_.direct);
    std::swap(indirect_, spare_.indirect);
    std::swap(width_, spare_.width);
    std::swap(height_, spare_.height);
}

void LightingTerms::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    swapWithSpare();  // the current targets become the spare
    if (width == width_ && height == height_) {  // the spare had this size
        clearIndirect();  // as after an allocation: no indirect terms of an earlier frame
        return;
    }
    width_ = width;
    height_ = height;
    const char* names[4] = {"term direct diffuse", "term direct specular", "term indirect diffuse",
                            "term indirect specular"};
    for (int i = 0; i < 4; ++i) {
        textures_[i] = gl::Texture(names[i], {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
        textures_[i].setFilter(GL_NEAREST, GL_NEAREST);
    }
    direct_ = gl::Framebuffer("direct lighting terms");
    direct_.attach(GL_COLOR_ATTACHMENT0, textures_[0]);
    direct_.attach(GL_COLOR_ATTACHMENT1, textures_[1]);
    direct_.setDrawBuffers(2);
    direct_.checkComplete("direct lighting terms");
    indirect_ = gl::Framebuffer("indirect lighting terms");
    indirect_.attach(GL_COLOR_ATTACHMENT0, textures_[2]);
    indirect_.attach(GL_COLOR_ATTACHMENT1, textures_[3]);
    indirect_.setDrawBuffers(2);
    indirect_.checkComplete("indirect lighting terms");
    clearIndirect();
}

void LightingTerms::clearIndirect() const {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(indirect_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(indirect_.id(), GL_COLOR, 1, zero);
}

void LightingTerms::bind() const {
    textures_[0].bind(LIT_TEX_TERM_DIRECT_DIFFUSE);
    textures_[1].bind(LIT_TEX_TERM_DIRECT_SPECULAR);
    textures_[2].bind(LIT_TEX_TERM_INDIRECT_DIFFUSE);
    textures_[3].bind(LIT_TEX_TERM_INDIRECT_SPECULAR);
}

}  // namespace lit
