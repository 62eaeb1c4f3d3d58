#pragma once
// Shadow maps: one layer of a 2D depth array per directional/spot light, one cube of a cube
// array per point light. Depth is rendered with slope-scaled polygon offset; the lighting pass
// filters it with PCF (lights.glsl).

#include "passes/LightSetup.h"
#include "passes/Pass.h"

namespace lit {

class GpuScene;
struct DrawCounters;

class ShadowPass : public Pass {
public:
    explicit ShadowPass(const std::filesystem::path& shaderRoot);

    // Renders every shadow view of `lights`. Reallocates the maps when the size or count changes.
    void execute(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                 const RenderSettings& settings, DrawCounters& counters);

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
};

}  // namespace lit
