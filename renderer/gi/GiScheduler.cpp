#include "gi/GiScheduler.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lit {

GiLightKey GiLightKey::of(const RenderSettings& settings) {
    const GiSettings& gi = settings.gi;
    GiLightKey key;
    key.untilConverged = gi.bounces == kAllBounces;
    key.bounces = key.untilConverged ? kMaxConvergingBounces : std::clamp(gi.bounces, 1, kMaxBounces);
    key.voxelIrradiance = gi.voxelIrradiance();
    key.anisotropic = gi.anisotropicVoxels();
    key.voxelRays = std::clamp(gi.voxelRays, 0, kMaxVoxelRays);
    key.laterBounceRayStride = std::clamp(gi.laterBounceRayStride, 1, kMaxLaterBounceRayStride);
    key.footprint = gi.footprintPerHeight();
    key.aperture = gi.diffuseConeAperture;
    key.stepScale = gi.coneStepScale;
    key.traceDistance = gi.maxTraceDistance;
    key.intensity = gi.indirectIntensity;
    key.radianceRange = gi.radianceRange;
    return key;
}

bool GiLightKey::retraces(const GiLightKey& last) const {
    if (bounces != last.bounces || untilConverged != last.untilConverged || voxelIrradiance != last.voxelIrradiance)
        return true;
    // What the traces read matters only when something traces.
    const bool traced = last.bounces > 1 || last.voxelIrradiance;
    return traced && (anisotropic != last.anisotropic || voxelRays != last.voxelRays ||
                      laterBounceRayStride != last.laterBounceRayStride || footprint != last.footprint ||
                      aperture != last.aperture || stepScale != last.stepScale || traceDistance != last.traceDistance ||
                      intensity != last.intensity);
}

bool BounceConvergence::add(double relativeChange) {
    ++bounces_;
    tail_ = 0.0;
    const double previous = last_;
    last_ = relativeChange;
    if (relativeChange <= kStill) return true;
    if (previous <= 0.0) return false;  // one measured bounce says nothing of the rate
    const double ratio = std::clamp(relativeChange / previous, 0.0, 0.97);
    const bool steady = lastRatio_ >= 0.0 && std::abs(ratio - lastRatio_) <= kSteadyRatio;
    lastRatio_ = ratio;
    const double missing = relativeChange * ratio / (1.0 - ratio);
    // Bounces until missing · ratio^n falls below what stops the update (with the ratio steady,
    // as it stays once steady).
    const double stop = steady ? kExtrapolated : kMissing;
    const double more =
        ratio > 0.0 && missing > stop ? std::ceil(std::log(stop / missing) / std::log(ratio)) : 0.0;
    expected_ = bounces_ + static_cast<int>(std::min(more, 1000.0));
    if (missing >= stop) return false;
    tail_ = ratio / (1.0 - ratio);
    return true;
}

GiScheduler::Changes GiScheduler::changes(const VoxelKey& voxels, const GiLightKey& light, bool volumeReallocated,
                                          bool volumeMoved, bool shadowsDirty) const {
    Changes c;
    c.voxelize = !state_.voxelsValid || volumeReallocated || volumeMoved || !(voxels == state_.voxels);
    if (!state_.voxelsValid)
        c.reason = "first GI frame";
    else if (volumeReallocated)
        c.reason = "voxel resolution or format changed";
    else if (volumeMoved || voxels.geometry != state_.voxels.geometry || voxels.scene != state_.voxels.scene)
        c.reason = "geometry changed";
    else if (voxels.materials != state_.voxels.materials)
        c.reason = "materials changed";
    c.retrace = light.retraces(state_.light);
    // The directional chains are built only while anisotropic voxels are on: switching them on
    // builds them.
    const bool directionalMissing = light.anisotropic && !state_.light.anisotropic;
    const bool rangeChanged = light.radianceRange != state_.light.radianceRange;
    c.inject = c.voxelize || shadowsDirty || rangeChanged || c.retrace || directionalMissing;
    c.onlyScene = !c.retrace && !directionalMissing && !rangeChanged;
    c.onlyLight = !c.voxelize && c.onlyScene;
    if (!c.voxelize && c.inject)
        c.reason = c.retrace            ? "bounce settings changed"
                   : directionalMissing ? "anisotropic voxels switched on"
                                        : "lights or shadows changed";
    return c;
}

