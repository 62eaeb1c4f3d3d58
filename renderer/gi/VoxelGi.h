#pragma once
// The voxel GI subsystem: one owner for the voxel volume and everything that fills it —
// voxelize → inject → mips → bounces → voxel irradiance (traced, filtered, refined) — and for the
// scheduler that decides what of it a frame does under its GiBudget (GiScheduler). The frame asks
// update() once and then reads the volumes through volume() and bindGather(); nothing else writes
// them. docs/GI.md, "Pipeline".

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "Log.h"
#include "Profiler.h"
#include "RenderSettings.h"
#include "gi/BouncePass.h"
#include "gi/GiBudget.h"
#include "gi/GiPacer.h"
#include "gi/GiScheduler.h"
#include "gi/InjectPass.h"
#include "gi/IrradianceFilterPass.h"
#include "gi/MipmapBenchmark.h"
#include "gi/MipmapPass.h"
#include "gi/RayHitCache.h"
#include "gi/SolidVoxelsPass.h"
#include "gi/VoxelIrradianceCache.h"
#include "gi/VoxelIrradiancePass.h"
#include "gi/VoxelRegions.h"
#include "gi/VoxelScrollPass.h"
#include "gi/VoxelVolume.h"
#include "gi/VoxelizePass.h"
#include "scene/Aabb.h"

namespace lit {

class GpuScene;
struct DrawCounters;
struct MipmapTimings;
struct Scene;

// What a GI frame did, for FrameStats and the editor's overlay.
struct GiFrameReport {
    bool voxelized = false;            // the volume was voxelized again
    bool scrolled = false;             // a near level scrolled: only the slabs it uncovered were voxelized
    int voxelizedBoxes = 0;            // ... in this many changed boxes only (0: the whole volume)
    std::int64_t voxelizedVoxels = 0;  // voxels those boxes hold (the whole volume's N³ otherwise)
    bool injected = false;             // the light was injected again
    bool lightChanged = false;         // the voxels' light changed: accumulated indirect light is stale
    std::uint32_t occupiedVoxels = 0;  // voxels the last voxelization occupied
    float updateDone = 1.0f;           // share of the update after the last edit done (1: all)
    std::string updateStage;           // "bounce 2".."bounce N", "irradiance", "refining k/15", ""
    std::uint32_t refinedVoxels = 0;   // voxels the refinement traced this frame
    bool refining = false;             // refinement rounds (or a near level's uncovered slabs' update) are still to run
    // An update's last voxel was traced this frame: the pixels gather its light from now on (also
    // when another update follows at once: GiScheduler::restartIfAsked).
    bool updateCompleted = false;
    // The bounces the voxels' light holds (with every bounce: those it took to converge, or the
    // count expected while the update runs).
    int bounces = 0;
    bool everyBounce = false;  // GiSettings::bounces is every bounce
    // The pixels gather the last complete update's irradiance while the one after a geometry edit
    // is traced (VoxelIrradianceCache::showingPrevious).
    bool showingPrevious = false;
};

// Which volume a VoxelGi fills: the one around the whole scene, or one of the cached mode's near
// levels around the camera, whose voxel rays continue in the volumes outside it (docs/GI.md,
// "Near levels").
enum class VoxelGiLevel { Scene, Near };

class VoxelGi {
public:
    // Builds the passes' first programs (throws gl::GlError when a shader does not build).
    VoxelGi(const std::filesystem::path& shaderRoot, Profiler& profiler, Log& log,
            VoxelGiLevel level = VoxelGiLevel::Scene);

