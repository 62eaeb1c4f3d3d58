#include "gi/VoxelGi.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <utility>

#include "scene/Scene.h"

namespace lit {

namespace {
std::string formatMs(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f ms", ms);
    return text;
}
}  // namespace

VoxelGi::VoxelGi(const std::filesystem::path& shaderRoot, Profiler& profiler, Log& log, VoxelGiLevel level)
    : level_(level),
      profiler_(profiler),
      log_(log),
      voxelize_(shaderRoot),
      solid_(shaderRoot),
      inject_(shaderRoot),
      mipmap_(shaderRoot),
      bounce_(shaderRoot),
      irradiance_(shaderRoot),
      filter_(shaderRoot),
      scroll_(shaderRoot),
      shownUniforms_("near level shown placement", sizeof(gpu::VoxelUniforms), nullptr, 0) {}

const char* VoxelGi::step(const char* name) const {
    // The profiler's names of a near level's steps: the overlay, the logs and the pacers tell them apart.
    static constexpr std::pair<const char*, const char*> kNearNames[] = {
        {"voxelize", "near voxelize"},
        {"solid voxels", "near solid voxels"},
        {"mip lists", "near mip lists"},
        {"inject", "near inject"},
        {"mipmap", "near mipmap"},
        {"bounces", "near bounces"},
        {"voxel irradiance", "near voxel irradiance"},
        {"voxel irradiance filter", "near voxel irradiance filter"},
        {"scroll", "near scroll"}};
    if (level_ == VoxelGiLevel::Scene) return name;
    for (const auto& [scene, near] : kNearNames)
        if (std::strcmp(scene, name) == 0) return near;
    return name;
}

ConeFeatures VoxelGi::featuresFor(const RenderSettings& settings) const {
    ConeFeatures features = ConeFeatures::of(settings);
    features.nearGatherLevels = 0;  // the pixels' gather; the voxel passes trace their own
    features.nearLevel = level_ == VoxelGiLevel::Near;
    return features;
}

void VoxelGi::bindAsNearLevel(int index) const {
    irradianceCache_.shownTexels().bind(static_cast<GLuint>(LIT_TEX_NEAR_IRRADIANCE_FIRST + index));
    shownUniforms_.bindBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(LIT_UBO_NEAR_VOXEL_FIRST + index));
}

std::vector<Pass*> VoxelGi::passes() {
    return {&voxelize_, &solid_, &inject_, &mipmap_, &bounce_, &irradiance_, &filter_, &scroll_};
}

RayHits VoxelGi::rayHitsFor(int rays) {
    const GiState& state = scheduler_.state();
    if (rays <= 0 || !state.listComplete) return RayHits::Off;
    const bool fits = rayHitCache_.ensure(rays, state.occupied);
    if (fits && rayHitCache_.reallocated()) {
        char text[160];
        std::snprintf(text, sizeof text, "voxel ray hits: %.1f MiB (%u occupied voxels × 2 sides × %d rays)",
                      static_cast<double>(rayHitCache_.bytes()) / (1024.0 * 1024.0), state.occupied, rays);
        log_.info(text);
    }
    return scheduler_.rayHits(rays, fits, rayHitCache_.reallocated());
}

std::optional<std::vector<VoxelBox>> VoxelGi::changedBoxes(const std::vector<ItemPose>& items, const VoxelKey& voxels,
                                                           const RenderSettings& settings, bool reallocated,
                                                           bool moved) {
    const GiState& state = scheduler_.state();
    if (!settings.gi.voxelizeChangesOnly || reallocated || moved || !state.voxelsValid || !state.listComplete ||
        voxels.scene != state.voxels.scene || voxels.materials != state.voxels.materials ||
        state.occupied > 2 * std::max(wholeVolumeEntries_, 1u))
        return std::nullopt;
    return changes_.voxelizeChanged(items, volume_.placement());
}

std::optional<glm::ivec3> VoxelGi::scrollFor(const VoxelPlacement& before, const VoxelKey& voxels,
                                             const RenderSettings& settings, bool reallocated, bool moved) const {
    const GiState& state = scheduler_.state();
    // The shown texels must be those of the placement it scrolls from (not an older one, still
    // shown after a move that could not scroll), and the list may not have outgrown its rebuild.
    if (level_ != VoxelGiLevel::Near || !moved || reallocated || !settings.gi.voxelizeChangesOnly ||
        !state.voxelsValid || !state.listComplete || !(voxels == state.voxels) || shownPlacement_ != before ||
        !irradianceCache_.matches(volume_) || state.occupied > 2 * std::max(wholeVolumeEntries_, 1u))
        return std::nullopt;
    return scrollShift(before, volume_.placement());
}

void VoxelGi::listTraced(RayHits hits) {
    scheduler_.listTraced(hits);
    if (hits != RayHits::Off) rayHitCache_.endPass();
}

void VoxelGi::measureSpreadWork() {
    for (const std::vector<PassTiming>& timings : profiler_.recentFrames()) {
        if (timings.empty() || timings.front().frame <= lastMeasuredFrame_) continue;
        lastMeasuredFrame_ = timings.front().frame;
        const SpreadWork which = level_ == VoxelGiLevel::Near ? SpreadWork::NearLevels : SpreadWork::SceneVolume;
        pacer_.measured(lastMeasuredFrame_, spreadGiMs(timings, which));
        const EditGiTime edit = editGiMs(timings, which);
        pacer_.editMeasured(edit.voxelized ? GiPacer::Edit::Voxelize : GiPacer::Edit::Inject, edit.ms);
    }
}

