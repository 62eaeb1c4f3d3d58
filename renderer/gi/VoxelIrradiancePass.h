#pragma once
// The cached GI mode's gather per voxel (docs/GI.md, "Voxel irradiance cache"): after the
// injection (and the bounces) and a full mip build, occupied voxels trace their diffuse
// irradiance (voxel rays through the grid, or the stratified cones; bounce.comp.glsl with
// LIT_BOUNCE_IRRADIANCE) and store irradiance/π per side in the cache's traced volume. The
// radiance volume is left as it is. IrradianceFilterPass must follow before the pixels gather.

#include <filesystem>
#include <vector>

#include "gi/ConeProgram.h"
#include "gi/RayHitCache.h"
#include "gi/VoxelDispatch.h"
#include "passes/Pass.h"

namespace lit {

class VoxelIrradianceCache;
class VoxelVolume;

struct IrradianceTrace {
    ConeFeatures features;  // what to gather with (ConeFeatures::of)
    bool overList = true;   // the occupied-voxel list; false when it overflowed (whole grid, range ignored)
    VoxelRange range;       // list entries to trace (count 0: all)
    // 0: each voxel traces its own cone set and replaces its value. k > 0 (the refinement): each
    // voxel traces the set k after its own and averages it in with weight 1 / (k + 1).
    int setOffset = 0;
    RayHits rayHits = RayHits::Off;  // only the first set's rays are the cache's
};

class VoxelIrradiancePass : public Pass {
public:
    explicit VoxelIrradiancePass(std::filesystem::path shaderRoot) : shaderRoot_(std::move(shaderRoot)) {}

    // Writes cache.traced(); nothing when the cache does not match the volume (prepare first).
    void trace(const VoxelVolume& volume, const VoxelIrradianceCache& cache, const RayHitCache& rayHits,
               const IrradianceTrace& trace);

    std::vector<gl::Program*> programs() override;

private:
    std::filesystem::path shaderRoot_;
    ConeProgram programs8_, programs16f_;  // by radiance format, built on first use
};

}  // namespace lit
