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

#include <vector>

#include "gi/VoxelRegions.h"
#include "gl/Objects.h"

namespace lit {

class VoxelVolume;

class VoxelIrradianceCache {
public:
    // Makes the volumes for `volume`'s resolution and format. `clear` (after a voxelization: old
    // values sit at old geometry) marks every voxel untraced (alpha 0, which the filter and the
    // gather skip); new storage is always cleared. A light edit keeps the old values until they
    // are traced again.
    //
    // `keepShown` (with `clear`; the volume's placement unchanged): the pixels go on gathering the
    // last complete update's texels while the new ones are traced into a second set, so an edit
    // never blanks the indirect light; showWritten() swaps once the update is complete.
    void prepare(const VoxelVolume& volume, bool clear, bool keepShown = false);
    // The update is complete: the pixels gather the texels it wrote (no copy; the other set is
    // what the next kept update writes into).
    void showWritten() { shown_ = written_; }
    // The pixels gather the last complete update's texels, not those being written.
    bool showingPrevious() const { return shown_ != written_; }
    // The voxels of `boxes` were voxelized again while an update runs on: their traced values
    // are forgotten (alpha 0, which the filter skips), the rest kept.
    void forget(const std::vector<VoxelBox>& boxes) const;
    // Whether the volumes match `volume` (prepare ran for its resolution and format).
    bool matches(const VoxelVolume& volume) const;

    const gl::Texture& traced() const { return traced_; }
    // The texels the filter writes.
    const gl::Texture& gatherTexels() const { return gatherTexels_[written_]; }
    // The texels the pixels gather.
    const gl::Texture& shownTexels() const { return gatherTexels_[shown_]; }
    // Binds the texels the pixels gather (the last complete update's while another is traced)
    // to LIT_TEX_VOXEL_IRRADIANCE for the cone passes.
    void bindGatherTexels() const;
    std::size_t bytes() const;

private:
    gl::Texture traced_;
    // Two sets: the second is made by the first kept update and stays (docs/GI.md, "Memory").
    gl::Texture gatherTexels_[2];
    int written_ = 0, shown_ = 0;
    int resolution_ = 0;
    bool rgba8_ = false;
};

}  // namespace lit
