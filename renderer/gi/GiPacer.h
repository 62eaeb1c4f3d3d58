#pragma once
// Turns a time budget for the GI work spread over frames (GiBudget::milliseconds) into this
// frame's voxel counts, from what the same work cost in earlier frames. The costs come from the
// profiler's GPU timings of the spread passes, which arrive a few frames after the frame that ran
// them (Profiler::kFramesInFlight): each frame's traced voxels are kept until its timing comes.
//
// The update and the refinement are paced apart (a voxel of the update marches or replays its
// rays through several bounces, one of the refinement traces one cone set: their costs differ
// tenfold). Until a cost is known the pacer starts small (kFirstVoxels) and grows at most
// kMaxGrowth times a frame, so a cost measured on a few voxels (where a dispatch's fixed cost
// weighs most) cannot make one frame overshoot. No GL here: tests/unit/test_gi_pacer.cpp.

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

#include "Profiler.h"
#include "gi/GiBudget.h"

namespace lit {

// Whose spread GI passes: the scene volume's, the near levels' ("near bounces", ...), or both.
enum class SpreadWork { SceneVolume, NearLevels, All };
// The GPU time of the spread GI passes (the bounces, the voxel irradiance and its filter) among
// one frame's timings: what GiBudget::milliseconds bounds.
double spreadGiMs(const std::vector<PassTiming>& timings, SpreadWork which = SpreadWork::All);

class GiPacer {
public:
    enum class Work : std::uint8_t { Update, Refine };
    static constexpr std::uint32_t kFirstVoxels = 512;  // before any cost of the work is known
    static constexpr std::uint32_t kMinVoxels = 64;     // the least a frame with a budget traces
    static constexpr double kMaxGrowth = 2.0;           // per frame, over the voxels last given
    static constexpr double kSmoothing = 0.35;          // weight of a new cost in the running estimate

    // `budget` with its voxel counts cut to what its milliseconds allow (unchanged without a time
    // budget). The counts it holds are the most a frame may trace; kAll (everything in this
    // frame) stands.
    GiBudget paced(const GiBudget& budget) const;

    // Frame `frame` traced `voxels` of `work` (in GiBudget's units: a voxel that replays its ray
    // hits counts 1 / kReplayVoxelsPerFrameFactor). Frames that also did other GI work (an
    // injection) or both kinds are not recorded: their time is no measure of either.
    void traced(std::uint64_t frame, Work work, std::uint32_t voxels);
    // The spread passes of frame `frame` took `gpuMs` (once its timings are in).
    void measured(std::uint64_t frame, double gpuMs);

    // ms per voxel of `work`, 0 while unknown.
    double costPerVoxel(Work work) const { return cost_[index(work)]; }

private:
    static constexpr std::size_t index(Work work) { return work == Work::Update ? 0 : 1; }
    std::uint32_t voxelsFor(Work work, double milliseconds, std::uint32_t most) const;

    struct Traced {
        std::uint64_t frame;
        Work work;
        std::uint32_t voxels;
    };
    std::deque<Traced> traced_;  // frames whose timings have not come yet
    std::array<double, 2> cost_{0.0, 0.0};
    std::array<std::uint32_t, 2> lastTraced_{0, 0};  // the voxels the last recorded frame of each work traced
};

}  // namespace lit