    struct Frame {
        const Scene& scene;
        const GpuScene& gpuScene;
        Aabb bounds;                // the scene's world bounds: the volume is fitted around them
        ShadowKinds shadows;        // the kinds of shadow map the light table uses
        bool shadowsDirty = false;  // the lights or their shadow maps changed this frame
        int frameIndex = 0;         // sample pattern index (turns with temporal accumulation)
        // A near level: the next volume out and the scene's volume, both updated this frame before
        // it, where its rays continue (outer may be far).
        const VoxelGi* outer = nullptr;
        const VoxelGi* far = nullptr;
    };
    // Brings the volumes up to date with `settings` as far as `budget` allows this frame (a time
    // budget is turned into voxel counts by what the spread work cost in earlier frames). The
    // caller has bound the frame UBO (LIT_UBO_FRAME), the light table (LIT_SSBO_LIGHTS) and the
    // shadow maps (ShadowPass::bindMaps), which the injection reads. Leaves the voxel UBO bound.
    GiFrameReport update(const Frame& frame, const RenderSettings& settings, const GiBudget& budget,
                         DrawCounters& counters);
    // A new scene: everything is voxelized again on the next update.
    void invalidate() { scheduler_.invalidate(); }

    // The volume of the last update; valid() is false before the first one (or after invalidate).
    bool valid() const { return scheduler_.state().voxelsValid; }
    const VoxelVolume& volume() const { return volume_; }
    // Counts voxelizations (the voxel debug views cache by it).
    std::uint64_t generation() const { return generation_; }
    // Binds what the per-pixel gather reads in the cached mode (the irradiance gather texels).
    void bindGather(const RenderSettings& settings) const;
    // Near level `index` (0 the finest): binds what the pixels gather from it (LIT_NEAR_GATHER: its
    // gather texels and their placement, LIT_TEX_NEAR_IRRADIANCE_FIRST and LIT_UBO_NEAR_VOXEL_FIRST + index).
    void bindAsNearLevel(int index) const;
    // GPU memory of the volumes and caches, bytes.
    std::size_t bytes() const;

    // Logs what the last update did and what it cost, once its GPU timings are in (call once a
    // frame, before the frame's own passes).
    void reportUpdate();
    // MipmapTimings of the current volume (after a GI frame; zeros before one).
    MipmapTimings benchmarkMipmaps(int repetitions);
    // The passes' programs, for hot reload.
    std::vector<Pass*> passes();

private:
    // The cone features of this volume's own voxel passes.
    ConeFeatures featuresFor(const RenderSettings& settings) const;
    // The profiler's name of the step `name` ("voxelize", "bounces", ...) for this volume: a near
    // level's are "near voxelize", ... (a string that lives as long as the program).
    const char* step(const char* name) const;
    // A trace over the occupied-voxel list with `rays` rays: what it does with the ray-hit cache.
    RayHits rayHitsFor(int rays);
    // The changed boxes to voxelize instead of the whole volume, if a voxelization of them is
    // possible and asked for (RenderSettings: voxelizeChangesOnly).
    std::optional<std::vector<VoxelBox>> changedBoxes(const std::vector<ItemPose>& items, const VoxelKey& voxels,
                                                      const RenderSettings& settings, bool reallocated, bool moved);
    // A near level scrolled by `shift` with its light converged: the voxels of the uncovered slabs
    // and of a margin behind them (and of an earlier scroll's slabs not lit yet, moved with it) get
    // their light by an update over them alone, run by continueSlabUpdate under the frame budget.
    void startSlabUpdate(glm::ivec3 shift);
    void continueSlabUpdate(const RenderSettings& settings, const GiLightKey& light, const GiBudget& budget);
    // A near level that moved from `before`: the shift to scroll it by (VoxelScrollPass), or
    // nullopt when it must be voxelized whole.
    std::optional<glm::ivec3> scrollFor(const VoxelPlacement& before, const VoxelKey& voxels,
                                        const RenderSettings& settings, bool reallocated, bool moved) const;
    // Gives the pacer the GPU time of the spread passes of each frame whose timings came in since
    // the last call.
    void measureSpreadWork();
    // A pass over the whole list ended: the scheduler and the ray-hit cache say so.
    void listTraced(RayHits hits);
    // The work of the update after the injection frame: this frame's share of a spread bounce, of
    // the irradiance and of the refinement, and the filter after them.
    // Records the voxels it traced with the pacer unless `unmeasured` (the frame's "bounces" time
    // also holds a warm start's copies: no measure of the share).
    // `pace`: the budget asked and the edit's work this frame, which under a time budget give each
    // pass's share by its own cost (GiPacer::Work).
    struct Pace {
        GiBudget asked;
        GiPacer::Edit edit = GiPacer::Edit::None;
    };
    void continueUpdate(const RenderSettings& settings, const GiLightKey& light, const GiBudget& budget,
                        const Pace& pace, bool unmeasured, GiFrameReport& report);