GiFrameReport VoxelGi::update(const Frame& frame, const RenderSettings& settings, const GiBudget& asked,
                              DrawCounters& counters) {
    GiFrameReport report;
    if (asked.milliseconds > 0.0) measureSpreadWork();
    const bool reallocated = volume_.ensure(settings.gi.voxelResolution, settings.gi.radianceRgba8, log_);
    const VoxelPlacement placedBefore = volume_.placement();
    const bool moved = level_ == VoxelGiLevel::Near ? volume_.placeAt(frame.bounds) : volume_.fitTo(frame.bounds);
    volume_.updateUniforms(settings, frame.frameIndex);
    if (frame.outer && frame.far) {
        // A near level's rays continue in the next volume out, then in the scene's, where they
        // leave this one.
        const VoxelVolume& outer = frame.outer->volume();
        outer.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_OUTER_VOXEL);
        outer.radiance().bind(LIT_TEX_OUTER_RADIANCE);
        outer.normal().bind(LIT_TEX_OUTER_NORMAL);
        outer.surface().bind(LIT_TEX_OUTER_SURFACE);
        const VoxelVolume& far = frame.far->volume();
        far.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FAR_VOXEL);
        far.radiance().bind(LIT_TEX_FAR_RADIANCE);
        far.normal().bind(LIT_TEX_FAR_NORMAL);
        far.surface().bind(LIT_TEX_FAR_SURFACE);
    }
    const VoxelKey voxels{frame.scene.geometryRevision, frame.scene.materialRevision, &frame.scene};
    const GiLightKey light = GiLightKey::of(settings);
    const ConeFeatures features = featuresFor(settings);
    // A near level the camera moved by whole voxels scrolls: what it holds moves with the world and
    // only the uncovered slabs are voxelized, as changed boxes (their light made as after an edit
    // of the geometry in them).
    const std::optional<glm::ivec3> scroll = scrollFor(placedBefore, voxels, settings, reallocated, moved);
    GiScheduler::Changes changes = scheduler_.changes(voxels, light, reallocated, moved && !scroll, frame.shadowsDirty);
    // With the level's light converged and nothing else changed, only the voxels of the uncovered
    // slabs are lit (continueSlabUpdate): the others keep their light, which a full update would
    // only trace again. Else the scroll's update is a geometry edit's, over every voxel. (With a
    // scroll, `changes` was asked without the move: it holds what else changed.)
    const GiProgress& progressBefore = scheduler_.state().progress;
    const bool slabUpdate = scroll && light.untilConverged && light.voxelIrradiance && light.voxelRays > 0 &&
                            progressBefore.bounce == 0 && progressBefore.irradianceLeft == 0 && !changes.inject;
    if (scroll) {
        changes.voxelize = changes.inject = true;
        changes.reason = slabUpdate ? "near level scrolled, lighting the uncovered slabs" : "near level scrolled";
    }
    // Switched off: the directional volumes' memory goes back (0.6-1.3 GiB at 512³).
    if (!light.anisotropic && volume_.directional(0)) {
        volume_.releaseDirectionalVolumes();
        scheduler_.directionalReleased();
    }

    // After a geometry edit the pixels keep gathering the last complete update's irradiance until
    // the new one is complete, unless its texels no longer line up with the voxels (the volume moved
    // or was made again) or belong to another scene.
    const bool keepShownLight = !reallocated && (!moved || scroll) && scheduler_.state().voxelsValid &&
                                scheduler_.state().voxels.scene == &frame.scene;
    // The near level that moved: its pixels keep gathering the last complete update's texels where
    // they were traced (shownUniforms_) until the moved level's update completes.
    const bool keepShownOverMove = level_ == VoxelGiLevel::Near && moved && !scroll && !reallocated &&
                                   scheduler_.state().voxelsValid && scheduler_.state().voxels.scene == &frame.scene;
    std::vector<ItemPose> items;
    std::optional<std::vector<VoxelBox>> boxes;
    if (changes.voxelize) {
        items = itemPoses(frame.scene, frame.gpuScene);
        boxes = scroll ? uncoveredSlabs(*scroll, volume_.resolution())
                       : changedBoxes(items, voxels, settings, reallocated, moved);
        changes.changedBoxesOnly = boxes.has_value();
    }
    // A time budget's share: what the edit's whole work leaves of it. This budget paces the near
    // level's slab update, whose voxels march their rays, and the refinement; continueUpdate paces
    // each share of the update by its own kind of work.
    const GiPacer::Edit edit = changes.voxelize ? GiPacer::Edit::Voxelize
                               : changes.inject ? GiPacer::Edit::Inject
                                                : GiPacer::Edit::None;
    const GiBudget budget = pacer_.paced(asked, GiPacer::Work::Update, edit);
    // Every bounce after a geometry edit, spread over frames: the bounces start from the last
    // update's light (BouncePass::keepIndirect; the old list is read before the voxelization
    // replaces it), unless level 0 keeps that light (changed boxes only: keepLastUpdate).
    const GiState& before = scheduler_.state();
    bool warmStart = changes.voxelize && !GiScheduler::keepsLastUpdate(changes, light) && keepShownLight &&
                     light.untilConverged && before.light.bounces > 1 && before.listComplete && volume_.direct() &&
                     scheduler_.spreadsOverFrames(light, budget);
    const bool keptIndirect = warmStart;
    if (warmStart) {
        Profiler::Scope scope(profiler_, step("bounces"));
        bounce_.keepIndirect(volume_);
    }
    if (changes.voxelize) {
        if (scroll) {
            Profiler::Scope scope(profiler_, step("scroll"));
            scroll_.execute(volume_, irradianceCache_, *scroll,
                            std::min(scheduler_.state().occupied, volume_.occupiedCapacity()));
            // The shown texels moved with their voxels.
            glCopyNamedBufferSubData(volume_.uniforms().id(), shownUniforms_.id(), 0, 0, sizeof(gpu::VoxelUniforms));
            shownPlacement_ = volume_.placement();
            changes_.voxelizedAll(items, volume_.placement());
        }
        {
            Profiler::Scope scope(profiler_, step("voxelize"));
            if (boxes) {
                voxelize_.executeBoxes(frame.scene, frame.gpuScene, volume_, *boxes, items, counters);
                report.voxelizedBoxes = static_cast<int>(boxes->size());
                for (const VoxelBox& box : *boxes) report.voxelizedVoxels += box.voxels();
            } else {
                voxelize_.execute(frame.scene, frame.gpuScene, volume_, counters);
                changes_.voxelizedAll(items, volume_.placement());
                const std::int64_t n = volume_.resolution();
                report.voxelizedVoxels = n * n * n;
            }
        }
        {
            // A column's walk reads that column only: after a voxelization of changed boxes, the
            // columns through them (their whole height: a box can open or close a solid above or below it).
            Profiler::Scope scope(profiler_, step("solid voxels"));
            // After a scroll every column: the solid bits did not move.
            solid_.execute(volume_, boxes ? std::span<const VoxelBox>(*boxes) : std::span<const VoxelBox>(),
                           scroll ? SolidVoxelsPass::Columns::Every : SolidVoxelsPass::Columns::ThroughBoxes);
        }
        {
            // Once per voxelization: the mip chain is then built over these (light edits too).
            Profiler::Scope scope(profiler_, step("mip lists"));
            mipmap_.listOccupiedParents(volume_);
        }
        ++generation_;
        // One uint read back per voxelization, a stall (every frame while a node animation plays:
        // the list ranges the traces take need the count): a list that overflowed is grown for the
        // next voxelization while this one runs over the whole grid.
        const std::uint32_t occupied = volume_.readOccupiedCount();
        const bool complete = occupied <= volume_.occupiedCapacity();
        if (!complete) {
            volume_.setParentListsValid(false);  // listed from an incomplete list: mipmaps over the whole grid
            log_.warning("occupied-voxel list overflowed (" + std::to_string(occupied) + " voxels, room for " +
                         std::to_string(volume_.occupiedCapacity()) +
                         "); injecting the whole grid until the next voxelization");
            volume_.growOccupiedList(occupied + occupied / 4);
        }
        // After a scroll no recorded hit holds: the traces march at their own pace, not a replay's.
        scheduler_.voxelized(voxels, occupied, complete, boxes.has_value() && !scroll);
        if (scroll) {
            // Every recorded hit lies where its voxel was: each entry marches (and records) again,
            // also in a pass under way (as for a box over the whole volume).
            const int n = volume_.resolution();
            rayHitCache_.markChanged({VoxelBox{glm::ivec3(0), glm::ivec3(n)}});
        } else if (boxes) {
            rayHitCache_.markChanged(*boxes);
        } else {
            rayHitCache_.forgetChanges();
            wholeVolumeEntries_ = occupied;
        }
    }
    const bool overList = scheduler_.state().listComplete;
    warmStart = warmStart && overList;

    if (slabUpdate) {
        // Level 0 keeps every voxel's light but the slabs', which get their direct light; the
        // scheduler's state stays that of the complete update.
        {
            Profiler::Scope scope(profiler_, step("inject"));
            inject_.execute(volume_, {.overList = overList,
                                      .writeDirect = true,
                                      .writeLevel0 = false,
                                      .level0Boxes = *boxes,
                                      .shadows = frame.shadows});
        }
        {
            Profiler::Scope scope(profiler_, step("mipmap"));
            mipmap_.execute(volume_, light.anisotropic, overList);
        }
        startSlabUpdate(*scroll);
        report.injected = true;
        pendingReason_ = changes.reason;
        pendingFrame_ = profiler_.currentFrame();
        pendingVoxelize_ = true;
        pendingBoxes_ = report.voxelizedBoxes;
        pendingBoxVoxels_ = report.voxelizedVoxels;
        pendingBounces_ = 0;
    } else if (changes.inject) {
        slabs_ = {};  // the update lights every voxel
        // Before the injection, which then writes the bounces' direct radiance beside level 0.
        if (light.bounces > 1) volume_.ensureBounceVolumes();
        // The next bounce gathers the new direct light whole, and the one after it too unless the next
        // reads the direct light itself: level 0 holds the old direct light until a bounce replaced it.
        changeReady_ = false;
        sourceHoldsDirect_ = false;
        ++injections_;
        const GiScheduler::UpdateStart start = scheduler_.startUpdate(changes, light, budget);
        {
            Profiler::Scope scope(profiler_, step("inject"));
            inject_.execute(volume_, {.overList = overList,
                                      .writeDirect = light.bounces > 1,
                                      .writeLevel0 = !start.keepLastUpdate,
                                      .level0Boxes = boxes ? *boxes : std::vector<VoxelBox>{},
                                      .shadows = frame.shadows});
        }
        // Every bounce starts from level 0: the warm-started light, or after a voxelization of
        // changed boxes the last update's light it kept outside them (their voxels hold direct
        // light), which leaves less for the bounces to do than the direct light alone. (A fixed
        // bounce count starts from the direct light: its second bounce is one bounce.)
        if (!start.runOn) warmStart_ = warmStart || (boxes && start.keepLastUpdate && light.untilConverged);
        if (warmStart) bounce_.addKeptIndirect(volume_);
        // With the last update's light kept in level 0 its mips stand too (the bounces' rays read
        // only their occupancy): the direct light's own mip build is saved (docs/PERFORMANCE.md,
        // "GI update"). A voxelization of changed boxes cleared them.
        if (!start.keepLastUpdate || boxes) {
            Profiler::Scope scope(profiler_, step("mipmap"));
            mipmap_.execute(volume_, light.anisotropic, overList);
        }
        // An update that runs on keeps measuring its bounces' convergence (reset at every edit of a
        // drag or an animation, it never saw two bounces in a row and ran to the bounce limit).
        if (!start.runOn) {
            convergence_ = {};
            shownDone_ = 0.0f;
        }
        pendingBounces_ = light.untilConverged ? 0 : light.bounces;
        if (start.bouncesNow > 0) {
            Profiler::Scope scope(profiler_, step("bounces"));
            for (int b = 2; b <= start.bouncesNow + 1; ++b) {
                const RayHits hits = rayHitsFor(features.voxelRays);
                if (light.untilConverged) bounce_.resetChange();
                rayHitCache_.beginPass();
                const bool fromDirect = b == 2 && !warmStart_;
                bounce_.trace(volume_, rayHitCache_,
                              {features, fromDirect, overList, {}, hits, light.untilConverged,
                               changeReady_ ? changeSubsetFor(b, features.voxelRays, light.laterBounceRayStride) : -1,
                               light.laterBounceRayStride});
                const bool converged = light.untilConverged && convergence_.add(bounce_.readChange().relative());
                const bool last = b == start.bouncesNow + 1 || converged;
                // The last bounce adds the ones still missing (BounceConvergence::tail).
                bounce_.finish(volume_, {overList, converged ? static_cast<float>(convergence_.tail()) : 0.0f, fromDirect,
                                         !converged && light.gathersChanges()});
                changeReady_ = bounce_.changeKept() && (fromDirect || sourceHoldsDirect_);
                sourceHoldsDirect_ = true;
                listTraced(hits);
                // Voxel rays read level 0 where they end and only the mips' occupancy, which a
                // bounce does not change: the mips are rebuilt after the last bounce alone.
                if (features.voxelRays == 0 || last) mipmap_.execute(volume_, light.anisotropic, overList);
                if (last) {
                    if (light.untilConverged) {
                        pendingBounces_ = b;
                        scheduler_.estimateBounces(b);
                    }
                    break;
                }
            }
        }
        if (start.prepareIrradiance) {
            // Only an update spread over frames shows anything before it completes (lit-render's
            // stills never need the second set of texels).
            irradianceCache_.prepare(volume_, start.clearIrradiance,
                                     (keepShownLight || keepShownOverMove) && scheduler_.spreadsOverFrames(light, budget));
            if (changes.voxelize && (!moved || scroll)) filter_.pruneShown(volume_, irradianceCache_);
        } else if (boxes && irradianceCache_.matches(volume_)) {
            // The update runs on over changed boxes: their voxels' traced irradiance belongs to
            // surfaces that moved, and neither set of texels may keep light where a surface is gone.
            irradianceCache_.forget(*boxes);
            filter_.pruneBoth(volume_, irradianceCache_);
        }
        report.injected = true;
        report.lightChanged = true;
        pendingReason_ = changes.reason;
        pendingFrame_ = profiler_.currentFrame();
        pendingVoxelize_ = changes.voxelize;
        pendingBoxes_ = report.voxelizedBoxes;
        pendingBoxVoxels_ = report.voxelizedVoxels;
    }
    {
        // The refinement waits for the slabs' light.
        GiBudget updateBudget = budget;
        if (!slabs_.boxes.empty()) updateBudget.refineVoxels = 0;
        continueUpdate(settings, light, updateBudget, {asked, edit}, keptIndirect, report);
    }
    // Under a time budget a move's frame has done its share (the scroll, the slabs' voxelization,
    // injection and mips cost more than the budget on llvmpipe): the slabs' light starts next frame.
    if (!(scroll && budget.milliseconds > 0.0)) continueSlabUpdate(settings, light, budget);

    const GiState& state = scheduler_.state();
    report.voxelized = changes.voxelize;
    report.scrolled = scroll.has_value();
    report.occupiedVoxels = state.occupied;
    // The uncovered slabs' update counts as refinement: the light is right elsewhere, and the
    // editor keeps rendering frames for it.
    report.refining = scheduler_.refinementLeft(light) || !slabs_.boxes.empty();
    // The share done never goes back while an update runs, though the expected bounce count can grow
    // as the light's convergence is measured (in the sun room the share would fall from 41 % to 27 %).
    const float done = scheduler_.updateDone();
    if (done >= 1.0f || shownDone_ >= 1.0f)
        shownDone_ = done;  // complete, or a new update
    else
        shownDone_ = std::max(shownDone_, done);
    report.updateDone = shownDone_;
    report.updateStage = scheduler_.updateStage(report.refinedVoxels > 0);
    if (!slabs_.boxes.empty())  // the light is right but for the slabs a scroll uncovered
        report.updateStage = slabs_.bounce > 0   ? "uncovered slabs, bounce " + std::to_string(slabs_.bounce)
                             : slabs_.round == 0 ? std::string("uncovered slabs, irradiance")
                                                 : "uncovered slabs, refining " + std::to_string(slabs_.round) + "/" +
                                                       std::to_string(GiScheduler::kConeSets - 1);
    report.bounces = state.light.untilConverged ? state.progress.bounceEstimate : state.light.bounces;
    report.everyBounce = state.light.untilConverged;
    report.showingPrevious = irradianceCache_.showingPrevious();
    if (level_ == VoxelGiLevel::Near && !report.showingPrevious) {  // the shown texels are this placement's
        glCopyNamedBufferSubData(volume_.uniforms().id(), shownUniforms_.id(), 0, 0, sizeof(gpu::VoxelUniforms));
        shownPlacement_ = volume_.placement();
    }
    return report;
}