void GiScheduler::voxelized(const VoxelKey& voxels, std::uint32_t occupied, bool listComplete, bool keptRayHits) {
    state_.voxels = voxels;
    state_.voxelsValid = true;
    state_.occupied = occupied;
    state_.listComplete = listComplete;
    state_.rayHitsValid = state_.rayHitsValid && keptRayHits && listComplete;  // other voxels: other hits
}

std::uint32_t GiScheduler::voxelsPerFrame(const GiBudget& budget, int rays) const {
    const std::uint32_t perFrame = budget.updateVoxels == GiBudget::kAll ? 0u : std::max(budget.updateVoxels, 1u);
    if (!replaysRayHits(rays)) return perFrame;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(std::uint64_t{perFrame} * kReplayVoxelsPerFrameFactor,
                                                              std::numeric_limits<std::uint32_t>::max()));
}

bool GiScheduler::spreadsOverFrames(const GiLightKey& light, const GiBudget& budget) const {
    const std::uint32_t perFrame = voxelsPerFrame(budget, light.voxelRays);
    // Under a time budget a pass that fits one frame is still one pass of several (the bounces,
    // then the irradiance): run all at once they would take the frame several times over.
    const bool timed = budget.milliseconds > 0.0;
    return light.voxelIrradiance && perFrame > 0 && (timed || perFrame < state_.occupied) && state_.listComplete;
}

bool GiScheduler::replaysRayHits(int rays) const {
    return state_.rayHitsValid && state_.rayHitsRays > 0 && state_.rayHitsRays == rays;
}

void GiScheduler::restartIrradiance() {
    GiProgress& p = state_.progress;
    p.irradianceLeft = std::max(state_.occupied, 1u);
    p.refineRound = 1;
    p.refineNext = 0;
}

bool GiScheduler::keepsLastUpdate(const Changes& changes, const GiLightKey& light) {
    return (changes.onlyLight || (changes.changedBoxesOnly && changes.onlyScene)) && light.bounces > 1 &&
           light.voxelRays > 0;
}

GiScheduler::UpdateStart GiScheduler::startUpdate(const Changes& changes, const GiLightKey& light,
                                                  const GiBudget& budget) {
    UpdateStart u;
    GiProgress& p = state_.progress;
    u.keepLastUpdate = keepsLastUpdate(changes, light);
    // A light dragged in the editor, a node dragged or animated, edits every frame: starting the
    // spread update again at each edit would keep it from ever reaching the irradiance, so it runs
    // on and another follows.
    const bool updateRunning = p.bounce > 0 || (state_.light.voxelIrradiance && p.irradianceLeft > 0);
    u.runOn = u.keepLastUpdate && updateRunning && spreadsOverFrames(light, budget) &&
              light.voxelIrradiance == state_.light.voxelIrradiance;
    p.updateAgain = u.runOn;
    if (!u.runOn) {
        p.bounce = 0;
        if (light.bounces > 1) {
            p.bounceEstimate = light.untilConverged ? kFirstBounceEstimate : light.bounces;
            if (spreadsOverFrames(light, budget)) {
                p.bounce = 2;
                p.bounceNext = 0;
            } else {
                u.bouncesNow = light.bounces - 1;
            }
        }
        if (light.voxelIrradiance) {
            // From where the update stands (a new list after a voxelization: from its start), so
            // a light dragged over many frames keeps refreshing every voxel in turn.
            u.prepareIrradiance = true;
            u.clearIrradiance = changes.voxelize;
            if (changes.voxelize || p.irradianceNext >= state_.occupied) p.irradianceNext = 0;
            restartIrradiance();
        }
    }
    state_.light = light;
    return u;
}

RayHits GiScheduler::rayHits(int rays, bool cacheFits, bool cacheReallocated) {
    if (rays <= 0 || !state_.listComplete) return RayHits::Off;
    if (!cacheFits) {
        state_.rayHitsValid = false;
        return RayHits::Off;
    }
    if (cacheReallocated || rays != state_.rayHitsRays) state_.rayHitsValid = false;
    state_.rayHitsRays = rays;
    return replaysRayHits(rays) ? RayHits::Replay : RayHits::Record;
}

VoxelRange GiScheduler::bounceShare(std::uint32_t perFrame) const {
    const GiProgress& p = state_.progress;
    const std::uint32_t left = state_.occupied - std::min(p.bounceNext, state_.occupied);
    return {p.bounceNext, perFrame == 0 ? left : std::min(perFrame, left)};
}

