#pragma once
// The cached GI mode's irradiance per voxel (docs/GI.md, "Voxel irradiance cache"): what the
// voxels gathered themselves, and what the pixels gather from them.
//   traced        N × N × 2N in the radiance volume's format: each occupied voxel's irradiance/π
//                 on the side of its normal (z < N) and on the other side (z + N), as traced with
//                 its cone set(s) (VoxelIrradiancePass); alpha 1 where traced
//   gatherTexels  N³ RGBA32UI: per voxel its unit normal, flags and both sides' irradiance/π
//                 filtered over the cone sets' pattern (IrradianceFilterPass; voxel.glsl's
//                 packGatherTexel), read by the per-pixel gather (voxel_irradiance.glsl)

#include <cstddef>

#include "gl/Objects.h"

namespace lit {

class VoxelVolume;

class VoxelIrradianceCache {
public:
    // Makes the volumes for `volume`'s resolution and format. `clear` (after a voxelization: old
    // values sit at old geometry) marks every voxel untraced (alpha 0, which the filter and the
    // gather skip); new storage is always cleared. A light edit keeps the old values until they
    // are traced again.
    void prepare(const VoxelVolume& volume, bool clear);
    // Whether the volumes match `volume` (prepare ran for its resolution and format).
    bool matches(const VoxelVolume& volume) const;

    const gl::Texture& traced() const { return traced_; }
    const gl::Texture& gatherTexels() const { return gatherTexels_; }
    // Binds the gather texels to LIT_TEX_VOXEL_IRRADIANCE for the cone passes.
    void bindGatherTexels() const;
    std::size_t bytes() const;

private:
    gl::Texture traced_;
    gl::Texture gatherTexels_;
    int resolution_ = 0;
    bool rgba8_ = false;
};

}  // namespace lit