void VoxelGi::continueUpdate(const RenderSettings& settings, const GiLightKey& light, const GiBudget& budget,
                             const Pace& pace, bool unmeasured, GiFrameReport& report) {
    const ConeFeatures features = featuresFor(settings);
    const bool overList = scheduler_.state().listComplete;
    // The list ranges traced this frame, and whether the frame completed an update or a
    // refinement round (or traced everything at once): then the filter runs over the whole list,
    // else only over the ranges traced (over all occupied voxels it costs as much as a third of
    // the trace it follows at 256³; docs/PERFORMANCE.md, "GI update").
    std::vector<VoxelRange> traced;
    bool filterAll = false;
    // The update's voxels traced this frame in the budget's units (the pacer's measure), and of
    // each kind of work.
    double updateVoxels = 0.0;
    std::array<double, GiPacer::kWorks> voxelsOfWork{};
    std::array<std::uint32_t, GiPacer::kWorks> allowedOfWork{};  // ... and the shares the budget allowed
    // Under a time budget: the frame's time the edit's whole work left, less what the shares traced
    // so far are expected to cost.
    const bool timed = pace.asked.milliseconds > 0.0;
    double msLeft = timed ? pace.asked.milliseconds - pacer_.editCost(pace.edit) : 0.0;
    // The budget for this frame's next share of `work`: each kind of pass paced by its own cost.
    const auto budgetFor = [&](GiPacer::Work work) {
        if (!timed) return budget;
        GiBudget left = pace.asked;
        left.milliseconds = std::max(msLeft, 1e-3);  // none left: the least share
        return pacer_.paced(left, work);
    };
    const auto countUpdate = [&](GiPacer::Work work, const GiBudget& share, std::uint32_t entries,
                                 std::uint32_t perFrame) {
        if (perFrame == 0) return;
        const double units = static_cast<double>(share.updateVoxels) * entries / perFrame;
        updateVoxels += units;
        voxelsOfWork[static_cast<std::size_t>(work)] += units;
        // An edit's frame leaves its share less time: what a frame without the edit would have been
        // allowed bounds the next frame's growth.
        allowedOfWork[static_cast<std::size_t>(work)] +=
            pace.edit == GiPacer::Edit::None || !timed ? share.updateVoxels
                                                       : pacer_.paced(pace.asked, work).updateVoxels;
        msLeft -= units * pacer_.estimatedCostPerVoxel(work);
    };
    const GiProgress& progress = scheduler_.state().progress;
    // A bounce that ends with more than this share of a time budget left lets the next bounce start
    // in the same frame (later bounces that gather their change take a fraction of the first's time:
    // one a frame, a small scene's update took twice the frames its work needed).
    constexpr double kNextBounceShare = 0.25;
    bool nextBounce = progress.bounce > 0;
    // The irradiance runs in a frame without a bounce, or after the last bounce with time left.
    bool irradianceNow = !nextBounce;
    if (nextBounce) {
        // A spread bounce: the last share ends it (level 0 and its mips); after the last bounce
        // the irradiance starts in the next frame, or in this one with time left.
        Profiler::Scope scope(profiler_, step("bounces"));
        while (nextBounce) {
            nextBounce = false;
            if (progress.bounceNext == 0) {
                bounceGathersChange_ = changeReady_;
                bounceStartInjections_ = injections_;
                bounceSourceHoldsDirect_ = sourceHoldsDirect_;
            }
            // After an injection while the bounce ran (a light dragged) its other voxels gather the
            // light whole, and so does the next bounce: the change holds the old direct light.
            const bool sameLight = injections_ == bounceStartInjections_;
            const int bounceNumber = progress.bounce;
            const int changeSubset = bounceGathersChange_ && sameLight
                                         ? changeSubsetFor(bounceNumber, features.voxelRays, light.laterBounceRayStride)
                                         : -1;
            const RayHits hits = rayHitsFor(features.voxelRays);
            // Replaying after a voxelization of changed boxes, the entries whose rays cross them march.
            const GiPacer::Work work = hits != RayHits::Replay           ? GiPacer::Work::Update
                                       : rayHitCache_.changedBoxes() > 0 ? GiPacer::Work::ReplayChangedBoxes
                                       : changeSubset >= 0               ? GiPacer::Work::ReplayChange
                                                                         : GiPacer::Work::Replay;
            const GiBudget share = budgetFor(work);
            std::uint32_t perFrame = scheduler_.voxelsPerFrame(share, light.voxelRays);
            if (changeSubset >= 0 && perFrame > 0)
                perFrame = static_cast<std::uint32_t>(std::min<std::uint64_t>(
                    std::uint64_t{perFrame} * kChangeVoxelsPerFrameFactor, std::numeric_limits<std::uint32_t>::max()));
            const VoxelRange range = scheduler_.bounceShare(perFrame);
            countUpdate(work, share, range.count, perFrame);
            if (light.untilConverged && range.first == 0) bounce_.resetChange();
            if (range.first == 0) rayHitCache_.beginPass();
            const bool fromDirect = progress.bounce == 2 && !warmStart_;
            bounce_.trace(volume_, rayHitCache_,
                          {features, fromDirect, true, range, hits, light.untilConverged, changeSubset,
                           light.laterBounceRayStride});
            const bool passEnds = range.first + range.count >= scheduler_.state().occupied;
            const bool converged = passEnds && light.untilConverged && convergence_.add(bounce_.readChange().relative());
            if (light.untilConverged && convergence_.expectedBounces() > 0)
                scheduler_.estimateBounces(converged ? progress.bounce : convergence_.expectedBounces());
            if (scheduler_.advanceBounce(range, converged)) {
                listTraced(hits);  // the pass ran over the whole list from 0
                bounce_.finish(volume_, {true, converged ? static_cast<float>(convergence_.tail()) : 0.0f, fromDirect,
                                         !converged && light.gathersChanges()});
                changeReady_ = bounce_.changeKept() && sameLight && (fromDirect || bounceSourceHoldsDirect_);
                sourceHoldsDirect_ = sameLight;
                // Voxel rays need the mips' occupancy only (see update()): rebuilt after the last bounce.
                if (features.voxelRays == 0 || scheduler_.state().progress.bounce == 0)
                    mipmap_.execute(volume_, light.anisotropic, overList);
                const bool timeLeft =
                    timed && features.voxelRays > 0 && msLeft > kNextBounceShare * pace.asked.milliseconds;
                nextBounce = timeLeft && progress.bounce > 0;
                irradianceNow = timeLeft && progress.bounce == 0;
            }
        }
    }
    if (irradianceNow && light.voxelIrradiance && progress.irradianceLeft > 0) {
        Profiler::Scope scope(profiler_, step("voxel irradiance"));
        if (!scheduler_.spreadsOverFrames(light, budget)) {
            const RayHits hits = rayHitsFor(features.voxelRays);
            rayHitCache_.beginPass();
            irradiance_.trace(volume_, irradianceCache_, rayHitCache_, {features, overList, {}, 0, hits});
            listTraced(hits);
            scheduler_.irradianceDone();
            report.updateCompleted = true;
        } else {
            const RayHits hits = rayHitsFor(features.voxelRays);
            const GiPacer::Work work =
                hits == RayHits::Replay ? GiPacer::Work::ReplayIrradiance : GiPacer::Work::Update;
            const GiBudget share = budgetFor(work);
            const std::uint32_t perFrame = scheduler_.voxelsPerFrame(share, light.voxelRays);
            // The first share of a pass over the whole list (from where the round robin stands).
            if (scheduler_.state().progress.irradianceLeft >= scheduler_.state().occupied) rayHitCache_.beginPass();
            const std::vector<VoxelRange> ranges = scheduler_.takeIrradiance(perFrame);
            for (const VoxelRange& range : ranges) {
                irradiance_.trace(volume_, irradianceCache_, rayHitCache_, {features, true, range, 0, hits});
                traced.push_back(range);
                countUpdate(work, share, range.count, perFrame);
            }
            // Every entry was traced once since the edit: recorded, if that is what it did. The
            // accumulated indirect light holds the update's frames (old light in the voxels not
            // reached yet): the frame after it starts the history afresh.
            if (scheduler_.state().progress.irradianceLeft == 0) {
                report.lightChanged = true;
                report.updateCompleted = true;
                listTraced(hits);
                // An edit came while it ran (a light or node dragged, an animation playing): the
                // next update starts now, and the pixels gather this one's light meanwhile (below).
                if (scheduler_.restartIfAsked()) {
                    convergence_ = {};
                    shownDone_ = 0.0f;
                }
            }
        }
        filterAll = report.updateCompleted;
    }
    // The refinement once the update is done, in the same frame when the budget allows (a still
    // converges in its one frame; a time budget the update used waits for the next frame). Round k
    // traces every voxel's set + k once over the list; each voxel then averages k + 1 sets. The
    // light is right throughout: only its sampling improves.
    const GiProgress& after = scheduler_.state().progress;
    const bool timeLeft = !(budget.milliseconds > 0.0 && updateVoxels > 0.0);
    if (after.bounce == 0 && after.irradianceLeft == 0 && scheduler_.refinementLeft(light) && budget.refineVoxels > 0 &&
        timeLeft) {
        Profiler::Scope scope(profiler_, step("voxel irradiance"));
        int rounds = 0;
        for (const GiScheduler::RefineShare& share : scheduler_.takeRefinement(budget.refineVoxels, rounds)) {
            irradiance_.trace(volume_, irradianceCache_, rayHitCache_, {features, true, share.range, share.setOffset});
            traced.push_back(share.range);
            report.refinedVoxels += share.range.count;
        }
        filterAll = filterAll || rounds > 0;
    }
    if (filterAll || !traced.empty()) {
        // The voxels traced see their new values (and, once the update is complete, every voxel
        // its neighbours' new values: the result is then the all-at-once filter's exactly).
        Profiler::Scope scope(profiler_, step("voxel irradiance filter"));
        if (filterAll) {
            filter_.execute(volume_, irradianceCache_, overList);
        } else {
            for (const VoxelRange& range : traced) filter_.execute(volume_, irradianceCache_, true, range);
        }
    }
    if (budget.milliseconds > 0.0 && !unmeasured) {
        const std::uint64_t frame = profiler_.currentFrame();
        if (updateVoxels > 0.0) {
            for (std::size_t k = 0; k < GiPacer::kWorks; ++k)
                if (voxelsOfWork[k] > 0.0)
                    pacer_.traced(frame, static_cast<GiPacer::Work>(k),
                                  static_cast<std::uint32_t>(std::ceil(voxelsOfWork[k])), allowedOfWork[k]);
        } else if (report.refinedVoxels > 0) {
            pacer_.traced(frame, GiPacer::Work::Refine, report.refinedVoxels);
        }
    }
    // Every voxel holds the update's light: the pixels gather it from now on.
    if (report.updateCompleted ||
        (scheduler_.state().progress.irradianceLeft == 0 && scheduler_.state().progress.bounce == 0))
        irradianceCache_.showWritten();
}