bool GiScheduler::advanceBounce(VoxelRange range, bool converged) {
    GiProgress& p = state_.progress;
    p.bounceNext += range.count;
    if (p.bounceNext < state_.occupied) return false;
    p.bounceNext = 0;
    const bool settled = state_.light.untilConverged && converged;
    if (settled) p.settledBounces = p.bounce;
    const int ranOnLimit = p.settledBounces > 0 ? p.settledBounces : kFirstBounceEstimate;
    const bool last = p.bounce >= state_.light.bounces || settled ||
                      (state_.light.untilConverged && p.updateAgain && p.bounce >= ranOnLimit);
    p.bounce = last ? 0 : p.bounce + 1;
    return true;
}

std::vector<VoxelRange> GiScheduler::takeIrradiance(std::uint32_t perFrame) {
    GiProgress& p = state_.progress;
    std::vector<VoxelRange> ranges;
    std::uint32_t left = std::min(perFrame, p.irradianceLeft);
    p.irradianceLeft -= left;
    while (left > 0 && state_.occupied > 0) {  // at most twice: up to the list's end, then from its start
        const std::uint32_t count = std::min(left, state_.occupied - p.irradianceNext);
        ranges.push_back({p.irradianceNext, count});
        p.irradianceNext = (p.irradianceNext + count) % state_.occupied;
        left -= count;
    }
    return ranges;
}

bool GiScheduler::restartIfAsked() {
    GiProgress& p = state_.progress;
    if (p.irradianceLeft > 0 || !p.updateAgain) return false;
    p.updateAgain = false;
    p.bounce = state_.light.bounces > 1 ? 2 : 0;
    p.bounceNext = 0;
    p.bounceEstimate = state_.light.untilConverged ? kFirstBounceEstimate : state_.light.bounces;
    restartIrradiance();
    return true;
}

bool GiScheduler::refinementLeft(const GiLightKey& light) const {
    return light.voxelIrradiance && state_.progress.refineRound < kConeSets && state_.listComplete &&
           state_.occupied > 0;
}

std::vector<GiScheduler::RefineShare> GiScheduler::takeRefinement(std::uint32_t budget, int& roundsCompleted) {
    GiProgress& p = state_.progress;
    std::vector<RefineShare> shares;
    roundsCompleted = 0;
    std::uint32_t left = budget;
    while (left > 0 && p.refineRound < kConeSets && state_.occupied > 0) {
        const std::uint32_t count = std::min(left, state_.occupied - p.refineNext);
        shares.push_back({{p.refineNext, count}, p.refineRound});
        left -= count;
        p.refineNext += count;
        if (p.refineNext >= state_.occupied) {
            p.refineNext = 0;
            ++p.refineRound;
            ++roundsCompleted;
        }
    }
    return shares;
}

float GiScheduler::updateDone() const {
    const GiProgress& p = state_.progress;
    const double list = std::max(state_.occupied, 1u);
    // Every bounce: the passes the update is expected to take; the bounce under way is never the
    // last one counted, so the figure stays below 1 until the update ends. Passes weigh what they
    // cost: a bounce after the second that gathers the change over a subset of the rays about
    // 1 / kChangeVoxelsPerFrameFactor of one that gathers every ray (the second, the irradiance).
    const int bounces = state_.light.untilConverged ? std::max(p.bounceEstimate, p.bounce + 1) : state_.light.bounces;
    const GiLightKey& light = state_.light;
    const double later = light.gathersChanges() ? 1.0 / kChangeVoxelsPerFrameFactor : 1.0;
    // The work before bounce b (2, 3, ...) begins, in whole passes.
    const auto before = [&](int b) { return std::min(b - 2, 1) + std::max(b - 3, 0) * later; };
    const double total = before(bounces + 1) + (light.voxelIrradiance ? 1.0 : 0.0);
    if (p.bounce > 0) {
        const double pass = p.bounce == 2 ? 1.0 : later;
        return static_cast<float>((before(p.bounce) + pass * p.bounceNext / list) / total);
    }
    if (light.voxelIrradiance && p.irradianceLeft > 0)
        return static_cast<float>((before(bounces + 1) + (list - p.irradianceLeft) / list) / total);
    return 1.0f;
}

std::string GiScheduler::updateStage(bool refinedThisFrame) const {
    const GiProgress& p = state_.progress;
    if (p.bounce > 0) return "bounce " + std::to_string(p.bounce);
    if (state_.light.voxelIrradiance && p.irradianceLeft > 0) return "irradiance";
    if (refinedThisFrame && p.refineRound < kConeSets)
        return "refining " + std::to_string(p.refineRound) + "/" + std::to_string(kConeSets - 1);
    return "";
}

}  // namespace lit
