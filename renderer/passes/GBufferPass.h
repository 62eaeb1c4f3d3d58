#pragma once
// G-buffer pass: rasterizes the scene once from the camera and stores per-pixel surface data.
// Targets: albedo (SRGB8_A8: base colour + occlusion), normal (RGBA16F world normal),
// material (RGBA8: roughness, metalness), emissive (RGBA16F radiance), node ID (R32UI: index of
// the scene node drawn there + 1, 0 = background; for picking and the selection outline), depth (32F).

#include "passes/Pass.h"

#include <cstdint>
#include <vector>

namespace lit {

class GpuScene;
struct DrawCounters;
struct Scene;

class GBufferPass : public Pass {
public:
    explicit GBufferPass(const std::filesystem::path& shaderRoot);

    void resize(int width, int height);
    // Draws the items listed in `visibleItems` (indices into gpuScene.items(), e.g. the camera's
    // culling result), or every item when it is null.
    void execute(const Scene& scene, const GpuScene& gpuScene, DrawCounters& counters,
                 const std::vector<std::uint32_t>* visibleItems = nullptr);
    // Binds the targets to LIT_TEX_GBUFFER_* for the full-screen passes.
    void bindTargets() const;

    const gl::Texture& depth() const { return depth_; }
    const gl::Texture& albedo() const { return albedo_; }
    const gl::Texture& normal() const { return normal_; }
    const gl::Texture& material() const { return material_; }
    const gl::Texture& nodeId() const { return nodeId_; }
    std::vector<gl::Program*> programs() override { return {&program_}; }

private:
    gl::Program program_;
    gl::Texture albedo_, normal_, material_, emissive_, nodeId_, depth_;
    gl::Framebuffer framebuffer_;
    int width_ = 0, height_ = 0;
    // The targets of the size used before the current one, kept so that switching back (the
    // editor's interactive render scale: full size when still, a smaller one while moving)
    // reuses them instead of reallocating: allocating the 1280×720 targets cost 120–590 ms on
    // llvmpipe in the frame after a motion (docs/PERFORMANCE.md). Empty until a second size is
    // used (lit-render and the tests render at one size).
    struct Spare {
        gl::Texture albedo, normal, material, emissive, nodeId, depth;
        gl::Framebuffer framebuffer;
        int width = 0, height = 0;
    } spare_;
    void swapWithSpare();
};

}  // namespace lit
