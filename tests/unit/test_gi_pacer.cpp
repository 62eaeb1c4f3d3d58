#include <gtest/gtest.h>

#include "gi/GiPacer.h"

using namespace lit;
using Work = GiPacer::Work;

namespace {

// Frames that trace what `pacer` allows of `work` at `msPerVoxel` (ms), with their timings
// arriving `lag` frames late, as the profiler's do. Returns the voxels of the last frame.
std::uint32_t runFrames(GiPacer& pacer, const GiBudget& budget, Work work, double msPerVoxel, int frames,
                        std::uint64_t& frame, int lag = 4) {
    std::vector<std::pair<std::uint64_t, double>> inFlight;
    std::uint32_t voxels = 0;
    for (int i = 0; i < frames; ++i, ++frame) {
        const GiBudget paced = pacer.paced(budget, work == Work::Refine ? Work::Update : work);
        voxels = work == Work::Refine ? paced.refineVoxels : paced.updateVoxels;
        pacer.traced(frame, work, voxels);
        inFlight.emplace_back(frame, voxels * msPerVoxel);
        if (inFlight.size() > static_cast<std::size_t>(lag)) {
            pacer.measured(inFlight.front().first, inFlight.front().second);
            inFlight.erase(inFlight.begin());
        }
    }
    return voxels;
}

}  // namespace

TEST(GiPacer, WithoutATimeBudgetTheVoxelCountsStand) {
    GiPacer pacer;
    const GiBudget budget{16384, 8192, 0.0};
    EXPECT_EQ(pacer.paced(budget), budget);
    EXPECT_EQ(pacer.paced(GiBudget::converge()), GiBudget::converge());
}

TEST(GiPacer, StartsSmallThenTracesWhatTheTimeAllows) {
    GiPacer pacer;
    const GiBudget budget{1u << 24, 0, 25.0};
    EXPECT_EQ(pacer.paced(budget).updateVoxels, GiPacer::kFirstVoxels);
    EXPECT_EQ(pacer.paced(budget).refineVoxels, 0u) << "a refinement that waits keeps waiting";
    std::uint64_t frame = 1;
    // 0.01 ms a voxel: 2500 voxels fill 25 ms.
    const std::uint32_t voxels = runFrames(pacer, budget, Work::Update, 0.01, 40, frame);
    EXPECT_NEAR(voxels, 2500.0, 2.0);
    EXPECT_NEAR(pacer.costPerVoxel(Work::Update), 0.01, 1e-9);
    EXPECT_EQ(pacer.costPerVoxel(Work::Refine), 0.0) << "the works are paced apart";
}

TEST(GiPacer, TheCountsInTheBudgetAreTheMost) {
    GiPacer pacer;
    const GiBudget budget{1000, 300, 25.0};
    std::uint64_t frame = 1;
    EXPECT_EQ(runFrames(pacer, budget, Work::Update, 0.001, 30, frame), 1000u);
    EXPECT_EQ(runFrames(pacer, budget, Work::Refine, 0.001, 30, frame), 300u);
}

TEST(GiPacer, GrowsAtMostTwiceAFrameAndFollowsASlowerCost) {
    GiPacer pacer;
    const GiBudget budget{1u << 24, 1u << 20, 20.0};
    std::uint64_t frame = 1;
    // One cheap measurement would allow 20 / 1e-5 = 2 million voxels at once.
    pacer.traced(frame, Work::Refine, GiPacer::kFirstVoxels);
    pacer.measured(frame, GiPacer::kFirstVoxels * 1e-5);
    ++frame;
    EXPECT_EQ(pacer.paced(budget).refineVoxels, 2 * GiPacer::kFirstVoxels);
    // The machine gets ten times slower: the voxels follow down to the new cost's.
    runFrames(pacer, budget, Work::Refine, 1e-5, 30, frame);
    const std::uint32_t slow = runFrames(pacer, budget, Work::Refine, 1e-4, 40, frame);
    EXPECT_NEAR(slow, 200000.0, 2000.0);
}

