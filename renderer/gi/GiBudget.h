#pragma once
// How much GI work one frame may do. The GI update after a light or geometry edit traces every
// occupied voxel once; the refinement after it traces every voxel again with each of the other
// cone sets in turn (docs/GI.md, "The update and its budget"). Neither changes what the light
// converges to, only how many frames it takes: the budget is the front end's choice, not a
// render setting. The editor spreads the work to keep its frame rate; lit-render finishes it in
// the still's one frame.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lit {

struct GiBudget {
    static constexpr std::uint32_t kAll = std::numeric_limits<std::uint32_t>::max();
    // Occupied voxels the update may trace this frame (bounces 2..N, then the irradiance; voxels
    // that replay recorded ray hits count a quarter, kReplayVoxelsPerFrameFactor). kAll: the whole
    // update in the edit's frame.
    std::uint32_t updateVoxels = kAll;
    // Voxels the refinement may trace this frame once the update is done; 0: it waits.
    std::uint32_t refineVoxels = 0;
    // GPU time the spread work (the update's shares and the refinement) may take this frame, ms;
    // the voxel counts above are then the most it may trace (GiPacer). 0: the counts alone. The
    // frame after an edit still voxelizes and injects whole: that work is not spread.
    double milliseconds = 0.0;

    // The whole update and every refinement round in one frame: a still's converged light.
    static constexpr GiBudget converge() { return {kAll, kAll, 0.0}; }
    // The whole update in one frame, no refinement: the single-frame steady state benchmarks time.
    static constexpr GiBudget updateOnly() { return {kAll, 0, 0.0}; }
    // This budget with its time raised to `ms` and its voxel counts scaled alike (kAll stays), when
    // it has a time and `ms` is more; else unchanged (the editor's budget while nothing is touched).
    GiBudget widenedTo(double ms) const {
        if (!(milliseconds > 0.0) || !(ms > milliseconds)) return *this;
        const double factor = ms / milliseconds;
        const auto scaled = [factor](std::uint32_t voxels) {
            if (voxels == kAll) return kAll;
            return static_cast<std::uint32_t>(std::min(std::ceil(voxels * factor), static_cast<double>(kAll - 1)));
        };
        return {scaled(updateVoxels), scaled(refineVoxels), ms};
    }
    bool operator==(const GiBudget&) const = default;
};

// A spread update's voxels per frame when they replay their recorded ray hits: a replayed voxel
// costs about a fifth of a marched one (docs/PERFORMANCE.md, "GI update"), so such a frame costs
// what a marching one does and an edit's light is final in a quarter of the frames.
inline constexpr int kReplayVoxelsPerFrameFactor = 4;
// ... and twice as many again in a bounce that gathers the change of the one before over a subset
// of the rays (GiSettings::laterBounceRayStride): at stride 4 such a bounce costs about half of one
// that gathers the light over every ray (docs/GI.md, "Bounces").
inline constexpr int kChangeVoxelsPerFrameFactor = 2;

// The subset of the rays bounce `bounce` (3, 4, ...) gathers its change over with one ray in
// `stride` (GiSettings::laterBounceRayStride), rotating so that successive bounces take different
// rays; −1 (every ray) for a stride of 1 or fewer than two rays a subset.
inline int changeSubsetFor(int bounce, int rays, int stride) {
    return stride > 1 && rays >= 2 * stride ? bounce % stride : -1;
}

}  // namespace lit
