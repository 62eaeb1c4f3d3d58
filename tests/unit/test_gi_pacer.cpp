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
        const GiBudget paced = pacer.paced(budget);
        voxels = work == Work::Update ? paced.updateVoxels : paced.refineVoxels;
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
