#include "gi/RayHitCache.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "gi/VoxelDispatch.h"

namespace lit {

static_assert(VoxelChangeTracker::kMaxBoxes == LIT_CHANGED_BOXES);

bool RayHitCache::ensure(int rays, std::uint32_t entries) {
    reallocated_ = false;
    if (rays <= 0 || entries == 0) return false;
    const std::size_t needed = bytesFor(rays, entries);
    if (needed > kMaxBytes) {
        reallocated_ = static_cast<bool>(buffer_);
        buffer_ = {};
        epochs_ = {};
        return false;
    }
    // Kept while it fits and is not more than twice what is needed (a voxelization that changes
    // the count a little reallocates nothing); made with a quarter more entries than needed, for
    // the entries a voxelization of changed boxes appends.
    const std::size_t hitBytes = static_cast<std::size_t>(entries) * 2 * static_cast<std::size_t>(rays) * 4;
    if (buffer_.size() < hitBytes || buffer_.size() > 2 * hitBytes) {
        const std::size_t room = std::min<std::size_t>(entries + entries / 4, std::numeric_limits<std::uint32_t>::max());
        buffer_ = gl::Buffer("voxel ray hits", room * 2 * static_cast<std::size_t>(rays) * 4, nullptr, 0);
        epochs_ = gl::Buffer("voxel ray hit epochs", room * 4, nullptr, 0);
        glClearNamedBufferData(epochs_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
        changed_.clear();
        reallocated_ = true;
    }
    return true;
}

void RayHitCache::markChanged(const std::vector<VoxelBox>& boxes) {
    ++epoch_;
    for (const VoxelBox& box : boxes) changed_.push_back({box, epoch_});
    // Too many boxes: the pair whose joined box adds the fewest voxels becomes one, with the later
    // epoch (an entry recorded before it must test both; one recorded after both tests neither).
    while (changed_.size() > VoxelChangeTracker::kMaxBoxes) {
        std::vector<VoxelBox> kept;
        for (const ChangedBox& c : changed_) kept.push_back(c.box);
        const auto [bestI, bestJ] = cheapestJoin(kept);
        changed_[bestI] = {changed_[bestI].box.joined(changed_[bestJ].box),
                           std::max(changed_[bestI].epoch, changed_[bestJ].epoch)};
        changed_.erase(changed_.begin() + static_cast<std::ptrdiff_t>(bestJ));
    }
}

void RayHitCache::endPass() {
    std::erase_if(changed_, [&](const ChangedBox& c) { return c.epoch <= passEpoch_; });
}

void RayHitCache::bind(const gl::Program& program, ConeFeatures features, RayHits hits) const {
    if (features.voxelRays <= 0) return;
    const bool cached = hits != RayHits::Off && static_cast<bool>(buffer_);
    glProgramUniform1i(program.id(), program.location("uRayHits"), !cached ? 0 : (hits == RayHits::Record ? 1 : 2));
    if (!cached) return;
    glProgramUniform1ui(program.id(), program.location("uRayEpoch"), epoch_);
    std::vector<VoxelBox> boxes;
    std::vector<int> epochs;  // in w: the epoch of each change
    for (const ChangedBox& c : changed_) {
        boxes.push_back(c.box);
        epochs.push_back(static_cast<int>(c.epoch));
    }
    setBoxUniforms(program, "uChangedBox", boxes, epochs);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_VOXEL_RAY_HITS);
    epochs_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_VOXEL_RAY_EPOCHS);
}

}  // namespace lit
