#include "gi/RayHitCache.h"

#include <shared.h>

namespace lit {

bool RayHitCache::ensure(int rays, std::uint32_t entries) {
    reallocated_ = false;
    if (rays <= 0 || entries == 0) return false;
    const std::size_t needed = bytesFor(rays, entries);
    if (needed > kMaxBytes) {
        reallocated_ = static_cast<bool>(buffer_);
        buffer_ = {};
        return false;
    }
    // Kept while it fits and is not more than twice what is needed (a voxelization that changes
    // the count a little reallocates nothing).
    if (buffer_.size() < needed || buffer_.size() > 2 * needed) {
        buffer_ = gl::Buffer("voxel ray hits", needed, nullptr, 0);
        reallocated_ = true;
    }
    return true;
}

void RayHitCache::bind(const gl::Program& program, ConeFeatures features, RayHits hits) const {
    if (features.voxelRays <= 0) return;
    const bool cached = hits != RayHits::Off && static_cast<bool>(buffer_);
    glProgramUniform1i(program.id(), program.location("uRayHits"), !cached ? 0 : (hits == RayHits::Record ? 1 : 2));
    if (cached) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_VOXEL_RAY_HITS);
    }
}

}  // namespace lit
