#pragma once
// What the voxel GI does in a frame, decided on the CPU (no GL here, so it is tested without a
// context): whether the volume is voxelized again, whether the light is injected again, and how
// much of the update after an edit (bounces 2..N, then the voxel irradiance, then its refinement)
// this frame's GiBudget lets run. VoxelGi carries the decisions out. docs/GI.md, "The update and
// its budget".
//
// All that the scheduler knows is one struct, GiState, compared with == (a frame that changes
// nothing leaves it equal).

#include <shared.h>

#include <cstdint>
#include <string>
#include <vector>

#include "RenderSettings.h"
#include "gi/GiBudget.h"
#include "gi/RayHitCache.h"
#include "gi/VoxelDispatch.h"

namespace lit {

struct Scene;

// What the voxel material volumes depend on; re-voxelized only when it changes.
struct VoxelKey {
    std::uint64_t geometry = ~0ull, materials = ~0ull;
    const Scene* scene = nullptr;
    bool operator==(const VoxelKey&) const = default;
};

// What the voxels' light depends on besides the scene's lights and shadow maps.
struct GiLightKey {
    // 1..kMaxBounces, or kMaxConvergingBounces with untilConverged; 0 before the first injection.
    int bounces = 0;
    bool untilConverged = false;   // every bounce: the passes stop once the light stops changing
    bool voxelIrradiance = false;  // the cached mode's irradiance is traced after the bounces
    bool anisotropic = false;      // the directional chains are built
    int voxelRays = 0;
    int laterBounceRayStride = 1;
    float footprint = 0.0f, aperture = 0.0f, stepScale = 0.0f, traceDistance = 0.0f, intensity = 0.0f;
    float radianceRange = 0.0f;

    static GiLightKey of(const RenderSettings& settings);
    // Whether the bounces after an update's first gather the change of the one before over a subset
    // of the rays (changeSubsetFor).
    bool gathersChanges() const { return changeSubsetFor(3, voxelRays, laterBounceRayStride) >= 0; }
    // Whether going from `last` to this needs the bounces or the voxel irradiance traced again:
    // their count or the mode changed, or (when anything traces) a setting they trace with.
    bool retraces(const GiLightKey& last) const;
    bool operator==(const GiLightKey&) const = default;
};

// The update under way after the last light or geometry edit, over the occupied-voxel list.
struct GiProgress {
    int bounce = 0;                    // the bounce spread over frames (2..N); 0: none
    int bounceEstimate = 0;            // every bounce: the bounces the update is expected to take
    std::uint32_t bounceNext = 0;      // its next list entry
    std::uint32_t irradianceNext = 0;  // the irradiance's next list entry (round robin over the list)
    std::uint32_t irradianceLeft = 0;  // entries still to trace since the last edit (0: all hold its light)
    int refineRound = 0;               // the refinement round under way (1..kConeSets − 1; kConeSets: done)
    std::uint32_t refineNext = 0;      // its next list entry
    bool updateAgain = false;          // an edit came while a spread update ran: one more follows it
    // Every bounce: the bounces the last update that converged took (0 before one). An update that
    // runs on through edits stops there: the light it bounces changes under it (a light dragged, a
    // node animated), so its bounces never look converged, and the next update follows anyway.
    int settledBounces = 0;
    bool operator==(const GiProgress&) const = default;
};

struct GiState {
    bool voxelsValid = false;
    VoxelKey voxels;             // what the material volumes were voxelized from
    GiLightKey light;            // what the light in the voxels was injected and traced with
    std::uint32_t occupied = 0;  // voxels the last voxelization occupied
    bool listComplete = false;   // the occupied-voxel list holds all of them (else passes run over N³)
    bool rayHitsValid = false;   // the ray-hit cache holds every listed voxel's hits for rayHitsRays rays
    int rayHitsRays = 0;
    GiProgress progress;
    bool operator==(const GiState&) const = default;
};

// Every bounce (GiSettings::bounces kAllBounces): when to stop. From one bounce to the next the
// voxels' light changes by a share that falls about geometrically (by the scene's mean albedo
// times how much of a voxel's hemisphere sees other voxels), so after a bounce whose relative
// change is c, with ratio r to the bounce before, about c · r / (1 − r) of the light is still
// missing. Once the ratio holds steady the change keeps its shape from bounce to bounce, and the
// missing light is added as r / (1 − r) × the last change (tail(), bounce_copy.comp.glsl): the
// update stops once the missing share is below kExtrapolated with the ratio steady, or below
// kMissing. docs/GI.md, "Bounces".
class BounceConvergence {
public:
    static constexpr double kMissing = 0.005;  // share of the light still missing when it stops
    // ... or this share, added as the series' tail, when the ratio changed by at most kSteadyRatio
    // from the bounce before.
    static constexpr double kExtrapolated = 0.05;
    static constexpr double kSteadyRatio = 0.02;
    // A relative change this small is the radiance volume's own rounding (RGBA16F holds 11
    // significant bits, 0.05 %: once the light has settled, the bounces keep changing it by
    // 0.07 % in a dim room, a limit cycle), so the light has settled whatever the rate says.
    static constexpr double kStill = 0.002;
    // Adds bounce k's relative change (BounceChange::relative); true when the light has converged.
    bool add(double relativeChange);
    // Once add() said converged: the bounces still missing as a multiple of the last bounce's
    // change, r / (1 − r) (0 when the light had stopped changing).
    double tail() const { return tail_; }
    // The bounces the light is expected to need in all, from the ratio measured so far (0 before
    // two bounces were measured).
    int expectedBounces() const { return expected_; }

private:
    double last_ = -1.0;
    double lastRatio_ = -1.0;
    double tail_ = 0.0;
    int bounces_ = 1;  // bounce 1 is the direct light; the first measured is bounce 2
    int expected_ = 0;
};

class GiScheduler {
public:
    // Cone sets of the stratified pattern: the refinement traces every voxel with the other
    // kConeSets − 1 after the update's one.
    static constexpr int kConeSets = LIT_CONE_STRATA * LIT_CONE_STRATA;
    // Every bounce: the bounces an update is expected to take before the first is measured.
    static constexpr int kFirstBounceEstimate = 8;

