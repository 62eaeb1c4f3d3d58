#pragma once
// The voxel rays' first hits (bounce.comp.glsl, LIT_SSBO_VOXEL_RAY_HITS): one uint per entry of
// the occupied-voxel list, side and ray. A ray's hit depends on the voxels, not on their light, so
// a trace over the list that records them lets the traces of the same rays after a light edit
// replay them (no ray marched) until the voxels change. The bounce and the irradiance's first
// cone set trace the same rays; the refinement's other sets march.

#include <cstddef>
#include <cstdint>

#include "gi/ConeProgram.h"
#include "gl/Objects.h"
#include "gl/Shader.h"

namespace lit {

// What a voxel-ray trace does with the cache.
enum class RayHits { Off, Record, Replay };

class RayHitCache {
public:
    static constexpr std::size_t kMaxBytes = std::size_t{1} << 30;  // 1 GiB
    // Bytes the hits of `rays` rays per side over `entries` list entries take.
    static std::size_t bytesFor(int rays, std::uint32_t entries) {
        return static_cast<std::size_t>(entries) * 2 * static_cast<std::size_t>(rays) * 4;
    }

    // Makes (or keeps) the buffer for `rays` rays over `entries` entries; false when that needs
    // more than kMaxBytes (the passes then march every time). A new buffer holds no hits:
    // reallocated() says whether this call made one.
    bool ensure(int rays, std::uint32_t entries);
    bool reallocated() const { return reallocated_; }
    std::size_t bytes() const { return buffer_.size(); }

    // Sets uRayHits (0 off, 1 record, 2 replay) of a voxel-ray program and binds the buffer;
    // nothing for cones.
    void bind(const gl::Program& program, ConeFeatures features, RayHits hits) const;

private:
    gl::Buffer buffer_;
    bool reallocated_ = false;
};

}  // namespace lit
