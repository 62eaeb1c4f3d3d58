#pragma once
// The four lighting-term images (linear radiance, RGBA16F): L_DD, L_DS written by the direct
// lighting pass, L_ID, L_IS by the cone-tracing pass. The composite pass sums them.

#include "gl/Objects.h"
#include "passes/TargetsBySize.h"

namespace lit {

enum class Term { DirectDiffuse = 0, DirectSpecular = 1, IndirectDiffuse = 2, IndirectSpecular = 3 };

class LightingTerms {
public:
    void resize(int width, int height);
    const gl::Texture& texture(Term term) const { return targets_->textures[static_cast<int>(term)]; }
    // Framebuffer writing L_DD to attachment 0 and L_DS to attachment 1.
    const gl::Framebuffer& directFramebuffer() const { return targets_->direct; }
    // Framebuffer writing L_ID to attachment 0 and L_IS to attachment 1.
    const gl::Framebuffer& indirectFramebuffer() const { return targets_->indirect; }
    void clearIndirect() const;
    // Binds all four to LIT_TEX_TERM_* units.
    void bind() const;
    int width() const { return targets_->width; }
    int height() const { return targets_->height; }

private:
    struct Targets {
        gl::Texture textures[4];
        gl::Framebuffer direct, indirect;
        int width = 0, height = 0;
    };
    TargetsBySize<Targets> targets_;
};

}  // namespace lit
