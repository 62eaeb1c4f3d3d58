#pragma once
// G-buffer pass: rasterizes the scene once from the camera and stores per-pixel surface data.
// Targets: albedo (SRGB8_A8: base colour + occlusion), normal (RGBA16F world normal),
// material (RGBA8: roughness, metalness, the clear coat's two texels), emissive (RGBA16F
// radiance), node ID (RGBA32UI: index of the scene node drawn there + 1, 0 = background, for
// picking and the selection outline; the primitive; the material), layer texels (RGBA32UI: the
// specular and sheen textures' texels and the coat's normal, shared.h LIT_TEX_GBUFFER_LAYERS),
// motion (RGBA16F: how far the surface point moved with its node since the last frame, world
// metres; written only in frames where nodes moved, for the temporal anti-aliasing), depth (32F).

#include <shared.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gl/ProgramVariants.h"
#include "passes/Pass.h"
#include "passes/TargetsBySize.h"

namespace lit {

class GpuScene;
struct DrawCounters;
struct Scene;

class GBufferPass : public Pass {
public:
    explicit GBufferPass(const std::filesystem::path& shaderRoot);

    void resize(int width, int height);
    // Draws the items listed in `visibleItems` (indices into gpuScene.items(), e.g. the camera's
    // culling result), or every item when it is null. `previousWorld`: each node's world transform
    // in the last frame (by node index); when given, the motion target holds each point's motion
    // since (world − previous world), else it is left out.
    void execute(const Scene& scene, const GpuScene& gpuScene, DrawCounters& counters,
                 const std::vector<std::uint32_t>* visibleItems = nullptr,
                 const std::vector<glm::mat4>* previousWorld = nullptr);
    // Binds the targets to LIT_TEX_GBUFFER_* for the full-screen passes.
    void bindTargets() const;

    const gl::Texture& depth() const { return targets_->depth; }
    const gl::Texture& albedo() const { return targets_->albedo; }
    const gl::Texture& normal() const { return targets_->normal; }
    const gl::Texture& material() const { return targets_->material; }
    const gl::Texture& nodeId() const { return targets_->nodeId; }
    const gl::Texture& motion() const { return targets_->motion; }
    std::vector<gl::Program*> programs() override { return programs_.built(); }

private:
    // gbuffer.frag.glsl per combination of material textures the draws use (LIT_MATERIAL_TEXTURES,
    // material.glsl), indexed by GpuScene::materialTextureMask.
    gl::ProgramVariants<LIT_MATERIAL_TEXTURES_ALL + 1> programs_;
    struct MaterialTextureKey {  // a ProgramVariants key
        unsigned mask;
        unsigned index() const { return mask; }
        std::string defines() const { return "#define LIT_MATERIAL_TEXTURES " + std::to_string(mask) + "\n"; }
        std::string label() const { return " (textures " + std::to_string(mask) + ")"; }
    };
    struct Targets {
        gl::Texture albedo, normal, material, emissive, nodeId, layers, motion, depth;
        gl::Framebuffer framebuffer;
        int width = 0, height = 0;
    };
    TargetsBySize<Targets> targets_;
};

}  // namespace lit