void VoxelGi::startSlabUpdate(glm::ivec3 shift) {
    // The voxels that lay within a quarter of the side of the face the level moved towards are lit
    // again with the slabs: their rays left the level soon through that face into coarser light,
    // and now run on inside it (docs/GI.md, "Near levels": lit with the slabs alone they read
    // 15 % RMSE against a level voxelized whole).
    const glm::ivec3 n(volume_.resolution());
    const glm::ivec3 relit = glm::sign(shift) * glm::min(glm::abs(shift) + n / 4, n - 1);
    std::vector<VoxelBox> boxes = uncoveredSlabs(relit, n.x);
    // Slabs still unlit from an earlier scroll moved with the level; what left it is dropped.
    for (const VoxelBox& old : slabs_.boxes) {
        const VoxelBox moved{glm::clamp(old.min - shift, glm::ivec3(0), n),
                             glm::clamp(old.max - shift, glm::ivec3(0), n)};
        if (!moved.empty()) boxes.push_back(moved);
    }
    // Bounces under way run on over the new slabs too (their voxels start from their direct light
    // as the others did): restarted at every scroll, a camera that moves on would keep them from
    // ever converging. From the irradiance on, the new slabs need their bounces first.
    const bool runOn = !slabs_.boxes.empty() && slabs_.bounce > 0;
    if (!runOn) slabs_ = {};
    slabs_.boxes = mergeVoxelBoxes(std::move(boxes), VoxelChangeTracker::kMaxBoxes);
    // The list read back once a scroll (a stall, as the voxelization's count; 4 bytes an entry).
    slabs_.shares = ListBoxShares(volume_.readOccupiedList(), slabs_.boxes);
}

