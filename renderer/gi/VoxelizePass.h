#pragma once
// Voxelization: rasterizes the scene into the material volumes of a VoxelVolume (albedo, normal,
// emission as running averages; see VoxelVolume.h and shaders/voxelize.*.glsl).
//
// Each triangle is projected along its dominant axis into an N×N viewport of an attachment-less
// framebuffer and enlarged for conservative rasterization; each fragment is one voxel the
// triangle touches and averages its material into that voxel with image atomics.
//
// Also here: read-backs of the volumes for tests and debug views (they stall the pipeline).

#include <shared.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gi/VoxelRegions.h"
#include "gl/ProgramVariants.h"
#include "passes/Pass.h"

namespace lit {

class GpuScene;
class VoxelVolume;
struct DrawCounters;
struct Scene;

class VoxelizePass : public Pass {
public:
    explicit VoxelizePass(const std::filesystem::path& shaderRoot);

    // Clears the material volumes, the radiance volume's chain (VoxelVolume::clearRadianceMips)
    // and the occupied-voxel list,
    // then voxelizes every item of `gpuScene` into them, appending each voxel it occupies to
    // volume.occupiedList() (the first fragment to reach a voxel appends it). Needs
    // `volume` allocated (ensure), placed (fitTo) and its uniforms uploaded (updateUniforms);
    // binds what it uses itself: the voxel UBO, the material SSBO, the three material images.
    // Changes GL state: viewport (N×N), draw framebuffer (0 afterwards), depth test and face
    // culling off. Ends with an image-access + texture-fetch barrier.
    void execute(const Scene& scene, const GpuScene& gpuScene, VoxelVolume& volume, DrawCounters& counters);
    // Voxelizes only the voxels of `boxes` (disjoint; VoxelChangeTracker) again: zeroes their
    // material voxels and draws the items whose boxes reach them, writing inside the boxes only.
    // `items`: itemPoses(scene, gpuScene).
    // The occupied-voxel list is kept: voxels new to it are appended (VoxelVolume::listedVoxels).
    // Level 0 of the radiance volume is cleared in the boxes only (outside them it keeps its light,
    // which a running update goes on reading), its mips wholly as by execute(). Same GL state after.
    void executeBoxes(const Scene& scene, const GpuScene& gpuScene, VoxelVolume& volume,
                      const std::vector<VoxelBox>& boxes, const std::vector<ItemPose>& items,
                      DrawCounters& counters);

    std::vector<gl::Program*> programs() override { return programs_.built(); }

private:
    // Binds what the draws read and write; false when there is nothing to draw.
    bool begin(const GpuScene& gpuScene, const VoxelVolume& volume);
    void setRegion(const VoxelBox& box) const;
    void end() const;

    // voxelize.*.glsl with and without the layers' textures (LIT_MATERIAL_TEXTURE_LAYERS,
    // material.glsl): llvmpipe pays for their texture reads in every fragment even where no
    // material has one (about an eighth of Sponza's voxelization).
    struct LayerTexturesKey {
        bool on = true;
        unsigned index() const { return on ? 1u : 0u; }
        std::string defines() const {
            return "#define LIT_MATERIAL_TEXTURES " +
                   std::to_string(on ? LIT_MATERIAL_TEXTURES_ALL
                                     : LIT_MATERIAL_TEXTURES_ALL & ~LIT_MATERIAL_TEXTURE_LAYERS) +
                   "\n";
        }
        std::string label() const { return on ? "" : " (no layer textures)"; }
    };
    gl::ProgramVariants<2> programs_;
    const gl::Program* program_ = nullptr;  // the variant begin() chose for the scene
    gl::Framebuffer framebuffer_;  // no attachments: its default size is the volume's N
    int framebufferSize_ = 0;
};

// Each item of `gpuScene` as the voxelization draws it: its node's world transform and world box.
std::vector<ItemPose> itemPoses(const Scene& scene, const GpuScene& gpuScene);

// Packed RGBA8 values of one material volume (albedo, normal or emission), x fastest, then y,
// then z: index = x + N·(y + N·z). Unpack with unpackVoxel.
std::vector<std::uint32_t> readMaterialVoxels(const gl::Texture& materialVolume);
// RGBA8 packed as in voxel.glsl (x in the low byte) → [0,1]⁴; alpha × 255 is the sample count.
glm::vec4 unpackVoxel(std::uint32_t packed);

// Voxels whose albedo sample count is non-zero.
std::size_t countOccupiedVoxels(const VoxelVolume& volume);
// Integer coordinates of the occupied voxels, in index order (x fastest).
std::vector<glm::ivec3> occupiedVoxels(const VoxelVolume& volume);

}  // namespace lit
