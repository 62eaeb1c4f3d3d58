#pragma once
// How much GI work one frame may do. The GI update after a light or geometry edit traces every
// occupied voxel once; the refinement after it traces every voxel again with each of the other
// cone sets in turn (docs/GI.md, "The update and its budget"). Neither changes what the light
// converges to, only how many frames it takes: the budget is the front end's choice, not a
// render setting. The editor spreads the work to keep its frame rate; lit-render finishes it in
// the still's one frame.

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
    bool operator==(const GiBudget&) const = default;
};

// A spread update's voxels per frame when they replay their recorded ray hits: a replayed voxel
// costs about a fifth of a marched one (docs/PERFORMANCE.md, "GI update"), so such a frame costs
// what a marching one does and an edit's light is final in a quarter of the frames.
inline constexpr int kReplayVoxelsPerFrameFactor = 4;

}  // namespace lit