void VoxelGi::continueSlabUpdate(const RenderSettings& settings, const GiLightKey& light, const GiBudget& budget) {
    if (slabs_.boxes.empty()) return;
    const std::uint32_t entries = std::min(scheduler_.state().occupied, volume_.occupiedCapacity());
    const ConeFeatures features = featuresFor(settings);
    if (slabs_.shares.entries() != entries) slabs_.shares = ListBoxShares(volume_.readOccupiedList(), slabs_.boxes);
    // A budget's voxel count is the slabs' voxels a frame traces (kAll: all at once): the list's
    // entries that hold them (0: the whole list).
    const auto entriesFor = [&](std::uint32_t voxels) -> std::uint32_t {
        if (voxels == GiBudget::kAll) return 0;
        return slabs_.shares.entriesFor(slabs_.next, voxels);
    };
    if (slabs_.mipmapPending) {
        // Under a time budget the mips after the last bounce take a frame of their own, as long as
        // a share of the bounces (spreadGiMs leaves them out, and the pacer records no voxels).
        Profiler::Scope scope(profiler_, step("mipmap"));
        mipmap_.execute(volume_, light.anisotropic, true);
        slabs_.mipmapPending = false;
        return;
    }
    volume_.setOnlyBoxes(slabs_.boxes);
    double tracedVoxels = 0.0;  // the slabs' voxels traced this frame, for the pacer
    GiPacer::Work work = GiPacer::Work::Update;
    for (bool traced = false; !slabs_.boxes.empty();) {
        // The refinement's rounds take the refinement's budget, and wait when it is 0.
        const bool refining = slabs_.bounce == 0 && slabs_.round > 0;
        if (refining && budget.refineVoxels == 0) break;
        const std::uint32_t perFrame = entriesFor(refining ? budget.refineVoxels : budget.updateVoxels);
        if (traced && perFrame > 0) break;  // a share a frame
        traced = true;
        const VoxelRange range{slabs_.next, perFrame > 0 ? std::min(perFrame, entries - slabs_.next) : entries};
        const bool passEnds = range.first + range.count >= entries;
        slabs_.next = passEnds ? 0 : slabs_.next + range.count;
        tracedVoxels += slabs_.shares.inRange(range.first, range.count);
        work = refining ? GiPacer::Work::Refine : GiPacer::Work::Update;
        if (slabs_.bounce > 0) {
            // Every bounce gathers level 0: the kept voxels' converged light and the slabs' own.
            Profiler::Scope scope(profiler_, step("bounces"));
            if (range.first == 0) bounce_.resetChange();
            bounce_.trace(volume_, rayHitCache_,
                          {features, false, true, range, RayHits::Off, true, -1, light.laterBounceRayStride});
            if (!passEnds) continue;
            const bool converged = slabs_.convergence.add(bounce_.readChange().relative());
            const bool last = converged || slabs_.bounce >= light.bounces;
            bounce_.finish(volume_,
                           {true, converged ? static_cast<float>(slabs_.convergence.tail()) : 0.0f, false, false});
            slabs_.bounce = last ? 0 : slabs_.bounce + 1;
            if (last && budget.milliseconds > 0.0) {
                slabs_.mipmapPending = true;
                break;
            }
            if (last) mipmap_.execute(volume_, light.anisotropic, true);
            continue;
        }
        // The irradiance with each voxel's own cone set (round 0), then the other sets averaged in
        // (GiScheduler::takeRefinement's rounds).
        {
            Profiler::Scope scope(profiler_, step("voxel irradiance"));
            irradiance_.trace(volume_, irradianceCache_, rayHitCache_,
                              {features, true, range, slabs_.round, RayHits::Off});
        }
        Profiler::Scope scope(profiler_, step("voxel irradiance filter"));
        // A round's last share filters all the slabs' voxels, each then seeing its neighbours' values.
        filter_.execute(volume_, irradianceCache_, true, passEnds ? VoxelRange{} : range);
        if (passEnds && ++slabs_.round == GiScheduler::kConeSets) slabs_.boxes.clear();
    }
    volume_.setOnlyBoxes({});
    if (budget.milliseconds > 0.0 && tracedVoxels > 0.0)
        pacer_.traced(profiler_.currentFrame(), work, static_cast<std::uint32_t>(std::ceil(tracedVoxels)));
}

