#pragma once
// The voxel rays' first hits (bounce.comp.glsl, LIT_SSBO_VOXEL_RAY_HITS): one uint per entry of
// the occupied-voxel list, side and ray. A ray's hit depends on the voxels, not on their light, so
// a trace over the list that records them lets the traces of the same rays after a light edit
// replay them (no ray marched) until the voxels change. The bounce and the irradiance's first
// cone set trace the same rays; the refinement's other sets march.
//
// After a voxelization of changed boxes (VoxelChangeTracker) the hits stay: each entry carries the
// epoch its hits were recorded in, each changed box the epoch of its change, and a replaying trace
// marches again (and records) only the rays of older entries whose voxel lies in a newer box or
// that cross one before their hits.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gi/ConeProgram.h"
#include "gi/VoxelRegions.h"
#include "gl/Objects.h"
#include "gl/Shader.h"

namespace lit {

// What a voxel-ray trace does with the cache.
enum class RayHits { Off, Record, Replay };

class RayHitCache {
public:
    static constexpr std::size_t kMaxBytes = std::size_t{1} << 30;  // 1 GiB
    // Bytes the hits of `rays` rays per side over `entries` list entries take (and their epochs).
    static std::size_t bytesFor(int rays, std::uint32_t entries) {
        return static_cast<std::size_t>(entries) * (2 * static_cast<std::size_t>(rays) + 1) * 4;
    }

    // Makes (or keeps) the buffer for `rays` rays over `entries` entries; false when that needs
    // more than kMaxBytes (the passes then march every time). A new buffer holds no hits:
    // reallocated() says whether this call made one.
    bool ensure(int rays, std::uint32_t entries);
    bool reallocated() const { return reallocated_; }
    std::size_t bytes() const { return buffer_.size() + epochs_.size(); }

    // The voxels of `boxes` were voxelized again: hits whose rays cross them are stale.
    void markChanged(const std::vector<VoxelBox>& boxes);
    // The whole volume was voxelized again: the next trace records every hit (no box needed).
    void forgetChanges() { changed_.clear(); }
    // A trace over the whole list begins, and one ended: every entry then holds hits recorded
    // after the boxes changed before it began, which are no longer needed.
    void beginPass() { passEpoch_ = epoch_; }
    void endPass();
    std::size_t changedBoxes() const { return changed_.size(); }

    // Sets uRayHits (0 off, 1 record, 2 replay) of a voxel-ray program and binds the buffer;
    // nothing for cones.
    void bind(const gl::Program& program, ConeFeatures features, RayHits hits) const;

private:
    struct ChangedBox {
        VoxelBox box;
        std::uint32_t epoch = 0;
    };
    gl::Buffer buffer_;
    gl::Buffer epochs_;  // per entry, the epoch its hits were recorded in (LIT_SSBO_VOXEL_RAY_EPOCHS)
    bool reallocated_ = false;
    std::uint32_t epoch_ = 1;      // the epoch a trace records in now
    std::uint32_t passEpoch_ = 0;  // epoch_ when the last pass over the whole list began
    std::vector<ChangedBox> changed_;
};

}  // namespace lit