    const GiState& state() const { return state_; }

    // What changed since the last update, and why (for the log).
    struct Changes {
        bool voxelize = false;  // the material volumes must be voxelized again
        bool inject = false;    // the light must be injected again (and what follows it)
        bool retrace = false;   // bounces / voxel irradiance settings changed
        // Only the scene's lights changed: with voxel rays, level 0 can keep the last update's
        // light while the bounces run (VoxelGi, keepLastUpdate).
        bool onlyLight = false;
        // Only the lights and the geometry changed, no setting the voxels' light depends on.
        bool onlyScene = false;
        // Set by VoxelGi once it knows: the geometry edit voxelized only changed boxes
        // (VoxelChangeTracker). With onlyScene, level 0 keeps the last update's light outside them
        // as after a light edit, and a running update runs on.
        bool changedBoxesOnly = false;
        std::string reason;
    };
    // `volumeReallocated` / `volumeMoved`: VoxelVolume::ensure / fitTo said so this frame.
    Changes changes(const VoxelKey& voxels, const GiLightKey& light, bool volumeReallocated, bool volumeMoved,
                    bool shadowsDirty) const;

    // The volume was voxelized from `voxels`: `occupied` list entries, all in the list or not.
    // `keptRayHits`: only changed boxes were voxelized and the ray-hit cache stays valid (its
    // entries check the boxes themselves, RayHitCache::markChanged).
    void voxelized(const VoxelKey& voxels, std::uint32_t occupied, bool listComplete, bool keptRayHits = false);
    // A new scene: the next update voxelizes again.
    void invalidate() { state_.voxelsValid = false; }
    // The directional chains were freed (anisotropic voxels off): switching them on re-injects.
    void directionalReleased() { state_.light.anisotropic = false; }

