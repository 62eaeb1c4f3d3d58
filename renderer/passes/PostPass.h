#pragma once
// Post processing: the composite (sum of terms or a debug view → linear HDR image) and the tone
// mapper (exposure + ACES → sRGB output). Both are full-screen passes.

#include "RenderSettings.h"
#include "passes/Pass.h"
#include "passes/TargetsBySize.h"

namespace lit {

class PostPass : public Pass {
public:
    explicit PostPass(const std::filesystem::path& shaderRoot);

    void resize(int width, int height);
    // Writes the HDR image of settings.view (any but the voxel views, see VoxelDebugPass).
    // Expects G-buffer, terms and frame UBO bound. `shadowLayer` is the 2D shadow-array layer the
    // shadow-map view shows (-1 for none).
    void composite(const RenderSettings& settings, const gl::Texture& shadowMaps, int shadowLayer);
    // Binds the HDR image as the render target with its viewport, for passes that write a view
    // in place of the composite (VoxelDebugPass).
    void bindHdrTarget() const;
    // Binds the sRGB output as the render target with its viewport, for passes that draw over the
    // tone-mapped image (OverlayPass).
    void bindOutputTarget() const;
    // Tone maps the HDR image into the sRGB output.
    void tonemap(const RenderSettings& settings);

    const gl::Texture& hdr() const { return targets_->hdr; }
    const gl::Texture& output() const { return targets_->output; }
    std::vector<gl::Program*> programs() override { return {&composite_, &finalComposite_, &tonemap_}; }

private:
    // composite.frag.glsl for every view, and for the final view alone (LIT_COMPOSITE_FINAL_ONLY:
    // without the other views' branches, which llvmpipe pays for though no pixel takes them).
    gl::Program composite_, finalComposite_, tonemap_;
    FullscreenTriangle triangle_;
    gl::Sampler plainSampler_;
    struct Targets {
        gl::Texture hdr, output;
        gl::Framebuffer hdrFramebuffer, outputFramebuffer;
        int width = 0, height = 0;
    };
    TargetsBySize<Targets> targets_;
};

// Views whose HDR image already holds display values in [0,1] (the tone mapper only clamps).
bool isDataView(View view);

}  // namespace lit