TEST(GiPacer, FramesWithoutTimingsOrWithOtherWorkAreNotMeasured) {
    GiPacer pacer;
    pacer.traced(5, Work::Update, 1000);
    pacer.measured(7, 100.0);  // frame 5's timing never came; frame 7 recorded no spread work
    EXPECT_EQ(pacer.costPerVoxel(Work::Update), 0.0);
    pacer.traced(8, Work::Update, 1000);
    pacer.measured(8, 0.0);  // a pass that did not run reports 0
    EXPECT_EQ(pacer.costPerVoxel(Work::Update), 0.0);
    pacer.traced(9, Work::Update, 1000);
    pacer.measured(9, 10.0);
    EXPECT_DOUBLE_EQ(pacer.costPerVoxel(Work::Update), 0.01);
}

TEST(GiPacer, EverythingAtOnceStandsWithATimeBudget) {
    GiPacer pacer;
    const GiBudget all{GiBudget::kAll, GiBudget::kAll, 25.0};
    EXPECT_EQ(pacer.paced(all), all);
}

TEST(GiPacer, NeverBelowTheLeastAFrameTraces) {
    GiPacer pacer;
    pacer.traced(1, Work::Update, 100);
    pacer.measured(1, 1000.0);  // 10 ms a voxel: 25 ms would allow 2
    EXPECT_EQ(pacer.paced({1u << 24, 0, 25.0}).updateVoxels, GiPacer::kMinVoxels);
}

// Each kind of update pass is paced by its own cost; one not measured yet starts from the dearest
// known cost of the others rather than from kFirstVoxels (a move's update passes through several).
TEST(GiPacer, UpdateKindsArePacedApartAndANewOneStartsFromTheDearestKnown) {
    GiPacer pacer;
    const GiBudget budget{1u << 24, 0, 20.0};
    std::uint64_t frame = 1;
    runFrames(pacer, budget, Work::Replay, 0.002, 40, frame);
    EXPECT_NEAR(pacer.costPerVoxel(Work::Replay), 0.002, 1e-9);
    EXPECT_EQ(pacer.costPerVoxel(Work::ReplayChange), 0.0);
    EXPECT_NEAR(pacer.paced(budget, Work::ReplayChange).updateVoxels, 10000.0, 1.0) << "Replay's cost as the prior";
    pacer.traced(frame, Work::ReplayChange, 1000);
    pacer.measured(frame, 1.0);  // 0.001 ms a unit
    ++frame;
    EXPECT_NEAR(pacer.paced(budget, Work::ReplayChange).updateVoxels, 2000.0, 1.0) << "grows at most twice a frame";
    EXPECT_NEAR(pacer.paced(budget, Work::Replay).updateVoxels, 10000.0, 1.0) << "Replay keeps its own cost";
    EXPECT_NEAR(pacer.paced(budget, Work::ReplayIrradiance).updateVoxels, 10000.0, 1.0) << "the dearer of the two";
}

// An edit's frame voxelizes, injects and rebuilds the mips whole: their measured cost comes off the
// frame's time, and an edit that takes it all leaves the least share.
TEST(GiPacer, AnEditsWholeWorkComesOffItsFrame) {
    GiPacer pacer;
    const GiBudget budget{1u << 24, 0, 25.0};
    std::uint64_t frame = 1;
    runFrames(pacer, budget, Work::Update, 0.01, 40, frame);
    EXPECT_EQ(pacer.paced(budget, Work::Update, GiPacer::Edit::Voxelize).updateVoxels, 2500u) << "not measured yet";
    pacer.editMeasured(GiPacer::Edit::Voxelize, 15.0);
    pacer.editMeasured(GiPacer::Edit::Inject, 5.0);
    EXPECT_NEAR(pacer.paced(budget, Work::Update, GiPacer::Edit::Voxelize).updateVoxels, 1000.0, 1.0);
    EXPECT_NEAR(pacer.paced(budget, Work::Update, GiPacer::Edit::Inject).updateVoxels, 2000.0, 1.0);
    EXPECT_NEAR(pacer.paced(budget).updateVoxels, 2500.0, 1.0) << "a frame without an edit keeps its whole time";
    pacer.editMeasured(GiPacer::Edit::Voxelize, 200.0);
    EXPECT_EQ(pacer.paced(budget, Work::Update, GiPacer::Edit::Voxelize).updateVoxels, GiPacer::kMinVoxels);
    EXPECT_EQ(pacer.paced(GiBudget::converge(), Work::Update, GiPacer::Edit::Voxelize), GiBudget::converge());
}

