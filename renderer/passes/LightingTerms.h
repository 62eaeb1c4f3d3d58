#pragma once
// The four lighting-term images (linear radiance, RGBA16F): L_DD, L_DS written by the direct
// lighting pass, L_ID, L_IS by the cone-tracing pass. The composite pass sums them.

#include "gl/Objects.h"

namespace lit {

enum class Term { DirectDiffuse = 0, DirectSpecular = 1, IndirectDiffuse = 2, IndirectSpecular = 3 };

class LightingTerms {
public:
    void resize(int width, int height);
    const gl::Texture& texture(Term term) const { return textures_[static_cast<int>(term)]; }
    // Framebuffer writing L_DD to attachment 0 and L_DS to attachment 1.
    const gl::Framebuffer& directFramebuffer() const { return direct_; }
    // Framebuffer writing L_ID to attachment 0 and L_IS to attachment 1.
    const gl::Framebuffer& indirectFramebuffer() const { return indirect_; }
    void clearIndirect() const;
    // Binds all four to LIT_TEX_TERM_* units.
    void bind() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    gl::Texture textures_[4];
    gl::Framebuffer direct_, indirect_;
    int width_ = 0, height_ = 0;
    // The targets of the size used before the current one, kept so that switching back (the
    // editor's interactive render scale: full size when still, a smaller one while moving)
    // reuses them instead of reallocating: allocating the 1280×720 targets cost 120–590 ms on
    // llvmpipe in the frame after a motion (docs/PERFORMANCE.md). Empty until a second size is
    // used (lit-render and the tests render at one size).
    struct Spare {
        gl::Texture textures[4];
        gl::Framebuffer direct, indirect;
        int width = 0, height = 0;
    } spare_;
    void swapWithSpare();
};

}  // namespace lit