    // A new update after `changes` (inject set), with `light` and `budget`: what the injection
    // frame does. The state records `light` as what the voxels hold.
    struct UpdateStart {
        // Level 0 keeps the last update's light until the last bounce replaces it (only the light
        // changed, or the geometry in changed boxes, whose voxels get their direct light; the
        // bounces gather with voxel rays, which read the direct volume's light where they end and
        // only the mips' occupancy while they march).
        bool keepLastUpdate = false;
        // A spread update is running and only the light changed or nodes moved: it runs on, the
        // voxels not traced yet taking the new light, and one more update follows it (updateAgain).
        bool runOn = false;
        int bouncesNow = 0;              // bounces 2..N traced whole in this frame (0: none or spread)
        bool prepareIrradiance = false;  // the irradiance starts again over the whole list
        bool clearIrradiance = false;    // ... and forgets the old values (after a voxelization)
    };
    UpdateStart startUpdate(const Changes& changes, const GiLightKey& light, const GiBudget& budget);
    // UpdateStart::keepLastUpdate for `changes` and `light` (known before the update starts).
    static bool keepsLastUpdate(const Changes& changes, const GiLightKey& light);

    // Voxels a frame of the update may trace with `budget` (0: all at once); voxels that replay
    // recorded ray hits take kReplayVoxelsPerFrameFactor times as many.
    std::uint32_t voxelsPerFrame(const GiBudget& budget, int rays) const;
    // Whether the cached mode's update runs over several frames with `budget`: only over a complete
    // list, and with a time budget or a list longer than a frame's share.
    bool spreadsOverFrames(const GiLightKey& light, const GiBudget& budget) const;
    // Whether a trace with `rays` rays would replay the recorded hits.
    bool replaysRayHits(int rays) const;

    // The ray-hit cache after RayHitCache::ensure for the list: what a trace over the list does
    // with it (Off when it does not fit or there are no rays or no complete list).
    RayHits rayHits(int rays, bool cacheFits, bool cacheReallocated);
    // A trace over the whole list ended with `hits`: what it recorded is the cache now.
    void listTraced(RayHits hits) {
        if (hits == RayHits::Record) state_.rayHitsValid = true;
    }

    // This frame's share of the spread bounce under way (progress.bounce > 0): the list range to
    // trace. finishBounce() after tracing it when the range reached the list's end.
    VoxelRange bounceShare(std::uint32_t perFrame) const;
    // Advances past `range`; returns true when the bounce is complete (the caller copies it into
    // level 0). `converged`: with every bounce, the light stopped changing with this one, which
    // is then the last. The last bounce lets the irradiance start next frame.
    bool advanceBounce(VoxelRange range, bool converged = false);
    // Every bounce: how many bounces the update is now expected to take (for the progress figure).
    void estimateBounces(int bounces) { state_.progress.bounceEstimate = bounces; }

    // This frame's share of the irradiance update (irradianceLeft > 0, spread): at most two ranges
    // (up to the list's end, then from its start). The state advances past them.
    std::vector<VoxelRange> takeIrradiance(std::uint32_t perFrame);
    // The irradiance traced whole (not spread, or the list overflowed): nothing left.
    void irradianceDone() { state_.progress.irradianceLeft = 0; }
    // After the irradiance's last share: a light edit that came meanwhile starts one more update.
    // Returns whether it did.
    bool restartIfAsked();

    // Refinement rounds are left: the cached mode, the update done, a complete list.
    bool refinementLeft(const GiLightKey& light) const;
    // This frame's refinement with `budget` voxels: ranges with the set offset each traces; the
    // state advances. `roundsCompleted` counts rounds finished this frame.
    struct RefineShare {
        VoxelRange range;
        int setOffset = 0;
    };
    std::vector<RefineShare> takeRefinement(std::uint32_t budget, int& roundsCompleted);

    // The update's progress for the editor's overlay: the share done (1: every voxel holds the
    // current light) and the stage ("bounce 2".."bounce N", "irradiance", "refining k/15", "").
    float updateDone() const;
    std::string updateStage(bool refinedThisFrame) const;

private:
    void restartIrradiance();
    GiState state_;
};

}  // namespace lit
