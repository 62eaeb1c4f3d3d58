#pragma once
// Shadow maps: one layer of a 2D depth array per directional/spot light, one cube of a cube
// array per point light. Depth is rendered with slope-scaled polygon offset; the lighting pass
// filters it with PCF (lights.glsl).

#include "passes/LightSetup.h"
#include "passes/Pass.h"
#include "scene/GpuScene.h"

namespace lit {

class ShadowPass : public Pass {
public:
    explicit ShadowPass(const std::filesystem::path& shaderRoot);

    // Renders every shadow view of `lights`. Reallocates the maps when the size or count changes.
    // Each view (each cube face of a point light) draws the items `cull` picks for its
    // view-projection; every item when `cull` is empty.
    void execute(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                 const RenderSettings& settings, DrawCounters& counters, const ItemCuller& cull = {});

    // Binds the shadow arrays to their texture units (LIT_TEX_SHADOW_2D / _CUBE).
    void bindMaps() const;
    const gl::Texture& maps2d() const { return maps2d_; }
    std::size_t memoryBytes() const;

    std::vector<gl::Program*> programs() override { return {&program_}; }

private:
    void ensureMaps(int size, int layers2d, int cubes);

    gl::Program program_;
    gl::Texture maps2d_;
    gl::Texture mapsCube_;
    gl::Framebuffer framebuffer_;
    gl::Buffer uniforms_;
    gl::Sampler comparisonSampler_;
    int size_ = 0, layers2d_ = 0, cubes_ = 0;
    std::vector<std::uint32_t> visibleItems_;  // the current view's culling result (kept to reuse its memory)
};

}  // namespace lit
