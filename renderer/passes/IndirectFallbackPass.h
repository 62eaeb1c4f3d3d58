#pragma once
// Indirect fallback: the full-resolution cone trace of the pixels IndirectResolvePass could not
// reconstruct from the low-resolution trace (no low-resolution neighbour on the pixel's surface:
// silhouettes, thin objects) or must not (specular of surfaces smoother than
// IndirectSettings::specularFullResRoughness). The resolve marks them in its trace mask; this
// pass draws a full-screen triangle over the same targets with early depth tests against that
// mask, so only the marked pixels run the shader (indirect_fallback.frag.glsl, the resolve's body
// with the trace compiled in). Same upsampling and accumulation as the resolve: together they
// write what one pass doing both would.

#include "gi/ConeProgram.h"
#include "passes/Pass.h"

namespace lit {

class IndirectResolvePass;

class IndirectFallbackPass : public Pass {
public:
    explicit IndirectFallbackPass(const std::filesystem::path& shaderRoot);

    // After resolve.execute() of this frame, with the bindings it expects (G-buffer, frame and
    // voxel UBOs). Does nothing when the resolve wrote no terms this frame. `features`: the cone
    // features of the frame's settings (ConeFeatures::of).
    void execute(const IndirectResolvePass& resolve, ConeFeatures features);

    std::vector<gl::Program*> programs() override;

private:
    ConeProgram program_;
    FullscreenTriangle triangle_;
};

}  // namespace lit
