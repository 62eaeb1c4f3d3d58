#pragma once
// Turns a time budget for the GI work spread over frames (GiBudget::milliseconds) into this
// frame's voxel counts, from what the same work cost in earlier frames. The costs come from the
// profiler's GPU timings of the spread passes, which arrive a few frames after the frame that ran
// them (Profiler::kFramesInFlight): each frame's traced voxels are kept until its timing comes.
//
// The update's marching and replaying voxels and the refinement are paced apart (a voxel of the
// update marches or replays its rays through several bounces, one of the refinement traces one
// cone set: their costs differ tenfold, and a replay's share of a march's depends on the scene).
// An edit's frame also voxelizes, injects and rebuilds the mips, which are not spread: their cost,
// measured on earlier edits of the same kind, comes off that frame's time. Until a cost is known
// the pacer starts small (kFirstVoxels) and grows at most kMaxGrowth times a frame, so a cost
// measured on a few voxels (where a dispatch's fixed cost weighs most) cannot make one frame
// overshoot. No GL here: tests/unit/test_gi_pacer.cpp.

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
// The GPU time of an edit's whole work among one frame's timings (a near level's scroll, the
// voxelization, solid bits and mip lists, the injection and the mips after it) of `which` (not
// All), and whether the frame voxelized; 0 ms for a frame that did not inject.
struct EditGiTime {
    double ms = 0.0;
    bool voxelized = false;
};
EditGiTime editGiMs(const std::vector<PassTiming>& timings, SpreadWork which);

class GiPacer {
public:
    // The update's voxels that march their rays (Update), and those that replay recorded hits in a
    // bounce that gathers the light (Replay), in one that gathers the last bounce's change over a
    // subset of the rays (ReplayChange), in a bounce after a voxelization of changed boxes (whose
    // crossing rays march again: ReplayChangedBoxes), and in the irradiance (ReplayIrradiance);
    // the refinement's.
    enum class Work : std::uint8_t { Update, Replay, ReplayChange, ReplayChangedBoxes, ReplayIrradiance, Refine };
    static constexpr std::size_t kWorks = 6;
    // The work an edit's frame does before its share, whole: none, an injection and the mips, or a
    // voxelization (of changed boxes or the whole volume) before them.
    enum class Edit : std::uint8_t { None, Inject, Voxelize };
    static constexpr std::size_t kEdits = 3;
    static constexpr std::uint32_t kFirstVoxels = 512;  // before any cost of the work is known
    static constexpr std::uint32_t kMinVoxels = 64;     // the least a frame with a budget traces
    static constexpr double kMaxGrowth = 2.0;           // per frame, over the voxels last given
    static constexpr double kSmoothing = 0.35;          // weight of a new cost in the running estimate

    // `budget` with its voxel counts cut to what its milliseconds allow (unchanged without a time
    // budget), for a frame whose update work is `update` (not Refine) after `edit`'s work.
    // The counts it holds are the most a frame may trace; kAll (everything in this frame) stands.
    GiBudget paced(const GiBudget& budget, Work update = Work::Update, Edit edit = Edit::None) const;

    // Frame `frame` traced `voxels` of `work` (in GiBudget's units: a voxel that replays its ray
    // hits counts 1 / kReplayVoxelsPerFrameFactor); a frame may trace several kinds (the update's
    // bounces one after the other), and a kind several times (their voxels add up). `allowed`:
    // the voxels its budget allowed, when more than it traced (a pass's last share, cut by the end
    // of the list): the next frame's growth is bounded by that, not by the short share.
    void traced(std::uint64_t frame, Work work, std::uint32_t voxels, std::uint32_t allowed = 0);
    // The spread passes of frame `frame` took `gpuMs` (once its timings are in; spreadGiMs, which
    // leaves an edit's whole work out). A frame of several kinds gives each the share of the time
    // their estimated costs say.
    void measured(std::uint64_t frame, double gpuMs);
    // An edit's frame spent `gpuMs` on the work it does whole (edit: Inject or Voxelize).
    void editMeasured(Edit edit, double gpuMs);

    // ms per voxel of `work`, 0 while unknown.
    double costPerVoxel(Work work) const { return cost_[index(work)]; }
    // ... or, for a kind of the update not measured yet, the dearest known cost of the others.
    double estimatedCostPerVoxel(Work work) const;
    // ms of an edit's whole work, 0 while unknown (and for Edit::None).
    double editCost(Edit edit) const { return editCost_[static_cast<std::size_t>(edit)]; }

private:
    static constexpr std::size_t index(Work work) { return static_cast<std::size_t>(work); }
    std::uint32_t voxelsFor(Work work, double milliseconds, std::uint32_t most) const;

    struct Traced {
        std::uint64_t frame;
        Work work;
        std::uint32_t voxels;
    };
    std::deque<Traced> traced_;  // frames whose timings have not come yet
    std::array<double, kWorks> cost_{};
    std::array<std::uint32_t, kWorks> lastTraced_{};  // the voxels the last recorded frame of each work traced
    std::array<double, kEdits> editCost_{};  // ms, by Edit
};

}  // namespace lit
