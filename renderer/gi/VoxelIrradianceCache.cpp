#include "gi/VoxelIrradianceCache.h"

#include <shared.h>

#include "gi/VoxelVolume.h"

namespace lit {

namespace {
gl::Texture makeGatherTexels(int n) {
    gl::Texture texels("voxel irradiance (gather texels)", {GL_TEXTURE_3D, GL_RGBA32UI, n, n, n, 1});
    // Read with texelFetch only; nearest keeps the one-level volume complete for any sampler
    // state (an integer texture with linear filtering would be incomplete).
    texels.setFilter(GL_NEAREST, GL_NEAREST);
    return texels;
}

void clearGatherTexels(const gl::Texture& texels) {
    const GLuint zeroBits[4] = {0, 0, 0, 0};  // an empty voxel to the gather
    glClearTexImage(texels.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, zeroBits);
}
}  // namespace

void VoxelIrradianceCache::prepare(const VoxelVolume& volume, bool clear, bool keepShown) {
    const int n = volume.resolution();
    if (n <= 0) return;
    if (!matches(volume)) {
        // Both sides stacked in z (otherSideTexel, voxel.glsl).
        traced_ = gl::Texture("voxel irradiance (traced)", {GL_TEXTURE_3D, volume.radianceFormat(), n, n, 2 * n, 1});
        traced_.setFilter(GL_NEAREST, GL_NEAREST);
        gatherTexels_[0] = makeGatherTexels(n);
        gatherTexels_[1] = {};
        written_ = shown_ = 0;
        resolution_ = n;
        rgba8_ = volume.radianceRgba8();
        clear = true;  // new storage holds anything
        keepShown = false;
    }
    if (!clear) return;
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(traced_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    if (keepShown && shown_ == written_) {
        // The shown set is complete: write the new update into the other one. (When the pixels
        // already gather an older complete set, the incomplete one is written again.)
        written_ = 1 - shown_;
        if (!gatherTexels_[written_]) gatherTexels_[written_] = makeGatherTexels(n);
    } else if (!keepShown) {
        shown_ = written_;
    }
    clearGatherTexels(gatherTexels_[written_]);
}

void VoxelIrradianceCache::forget(const std::vector<VoxelBox>& boxes) const {
    if (!traced_) return;
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (const VoxelBox& box : boxes) {
        const glm::ivec3 size = box.max - box.min;
        for (int side = 0; side < 2; ++side)  // both sides, stacked in z (otherSideTexel, voxel.glsl)
            glClearTexSubImage(traced_.id(), 0, box.min.x, box.min.y, box.min.z + side * resolution_, size.x, size.y,
                               size.z, GL_RGBA, GL_FLOAT, zero);
    }
}

bool VoxelIrradianceCache::matches(const VoxelVolume& volume) const {
    return volume.resolution() > 0 && resolution_ == volume.resolution() && rgba8_ == volume.radianceRgba8() && traced_;
}

void VoxelIrradianceCache::bindGatherTexels() const {
    const gl::Texture& texels = gatherTexels_[shown_];
    if (!texels) return;
    // A one-level volume with nearest filtering (set where it is made); a sampler object left on
    // this unit by another pass would override that.
    glBindSampler(LIT_TEX_VOXEL_IRRADIANCE, 0);
    texels.bind(LIT_TEX_VOXEL_IRRADIANCE);
}

std::size_t VoxelIrradianceCache::bytes() const {
    const auto n = static_cast<std::size_t>(resolution_);
    if (n == 0) return 0;
    const std::size_t gatherSets = gatherTexels_[1] ? 2 : 1;
    return n * n * 2 * n * (rgba8_ ? 4 : 8) + gatherSets * n * n * n * 16;
}

}  // namespace lit