TEST(GiPacer, AnEditsWholeWorkAmongAFramesTimings) {
    const auto timing = [](const char* name, double ms) { return PassTiming{name, ms, 0.0, true, 7}; };
    const std::vector<PassTiming> moved{
        timing("voxelize", 3.0), timing("solid voxels", 1.0), timing("mip lists", 2.0),  timing("inject", 4.0),
        timing("mipmap", 10.0),  timing("bounces", 80.0),     timing("near inject", 9.0)};
    EditGiTime edit = editGiMs(moved, SpreadWork::SceneVolume);
    EXPECT_DOUBLE_EQ(edit.ms, 20.0);
    EXPECT_TRUE(edit.voxelized);
    EXPECT_DOUBLE_EQ(spreadGiMs(moved, SpreadWork::SceneVolume), 80.0) << "the share is measured apart";
    edit = editGiMs(moved, SpreadWork::NearLevels);
    EXPECT_DOUBLE_EQ(edit.ms, 9.0);
    EXPECT_FALSE(edit.voxelized);
    // The mips rebuilt after a spread update's last bounce are no edit.
    EXPECT_DOUBLE_EQ(editGiMs({timing("mipmap", 10.0), timing("bounces", 50.0)}, SpreadWork::SceneVolume).ms, 0.0);
}

// A frame that traced several kinds (the next bounce started in the time the last one left) gives
// each the share of its time their estimated costs say: a frame that took twice the estimate
// doubles both.
TEST(GiPacer, AFrameOfSeveralKindsSplitsItsTimeByTheirEstimates) {
    GiPacer pacer;
    pacer.traced(1, Work::Replay, 1000);
    pacer.measured(1, 10.0);  // 0.01 ms a unit
    pacer.traced(2, Work::ReplayChange, 1000);
    pacer.measured(2, 5.0);  // 0.005
    pacer.traced(3, Work::Replay, 600);
    pacer.traced(3, Work::ReplayChange, 400);
    pacer.traced(3, Work::ReplayChange, 400);  // the same kind twice in a frame adds up
    pacer.measured(3, 2.0 * (600 * 0.01 + 800 * 0.005));
    // Each new cost is twice the old, weighed in at kSmoothing.
    EXPECT_NEAR(pacer.costPerVoxel(Work::Replay), 0.01 * (1.0 + GiPacer::kSmoothing), 1e-12);
    EXPECT_NEAR(pacer.costPerVoxel(Work::ReplayChange), 0.005 * (1.0 + GiPacer::kSmoothing), 1e-12);
}

// A pass's last share is cut by the end of the list, and an edit's frame by the edit's work: the
// growth after them is bounded by what the budget allowed, not by the short share.
TEST(GiPacer, AShortShareDoesNotSlowTheNextFrame) {
    GiPacer pacer;
    const GiBudget budget{1u << 24, 0, 20.0};
    std::uint64_t frame = 1;
    runFrames(pacer, budget, Work::Replay, 0.002, 40, frame);
    const std::uint32_t full = pacer.paced(budget, Work::Replay).updateVoxels;
    EXPECT_NEAR(full, 10000.0, 1.0);
    pacer.traced(frame, Work::Replay, 64, full);
    EXPECT_EQ(pacer.paced(budget, Work::Replay).updateVoxels, full);
    pacer.traced(frame + 1, Work::Replay, 64);  // cut by the budget itself: growth from there
    EXPECT_EQ(pacer.paced(budget, Work::Replay).updateVoxels, 128u);
}

TEST(GiBudget, WidenedScalesTheTimeAndTheCountsAlike) {
    const GiBudget editor{16384, 8192, 25.0};
    const GiBudget idle = editor.widenedTo(50.0);
    EXPECT_EQ(idle.milliseconds, 50.0);
    EXPECT_EQ(idle.updateVoxels, 32768u);
    EXPECT_EQ(idle.refineVoxels, 16384u);
    EXPECT_EQ(GiBudget({GiBudget::kAll, 0, 25.0}).widenedTo(100.0).updateVoxels, GiBudget::kAll);
    // Never narrowed, and a budget of counts alone (no time) stays as it is.
    EXPECT_EQ(editor.widenedTo(10.0), editor);
    EXPECT_EQ(editor.widenedTo(0.0), editor);
    EXPECT_EQ(GiBudget({4096, 1024, 0.0}).widenedTo(50.0), GiBudget({4096, 1024, 0.0}));
}