void VoxelGi::bindGather(const RenderSettings& settings) const {
    if (settings.gi.voxelIrradiance()) irradianceCache_.bindGatherTexels();
}

std::size_t VoxelGi::bytes() const { return volume_.totalBytes() + irradianceCache_.bytes() + rayHitCache_.bytes(); }

void VoxelGi::reportUpdate() {
    if (pendingFrame_ == 0) return;
    const PassTiming* injectTiming = profiler_.lastRun(step("inject"));
    if (!injectTiming || injectTiming->frame < pendingFrame_) return;
    const PassTiming* voxelizeTiming = profiler_.lastRun(step("voxelize"));
    const PassTiming* mipTiming = profiler_.lastRun(step("mipmap"));
    std::string text = std::string(level_ == VoxelGiLevel::Near ? "near level: " : "") +
                       (pendingVoxelize_ ? "re-voxelized " : "re-injected ");
    if (pendingVoxelize_ && pendingBoxes_ > 0)
        text += std::to_string(pendingBoxes_) + (pendingBoxes_ > 1 ? " changed boxes (" : " changed box (") +
                std::to_string(pendingBoxVoxels_) + " voxels) of ";
    text += std::to_string(volume_.resolution()) + "³ (" + pendingReason_ + "): ";
    if (pendingVoxelize_ && voxelizeTiming) text += "voxelize " + formatMs(voxelizeTiming->gpuMs) + ", ";
    const PassTiming* solidTiming = profiler_.lastRun(step("solid voxels"));
    if (pendingVoxelize_ && solidTiming && solidTiming->frame >= pendingFrame_)
        text += "solid voxels " + formatMs(solidTiming->gpuMs) + ", ";
    const PassTiming* listsTiming = profiler_.lastRun(step("mip lists"));
    if (pendingVoxelize_ && listsTiming && listsTiming->frame >= pendingFrame_)
        text += "mip lists " + formatMs(listsTiming->gpuMs) + ", ";
    const GiState& state = scheduler_.state();
    const double n = volume_.resolution();
    char occupancy[96];
    std::snprintf(occupancy, sizeof occupancy, "inject %s over %u occupied voxels (%.2f %% of the grid%s)",
                  formatMs(injectTiming->gpuMs).c_str(), state.occupied, 100.0 * state.occupied / (n * n * n),
                  state.listComplete ? "" : ", list overflowed: whole grid");
    text += occupancy;
    if (mipTiming) text += ", mipmap " + formatMs(mipTiming->gpuMs);
    const PassTiming* bounceTiming = profiler_.lastRun(step("bounces"));
    if (bounceTiming && bounceTiming->frame >= pendingFrame_) {
        // 0: every bounce, spread over frames (the count is known when the light converges).
        text += pendingBounces_ == 0
                    ? std::string(", bounces until converged ")
                    : ", " + std::to_string(pendingBounces_ - 1) + " more bounce" + (pendingBounces_ > 2 ? "s " : " ");
        text += formatMs(bounceTiming->gpuMs);
    }
    const PassTiming* irradianceTiming = profiler_.lastRun(step("voxel irradiance"));
    if (irradianceTiming && irradianceTiming->frame >= pendingFrame_)
        text += ", voxel irradiance " + formatMs(irradianceTiming->gpuMs);
    const PassTiming* filterTiming = profiler_.lastRun(step("voxel irradiance filter"));
    if (filterTiming && filterTiming->frame >= pendingFrame_) text += " + filter " + formatMs(filterTiming->gpuMs);
    // Every frame of a gizmo drag re-voxelizes: one folded line with a count, not one per frame.
    log_.info(text, Fold::IgnoringNumbers);
    pendingFrame_ = 0;
}

MipmapTimings VoxelGi::benchmarkMipmaps(int repetitions) {
    if (!valid()) return {};
    return lit::benchmarkMipmaps(mipmap_, volume_, repetitions, scheduler_.state().light.anisotropic);
}

}  // namespace lit
