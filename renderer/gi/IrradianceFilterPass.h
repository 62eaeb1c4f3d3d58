#pragma once
// The voxel irradiance filter (voxel_irradiance_filter.comp.glsl): every occupied voxel averages
// the traced irradiance over one period of the cone sets' pattern along its surface and writes the
// gather texel the pixels read (VoxelIrradianceCache::gatherTexels).

#include <filesystem>
#include <vector>

#include "gi/VoxelDispatch.h"
#include "passes/Pass.h"

namespace lit {

class VoxelIrradianceCache;
class VoxelVolume;

class IrradianceFilterPass : public Pass {
public:
    explicit IrradianceFilterPass(std::filesystem::path shaderRoot) : shaderRoot_(std::move(shaderRoot)) {}

    // Filters the list entries `range` (count 0: every occupied voxel: the list, or the grid when
    // `overList` is false). A voxel's filtered value reads its neighbours', which a range may have
    // traced though the voxel itself lies elsewhere in the list: filtering only the traced range
    // leaves those neighbours' values stale until their own range is traced, so the frame that
    // completes an update filters the whole list.
    void execute(const VoxelVolume& volume, const VoxelIrradianceCache& cache, bool overList, VoxelRange range = {});

    // After a voxelization: empties the shown texels (VoxelIrradianceCache::showingPrevious) of
    // voxels the new voxelization left empty or turned (voxel_irradiance_prune.comp.glsl).
    void pruneShown(const VoxelVolume& volume, const VoxelIrradianceCache& cache);
    // The same for both sets of texels, shown and written (a voxelization of changed boxes while
    // an update runs on and goes on writing its set).
    void pruneBoth(const VoxelVolume& volume, const VoxelIrradianceCache& cache);

    std::vector<gl::Program*> programs() override {
        std::vector<gl::Program*> built;
        for (gl::Program* p : {&program_, &prune_})
            if (*p) built.push_back(p);
        return built;
    }

private:
    void prune(const VoxelVolume& volume, const gl::Texture& texels);

    std::filesystem::path shaderRoot_;
    gl::Program program_;  // one program for both radiance formats, built on first use
    gl::Program prune_;    // built by the first pruneShown
};

}  // namespace lit
