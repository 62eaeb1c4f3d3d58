#include "gi/VoxelIrradianceCache.h"

#include <shared.h>

#include "gi/VoxelVolume.h"

namespace lit {

void VoxelIrradianceCache::prepare(const VoxelVolume& volume, bool clear) {
    const int n = volume.resolution();
    if (n <= 0) return;
    if (!matches(volume)) {
        // Both sides stacked in z (otherSideTexel, voxel.glsl).
        traced_ = gl::Texture("voxel irradiance (traced)", {GL_TEXTURE_3D, volume.radianceFormat(), n, n, 2 * n, 1});
        gatherTexels_ = gl::Texture("voxel irradiance (gather texels)", {GL_TEXTURE_3D, GL_RGBA32UI, n, n, n, 1});
        // Read with texelFetch only; nearest keeps the one-level volumes complete for any sampler
        // state (an integer texture with linear filtering would be incomplete).
        for (const gl::Texture* t : {&traced_, &gatherTexels_}) t->setFilter(GL_NEAREST, GL_NEAREST);
        resolution_ = n;
        rgba8_ = volume.radianceRgba8();
        clear = true;  // new storage holds anything
    }
    if (!clear) return;
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(traced_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    const GLuint zeroBits[4] = {0, 0, 0, 0};  // an empty voxel to the gather
    glClearTexImage(gatherTexels_.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, zeroBits);
}

bool VoxelIrradianceCache::matches(const VoxelVolume& volume) const {
    return volume.resolution() > 0 && resolution_ == volume.resolution() && rgba8_ == volume.radianceRgba8() && traced_;
}

void VoxelIrradianceCache::bindGatherTexels() const {
    if (!gatherTexels_) return;
    // A one-level volume with nearest filtering (set where it is made); a sampler object left on
    // this unit by another pass would override that.
    glBindSampler(LIT_TEX_VOXEL_IRRADIANCE, 0);
    gatherTexels_.bind(LIT_TEX_VOXEL_IRRADIANCE);
}

std::size_t VoxelIrradianceCache::bytes() const {
    const auto n = static_cast<std::size_t>(resolution_);
    if (n == 0) return 0;
    return n * n * 2 * n * (rgba8_ ? 4 : 8) + n * n * n * 16;
}

}  // namespace lit
