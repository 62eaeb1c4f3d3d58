// The GI scheduler's decisions, without GL: what an edit starts, how a GiBudget spreads the update
// over frames, the ray-hit cache's record and replay, a light dragged while an update runs, and the
// refinement.

#include <gtest/gtest.h>

#include "gi/GiScheduler.h"

namespace {

using lit::GiBudget;
using lit::GiLightKey;
using lit::GiScheduler;
using lit::RayHits;
using lit::VoxelKey;
using lit::VoxelRange;

// The cached mode, two bounces, 32 voxel rays.
GiLightKey cachedTwoBounces() {
    lit::RenderSettings settings;
    settings.gi.bounces = 2;
    return GiLightKey::of(settings);
}

// A scheduler that has voxelized `occupied` voxels and injected `light` once, all at once.
GiScheduler injected(std::uint32_t occupied, const GiLightKey& light = cachedTwoBounces()) {
    GiScheduler s;
    const VoxelKey voxels{1, 1, nullptr};
    const GiScheduler::Changes first = s.changes(voxels, light, true, true, true);
    s.voxelized(voxels, occupied, true);
    s.startUpdate(first, light, GiBudget::updateOnly());
    return s;
}

// The same, its update done and the voxel rays' hits recorded: a light or node edit replays them.
GiScheduler settledWithRayHits(std::uint32_t occupied) {
    GiScheduler s = injected(occupied);
    s.rayHits(cachedTwoBounces().voxelRays, true, true);
    s.listTraced(RayHits::Record);
    s.irradianceDone();
    return s;
}

TEST(GiScheduler, TheFirstFrameVoxelizesAndInjectsEverythingAtOnce) {
    GiScheduler s;
    const GiLightKey light = cachedTwoBounces();
    const VoxelKey voxels{1, 1, nullptr};
    const GiScheduler::Changes changes = s.changes(voxels, light, true, true, false);
    EXPECT_TRUE(changes.voxelize);
    EXPECT_TRUE(changes.inject);
    EXPECT_EQ(changes.reason, "first GI frame");
    s.voxelized(voxels, 5000, true);
    const GiScheduler::UpdateStart start = s.startUpdate(changes, light, GiBudget::converge());
    EXPECT_EQ(start.bouncesNow, 1) << "bounce 2 traced whole in this frame";
    EXPECT_TRUE(start.prepareIrradiance);
    EXPECT_TRUE(start.clearIrradiance) << "after a voxelization the old values sit at old geometry";
    EXPECT_FALSE(start.keepLastUpdate);
    EXPECT_EQ(s.state().progress.irradianceLeft, 5000u);
    EXPECT_FALSE(s.spreadsOverFrames(light, GiBudget::converge()));
    EXPECT_EQ(s.state().light, light);
}

// Under a time budget an update is spread whenever the list is complete, also when one pass fits a
// frame's share: run all at once, its bounces and irradiance would take the frame several times.
TEST(GiScheduler, ATimeBudgetAlwaysSpreadsTheUpdate) {
    GiScheduler s;
    const GiLightKey light = cachedTwoBounces();
    s.voxelized({1, 1, nullptr}, 5000, true);
    EXPECT_FALSE(s.spreadsOverFrames(light, {10000, 0, 0.0})) << "a share that covers the list: all at once";
    EXPECT_TRUE(s.spreadsOverFrames(light, {10000, 0, 25.0}));
    EXPECT_FALSE(s.spreadsOverFrames(light, {GiBudget::kAll, 0, 25.0})) << "kAll asks for everything now";
    s.voxelized({1, 1, nullptr}, 5000, false);
    EXPECT_FALSE(s.spreadsOverFrames(light, {10000, 0, 25.0})) << "an incomplete list runs over the grid at once";
}

TEST(GiScheduler, NothingChangedIsNoWorkAndTheStateStaysEqual) {
    GiScheduler s = injected(5000);
    s.irradianceDone();
    const lit::GiState before = s.state();
    const GiScheduler::Changes changes = s.changes(before.voxels, before.light, false, false, false);
    EXPECT_FALSE(changes.voxelize);
    EXPECT_FALSE(changes.inject);
    EXPECT_EQ(s.state(), before);
}

TEST(GiScheduler, WhatRetracesTheVoxels) {
    const GiLightKey cached = cachedTwoBounces();
    GiLightKey rays = cached;
    rays.voxelRays = 64;
    EXPECT_TRUE(rays.retraces(cached));
    GiLightKey intensity = cached;
    intensity.intensity = 2.0f;
    EXPECT_TRUE(intensity.retraces(cached));
    // The fast mode with one bounce traces nothing per voxel: the cone settings do not matter.
    lit::RenderSettings fast;
    fast.gi.mode = lit::GiMode::Fast;
    fast.gi.bounces = 1;
    const GiLightKey fastKey = GiLightKey::of(fast);
    GiLightKey fastIntensity = fastKey;
    fastIntensity.intensity = 2.0f;
    EXPECT_FALSE(fastIntensity.retraces(fastKey));
    GiLightKey moreBounces = fastKey;
    moreBounces.bounces = 3;
    EXPECT_TRUE(moreBounces.retraces(fastKey));
    // A light edit alone re-injects without re-tracing, and lets level 0 keep the last light.
    GiScheduler s = injected(5000);
    const GiScheduler::Changes changes = s.changes(s.state().voxels, cached, false, false, true);
    EXPECT_TRUE(changes.inject);
    EXPECT_FALSE(changes.retrace);
    EXPECT_TRUE(changes.onlyLight);
    EXPECT_EQ(changes.reason, "lights or shadows changed");
    EXPECT_TRUE(s.startUpdate(changes, cached, GiBudget::updateOnly()).keepLastUpdate);
}

// A budget below the list: bounce 2 in ⌈occupied ÷ per frame⌉ shares, then the irradiance, the
// progress rising through both to 1.
TEST(GiScheduler, ABudgetSpreadsTheBounceAndTheIrradianceOverFrames) {
    GiScheduler s;
    const GiLightKey light = cachedTwoBounces();
    const VoxelKey voxels{1, 1, nullptr};
    const GiScheduler::Changes changes = s.changes(voxels, light, true, true, true);
    s.voxelized(voxels, 2500, true);
    const GiBudget budget{1000, 0};
    const GiScheduler::UpdateStart start = s.startUpdate(changes, light, budget);
    EXPECT_EQ(start.bouncesNow, 0);
    EXPECT_EQ(s.state().progress.bounce, 2);
    EXPECT_EQ(s.updateStage(false), "bounce 2");
    const std::uint32_t perFrame = s.voxelsPerFrame(budget, light.voxelRays);
    EXPECT_EQ(perFrame, 1000u) << "nothing recorded yet: no replay";
    EXPECT_EQ(s.bounceShare(perFrame), (VoxelRange{0, 1000}));
    EXPECT_FALSE(s.advanceBounce({0, 1000}));
    EXPECT_FLOAT_EQ(s.updateDone(), 1000.0f / 5000.0f);
    EXPECT_EQ(s.bounceShare(perFrame), (VoxelRange{1000, 1000}));
    EXPECT_FALSE(s.advanceBounce({1000, 1000}));
    EXPECT_EQ(s.bounceShare(perFrame), (VoxelRange{2000, 500}));
    EXPECT_TRUE(s.advanceBounce({2000, 500})) << "the last share ends the bounce";
    EXPECT_EQ(s.state().progress.bounce, 0) << "two bounces: the irradiance is next";
    EXPECT_EQ(s.updateStage(false), "irradiance");
    EXPECT_FLOAT_EQ(s.updateDone(), 0.5f);
    EXPECT_EQ(s.takeIrradiance(perFrame), (std::vector<VoxelRange>{{0, 1000}}));
    EXPECT_EQ(s.takeIrradiance(perFrame), (std::vector<VoxelRange>{{1000, 1000}}));
    EXPECT_EQ(s.takeIrradiance(perFrame), (std::vector<VoxelRange>{{2000, 500}}));
    EXPECT_EQ(s.state().progress.irradianceLeft, 0u);
    EXPECT_FLOAT_EQ(s.updateDone(), 1.0f);
    EXPECT_EQ(s.updateStage(false), "");
}

// The progress weighs each pass by what it costs: bounces after the second gather their change over
// one ray in four (GiSettings::laterBounceRayStride), about half a whole gather's cost in the spread
// frames (kChangeVoxelsPerFrameFactor); with every ray they weigh as much as the second.
TEST(GiScheduler, ProgressWeighsTheChangeBouncesByTheirCost) {
    for (const int stride : {4, 1}) {
        lit::RenderSettings settings;
        settings.gi.bounces = 4;
        settings.gi.laterBounceRayStride = stride;
        const GiLightKey light = GiLightKey::of(settings);
        GiScheduler s;
        const VoxelKey voxels{1, 1, nullptr};
        s.voxelized(voxels, 2000, true);
        s.startUpdate(s.changes(voxels, light, true, true, true), light, GiBudget{1000, 0});
        ASSERT_EQ(s.state().progress.bounce, 2);
        const double later = stride > 1 ? 1.0 / lit::kChangeVoxelsPerFrameFactor : 1.0;
        const double total = 1.0 + 2.0 * later + 1.0;  // bounce 2, bounces 3 and 4, the irradiance
        EXPECT_TRUE(s.advanceBounce({0, 2000}));
        EXPECT_FLOAT_EQ(s.updateDone(), static_cast<float>(1.0 / total)) << "stride " << stride;
        EXPECT_FALSE(s.advanceBounce({0, 1000}));
        EXPECT_FLOAT_EQ(s.updateDone(), static_cast<float>((1.0 + 0.5 * later) / total)) << "stride " << stride;
        EXPECT_TRUE(s.advanceBounce({1000, 1000}));
        EXPECT_TRUE(s.advanceBounce({0, 2000}));
        EXPECT_EQ(s.updateStage(false), "irradiance");
        EXPECT_FLOAT_EQ(s.updateDone(), static_cast<float>((1.0 + 2.0 * later) / total)) << "stride " << stride;
    }
}

// The first trace over the list records the rays' hits; the traces after a light edit replay them,
// kReplayVoxelsPerFrameFactor times the budget's voxels a frame; new voxels or another ray count
// record again.
TEST(GiScheduler, RayHitsAreRecordedThenReplayed) {
    GiScheduler s = injected(5000);
    EXPECT_EQ(s.rayHits(32, true, true), RayHits::Record);
    s.listTraced(RayHits::Record);
    EXPECT_EQ(s.rayHits(32, true, false), RayHits::Replay);
    EXPECT_EQ(s.voxelsPerFrame({1000, 0}, 32), 1000u * lit::kReplayVoxelsPerFrameFactor);
    EXPECT_EQ(s.rayHits(64, true, false), RayHits::Record) << "other rays";
    s.listTraced(RayHits::Record);
    EXPECT_EQ(s.rayHits(64, false, false), RayHits::Off) << "a cache that does not fit";
    EXPECT_EQ(s.rayHits(0, true, false), RayHits::Off) << "cones";
    s.listTraced(RayHits::Record);
    s.voxelized({2, 1, nullptr}, 5000, true);
    EXPECT_EQ(s.rayHits(64, true, false), RayHits::Record) << "new voxels, new hits";
}

// A light dragged while a spread update runs: the update runs on (the voxels not traced yet take
// the new light) and one more follows it, instead of starting again at every edit and never
// reaching the irradiance.
TEST(GiScheduler, ALightDragLetsTheRunningUpdateFinishAndOneMoreFollow) {
    GiScheduler s = settledWithRayHits(4000);
    const GiLightKey light = cachedTwoBounces();
    const GiBudget budget{500, 0};  // replayed: 2000 a frame, two frames a pass
    GiScheduler::Changes edit = s.changes(s.state().voxels, light, false, false, true);
    GiScheduler::UpdateStart start = s.startUpdate(edit, light, budget);
    EXPECT_FALSE(start.runOn) << "nothing was running";
    EXPECT_EQ(s.state().progress.bounce, 2);
    s.advanceBounce(s.bounceShare(s.voxelsPerFrame(budget, light.voxelRays)));
    edit = s.changes(s.state().voxels, light, false, false, true);
    start = s.startUpdate(edit, light, budget);
    EXPECT_TRUE(start.runOn);
    EXPECT_TRUE(s.state().progress.updateAgain);
    EXPECT_EQ(s.state().progress.bounceNext, 2000u) << "the bounce went on where it stood";
    s.advanceBounce(s.bounceShare(s.voxelsPerFrame(budget, light.voxelRays)));
    s.takeIrradiance(2000);
    s.takeIrradiance(2000);
    ASSERT_EQ(s.state().progress.irradianceLeft, 0u);
    EXPECT_TRUE(s.restartIfAsked()) << "the edit's own update follows";
    EXPECT_EQ(s.state().progress.bounce, 2);
    EXPECT_EQ(s.state().progress.irradianceLeft, 4000u);
    EXPECT_FALSE(s.state().progress.updateAgain);
}

// A node moved (or animated) while a spread update runs: with only changed boxes voxelized the
// update runs on as after a light drag, level 0 keeping its light and the ray hits their records;
// a voxelization of the whole volume starts the update again and forgets the hits.
TEST(GiScheduler, AMoveInChangedBoxesLetsTheRunningUpdateRunOn) {
    GiScheduler s = settledWithRayHits(4000);
    const GiLightKey light = cachedTwoBounces();
    const GiBudget budget{500, 0};
    GiScheduler::Changes edit = s.changes(s.state().voxels, light, false, false, true);
    s.startUpdate(edit, light, budget);
    s.advanceBounce(s.bounceShare(s.voxelsPerFrame(budget, light.voxelRays)));
    ASSERT_EQ(s.state().progress.bounceNext, 2000u);

    VoxelKey moved = s.state().voxels;
    ++moved.geometry;
    GiScheduler::Changes move = s.changes(moved, light, false, false, true);
    ASSERT_TRUE(move.voxelize);
    EXPECT_TRUE(move.onlyScene);
    move.changedBoxesOnly = true;
    s.voxelized(moved, 4100, true, true);
    EXPECT_TRUE(s.replaysRayHits(light.voxelRays)) << "the hits stay: the shaders test the changed boxes";
    GiScheduler::UpdateStart start = s.startUpdate(move, light, budget);
    EXPECT_TRUE(start.keepLastUpdate);
    EXPECT_TRUE(start.runOn);
    EXPECT_TRUE(s.state().progress.updateAgain);
    EXPECT_EQ(s.state().progress.bounceNext, 2000u) << "the bounce went on where it stood";
    EXPECT_EQ(s.bounceShare(s.voxelsPerFrame(budget, light.voxelRays)), (VoxelRange{2000, 2000}));
    EXPECT_EQ(s.bounceShare(100000), (VoxelRange{2000, 2100})) << "the appended entries are in the pass";

    ++moved.geometry;
    GiScheduler::Changes whole = s.changes(moved, light, false, false, true);
    s.voxelized(moved, 4000, true);
    EXPECT_FALSE(s.replaysRayHits(light.voxelRays));
    start = s.startUpdate(whole, light, budget);
    EXPECT_FALSE(start.keepLastUpdate);
    EXPECT_FALSE(start.runOn);
    EXPECT_EQ(s.state().progress.bounceNext, 0u) << "started again";
}

// The refinement: 15 rounds over the list with the set offsets 1..15, in the budget's shares; a
// budget of 0 waits; after the last round nothing is left.
TEST(GiScheduler, RefinementTracesTheOtherConeSetsRoundByRound) {
    GiScheduler s = injected(3000);
    const GiLightKey light = cachedTwoBounces();
    s.irradianceDone();
    ASSERT_TRUE(s.refinementLeft(light));
    int rounds = -1;
    EXPECT_TRUE(s.takeRefinement(0, rounds).empty());
    EXPECT_EQ(rounds, 0);
    const auto shares = s.takeRefinement(4000, rounds);
    ASSERT_EQ(shares.size(), 2u);
    EXPECT_EQ(shares[0].range, (VoxelRange{0, 3000}));
    EXPECT_EQ(shares[0].setOffset, 1);
    EXPECT_EQ(shares[1].range, (VoxelRange{0, 1000}));
    EXPECT_EQ(shares[1].setOffset, 2);
    EXPECT_EQ(rounds, 1);
    EXPECT_EQ(s.updateStage(true), "refining 2/15");
    std::uint32_t traced = 4000;
    for (const auto& share : s.takeRefinement(GiBudget::kAll, rounds)) traced += share.range.count;
    EXPECT_EQ(rounds, 14);
    EXPECT_EQ(traced, 15u * 3000u) << "every voxel once per round";
    EXPECT_FALSE(s.refinementLeft(light));
    GiLightKey accurate = light;
    accurate.voxelIrradiance = false;
    EXPECT_FALSE(injected(3000, accurate).refinementLeft(accurate)) << "only the cached mode refines";
}

// Every bounce (the default): the passes go on until a bounce's change, extrapolated over the
// bounces still to come, is below BounceConvergence::kExtrapolated with the rate steady (then that
// rest is added as the series' tail) or below kMissing; the progress counts the bounces the
// measured rate predicts.
TEST(GiScheduler, EveryBounceStopsWhenTheLightConverges) {
    const GiLightKey every = GiLightKey::of(lit::RenderSettings{});
    EXPECT_TRUE(every.untilConverged);
    EXPECT_EQ(every.bounces, lit::kMaxConvergingBounces);
    EXPECT_TRUE(every.retraces(cachedTwoBounces()));
    GiScheduler s;
    const VoxelKey voxels{1, 1, nullptr};
    const GiScheduler::Changes changes = s.changes(voxels, every, true, true, true);
    s.voxelized(voxels, 1000, true);
    const GiBudget budget{500, 0};  // spread: each bounce a pass over frames
    s.startUpdate(changes, every, budget);
    ASSERT_EQ(s.state().progress.bounce, 2);
    EXPECT_EQ(s.state().progress.bounceEstimate, GiScheduler::kFirstBounceEstimate);
    // Each bounce changes the light by half the last one's change.
    lit::BounceConvergence convergence;
    double change = 0.4;
    int bounce = 2;
    for (; bounce < 40; ++bounce) {
        const bool converged = convergence.add(change);
        EXPECT_EQ(s.state().progress.bounce, bounce);
        EXPECT_TRUE(s.advanceBounce({0, 1000}, converged));
        if (converged) break;
        change *= 0.5;
    }
    // After bounce k the light still missing is change_k · r / (1 − r) = change_k; the rate is steady
    // from bounce 4 (two ratios measured), so it stops at 0.4 · 2^(2−k) < 0.05, and the tail adds
    // r / (1 − r) = 1 × the last change.
    EXPECT_EQ(bounce, 6);
    EXPECT_EQ(s.state().progress.bounce, 0) << "the irradiance is next";
    EXPECT_EQ(convergence.expectedBounces(), 6);
    EXPECT_DOUBLE_EQ(convergence.tail(), 1.0);
    // A scene without light converges at once; a light that keeps changing stops at the cap.
    EXPECT_TRUE(lit::BounceConvergence{}.add(0.0));
    lit::BounceConvergence slow;
    EXPECT_FALSE(slow.add(0.5));
    EXPECT_FALSE(slow.add(0.49));
    EXPECT_GT(slow.expectedBounces(), 100);
    // A dim room's light, measured against its bounced light: the rate settles near 0.72 (it nears 1
    // only as the changes reach the radiance volume's rounding, 0.07 % a bounce): at bounce 10 the
    // 4 % still missing is added as the tail, where kMissing alone took 18 bounces.
    lit::BounceConvergence dim;
    int dimBounces = 1;
    for (double c : {1.0, 0.29, 0.156, 0.098, 0.066, 0.045, 0.031, 0.022, 0.0158, 0.0114, 0.0082, 0.0061,
                     0.0045, 0.0035, 0.0027, 0.0022, 0.00175, 0.00144, 0.0007, 0.0007}) {
        ++dimBounces;
        if (dim.add(c)) break;
    }
    EXPECT_EQ(dimBounces, 10);
    const double dimRatio = 0.0158 / 0.022;
    EXPECT_DOUBLE_EQ(dim.tail(), dimRatio / (1.0 - dimRatio));
    // A change below kStill is the volume's rounding: settled whatever the rate says, and no tail.
    lit::BounceConvergence settled;
    EXPECT_FALSE(settled.add(0.01));
    EXPECT_FALSE(settled.add(0.0099));
    EXPECT_TRUE(settled.add(0.0019));
    EXPECT_EQ(settled.tail(), 0.0);
}

}  // namespace