    VoxelGiLevel level_;
    Profiler& profiler_;
    Log& log_;
    VoxelVolume volume_;
    VoxelizePass voxelize_;
    SolidVoxelsPass solid_;
    InjectPass inject_;
    MipmapPass mipmap_;
    BouncePass bounce_;
    VoxelIrradiancePass irradiance_;
    IrradianceFilterPass filter_;
    VoxelScrollPass scroll_;
    VoxelIrradianceCache irradianceCache_;
    RayHitCache rayHitCache_;
    GiScheduler scheduler_;
    GiPacer pacer_;
    std::uint64_t lastMeasuredFrame_ = 0;  // the profiler frame the pacer last heard of
    VoxelChangeTracker changes_;
    // List entries after the last voxelization of the whole volume: a list that grew to twice that
    // by voxelizations of changed boxes (entries of voxels that became empty stay) is rebuilt.
    std::uint32_t wholeVolumeEntries_ = 0;
    BounceConvergence convergence_;  // every bounce: the update's bounces so far
    // The update's bounces started from the last update's light (level 0 holds it): its second
    // bounce reads level 0, not the direct volume.
    bool warmStart_ = false;
    // The change volume holds the last bounce's change, no injection came since, and that change is
    // smooth (no step of the direct light in it: the bounce read light with the same direct light):
    // the next bounce may gather it over a subset of the rays (BounceTrace::changeSubset). A change
    // holding the direct light's step after a light edit, gathered over a subset, read 20 % more
    // change in the Cornell box's next bounce and stopped the update two bounces early.
    bool changeReady_ = false;
    float shownDone_ = 0.0f;  // GiFrameReport::updateDone as shown: the most the update under way reported
    // Level 0, where later bounces' rays take their light, was written by a bounce run wholly with the
    // direct light injected last.
    bool sourceHoldsDirect_ = false;
    bool bounceGathersChange_ = false;      // changeReady_ when the spread bounce under way started
    bool bounceSourceHoldsDirect_ = false;  // sourceHoldsDirect_ then
    std::uint64_t injections_ = 0;            // injections so far
    std::uint64_t bounceStartInjections_ = 0;  // injections_ when the spread bounce under way started
    std::uint64_t generation_ = 0;
    // A near level: the placement (VoxelUniforms) of the texels the pixels gather, which after a
    // move is the old one until the moved level's update completes.
    gl::Buffer shownUniforms_;
    VoxelPlacement shownPlacement_;  // ... as a placement
    // The update of a scroll's uncovered slabs under way (empty boxes: none): every bounce until the
    // slabs' light converges, then their irradiance and its refinement rounds; the list passes skip
    // the voxels outside them.
    struct SlabUpdate {
        std::vector<VoxelBox> boxes;
        int bounce = 2;          // the bounce under way (2, 3, ...); 0: the irradiance
        int round = 0;           // the irradiance's round: 0 each voxel's own cone set, 1.. the refinement's
        std::uint32_t next = 0;  // the pass's next list entry
        BounceConvergence convergence;
        bool mipmapPending = false;  // the bounces ended; under a time budget their mips get a frame of their own
        ListBoxShares shares;        // where the boxes' voxels lie along the list: the ranges' sizes
    };
    SlabUpdate slabs_;
    // The update waiting for its GPU timings to be logged: why it ran, in which frame.
    std::string pendingReason_;
    std::uint64_t pendingFrame_ = 0;
    bool pendingVoxelize_ = false;
    int pendingBoxes_ = 0;  // the voxelization's changed boxes (0: the whole volume)
    std::int64_t pendingBoxVoxels_ = 0;
    int pendingBounces_ = 1;
};

}  // namespace lit
