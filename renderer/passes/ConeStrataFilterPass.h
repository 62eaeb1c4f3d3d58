#pragma once
// Cone-strata filter (accurate mode): the footprint-bounded diffuse cones see along
// their axes only, so each low-resolution texel of the reduced trace traces one of
// LIT_CONE_STRATA² differently stratified cone sets (shaders/include/cone_strata.glsl), laid out as
// a fixed pattern over the texels; this pass averages each texel's demodulated indirect diffuse
// over one period of that pattern with depth- and normal-aware weights
// (cone_strata_filter.frag.glsl), so a flat surface gets the mean of every set: 96 directions
// for the cost of six cones per traced pixel. Specular and the guide pass through unchanged.
// docs/GI.md, "Stratified cone sets".

#include "passes/Pass.h"

namespace lit {

class ConeStrataFilterPass : public Pass {
public:
    explicit ConeStrataFilterPass(const std::filesystem::path& shaderRoot);

    // Writes the filtered copy of `traced` (RGBA32UI, packed as indirect.glsl) into `target`
    // (a framebuffer whose colour attachment 0 is an RGBA32UI texture of the same size w × h),
    // using `guide` (the trace's positions and normals). Expects the frame UBO bound.
    void execute(const gl::Texture& traced, const gl::Texture& guide, const gl::Framebuffer& target, int w, int h);

    std::vector<gl::Program*> programs() override { return {&program_}; }

private:
    gl::Program program_;
    FullscreenTriangle triangle_;
};

}  // namespace lit
