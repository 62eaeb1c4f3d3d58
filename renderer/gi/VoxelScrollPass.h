#pragma once
// Scrolls a near level (docs/GI.md, "Near levels"): when the camera has moved the level by whole
// voxels, what the level holds in the part it keeps moves with the world instead of being made
// again. The listed voxels' texels (the materials, level 0 of the radiance, the voxel irradiance
// the pixels gather, the traced irradiance and what an update under way has written) move by the
// shift, the slabs the move uncovered are left empty for the caller to voxelize (uncoveredSlabs),
// and the occupied-voxel list keeps its entries in place with their voxels' new coordinates
// (voxel_scroll.comp.glsl). Its cost follows the occupied voxels, not N³. The mips, the solid bits
// and the mip parents' lists are the caller's to build again, as after any voxelization.

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <vector>

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "passes/Pass.h"

namespace lit {

class VoxelIrradianceCache;
class VoxelVolume;

class VoxelScrollPass : public Pass {
public:
    explicit VoxelScrollPass(const std::filesystem::path& shaderRoot) : shaderRoot_(shaderRoot) {}

    // Moves `volume`'s and `cache`'s listed voxels by `shift` voxels (scrollShift: whole voxels,
    // fewer than N; the list complete, `entries` long; the cache made for the volume).
    void execute(const VoxelVolume& volume, const VoxelIrradianceCache& cache, glm::ivec3 shift, std::uint32_t entries);

    std::vector<gl::Program*> programs() override;

private:
    // The program for the texels kept or written (LIT_SCROLL_WRITTEN) in the radiance format, for
    // the phase (LIT_SCROLL_PHASE 0 lift, 1 place), built on first use.
    const gl::Program& program(bool written, bool rgba8, int phase);

    std::filesystem::path shaderRoot_;
    gl::Program programs_[2][2][2];  // [written][rgba8][phase]
    gl::Buffer saved_;               // LIT_SSBO_VOXEL_SCROLL, grown to the list
};

}  // namespace lit
