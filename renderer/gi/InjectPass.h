#pragma once
// Radiance injection: lights the voxel volume. For every occupied voxel, the outgoing radiance of
// a Lambertian surface under the scene's direct light (with shadows) plus its emission goes into
// level 0 of the radiance volume; empty voxels get 0 (opacity 0). See shaders/inject.comp.glsl.

#include <glm/glm.hpp>
#include <vector>

#include "gi/VoxelRegions.h"
#include "gl/ProgramVariants.h"
#include "passes/LightSetup.h"
#include "passes/Pass.h"

namespace lit {

class VoxelVolume;

struct InjectOptions {
    // Only the voxels of the occupied-voxel list (complete, not overflowed), with an indirect
    // dispatch; empty voxels are then not written (VoxelizePass zeroed them). Otherwise every
    // voxel of the grid, empty ones written as 0.
    bool overList = true;
    // Also write the same radiance to volume.direct() (light bounces follow; ignored when the
    // volume has no direct volume).
    bool writeDirect = false;
    // With writeDirect: false writes only the direct volume and level 0 keeps what it holds (the
    // last update's light, while a light edit's bounces run).
    bool writeLevel0 = true;
    // With writeLevel0 false: level 0 is written all the same in these boxes (at most
    // LIT_CHANGED_BOXES), whose voxels a voxelization of changed boxes left without light.
    std::vector<VoxelBox> level0Boxes;
    ShadowKinds shadows;  // the shadow map kinds the light table uses (program variant)
};

class InjectPass : public Pass {
public:
    explicit InjectPass(const std::filesystem::path& shaderRoot);

    // Writes level 0 of volume.radiance() from the material volumes (after VoxelizePass).
    // The caller must have bound, as for the direct-lighting pass:
    //   - the frame UBO at LIT_UBO_FRAME (only counts.x, the light count, is read),
    //   - the light table SSBO at LIT_SSBO_LIGHTS,
    //   - the shadow maps (ShadowPass::bindMaps) at LIT_TEX_SHADOW_2D / LIT_TEX_SHADOW_CUBE.
    // Binds itself: the voxel UBO (volume.uniforms(), which must be up to date) and the image
    // units LIT_IMG_VOXEL_ALBEDO/NORMAL/EMISSION (read) and LIT_IMG_VOXEL_RADIANCE (write).
    // Ends with an image-access + texture-fetch barrier; the mip levels are left to the mipmap pass.
    void execute(const VoxelVolume& volume, const InjectOptions& options = {});

    std::vector<gl::Program*> programs() override { return programs_.built(); }

private:
    gl::ProgramVariants<ShadowKinds::kVariants> programs_;  // inject.comp.glsl by ShadowKinds::index()
};

// Level `level` of the radiance volume as linear radiance, rgb W/(sr·m²), a opacity; x fastest,
// then y, then z. An RGBA8 volume is decoded with `rgba8Range`, the GiSettings::radianceRange
// it was injected with. Stalls the pipeline (tests, debug tools).
std::vector<glm::vec4> readRadianceVoxels(const VoxelVolume& volume, int level = 0, float rgba8Range = 1.0f);

// A two-sided voxel's split of its direct light by side (VoxelVolume::sides, voxel.glsl "Sides"):
// the axis of its slab and the half difference Δ of its sides' direct light (W/(sr·m²)); a ray
// that ends on the +axis side sees level 0 + Δ, one on the other side level 0 − Δ.
struct VoxelSides {
    bool split = false;  // false: the voxel sends the same light to both sides
    glm::vec3 axis{0.0f};
    glm::vec3 delta{0.0f};
};
// Every voxel's sides, in readRadianceVoxels' order and decoding. Stalls the pipeline (tests).
std::vector<VoxelSides> readVoxelSides(const VoxelVolume& volume, float rgba8Range = 1.0f);

}  // namespace lit
