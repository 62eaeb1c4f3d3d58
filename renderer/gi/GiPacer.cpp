#include "gi/GiPacer.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace lit {

namespace {
// Frames kept waiting for their timings: far more than the profiler keeps in flight, so a timing
// that never comes (a frame whose queries were dropped) does not keep its entry for ever.
constexpr std::size_t kMaxWaiting = 16;
}  // namespace

double spreadGiMs(const std::vector<PassTiming>& timings, SpreadWork which) {
    const auto spread = [](std::string_view name) {
        return name == "bounces" || name == "voxel irradiance" || name == "voxel irradiance filter";
    };
    double ms = 0.0;
    for (const PassTiming& t : timings) {
        if (!t.ran) continue;
        const std::string_view name = t.name;
        const bool near = name.starts_with("near ");
        const bool counted = which == SpreadWork::All || (which == SpreadWork::NearLevels) == near;
        if (counted && spread(near ? name.substr(5) : name)) ms += t.gpuMs;
    }
    return ms;
}

EditGiTime editGiMs(const std::vector<PassTiming>& timings, SpreadWork which) {
    EditGiTime out;
    bool injected = false;
    for (const PassTiming& t : timings) {
        if (!t.ran) continue;
        std::string_view name = t.name;
        const bool near = name.starts_with("near ");
        if (near != (which == SpreadWork::NearLevels)) continue;
        if (near) name = name.substr(5);
        const bool voxelizing = name == "scroll" || name == "voxelize" || name == "solid voxels" || name == "mip lists";
        if (!voxelizing && name != "inject" && name != "mipmap") continue;
        out.ms += t.gpuMs;
        out.voxelized = out.voxelized || voxelizing;
        injected = injected || name == "inject";
    }
    return injected ? out : EditGiTime{};
}

GiBudget GiPacer::paced(const GiBudget& budget, Work update, Edit edit) const {
    if (!(budget.milliseconds > 0.0)) return budget;
    GiBudget out = budget;
    // What the edit's whole work leaves (an edit that takes it all leaves the least share, so that
    // an animation that moves every frame still brings its light up to date).
    const double ms = std::max(budget.milliseconds - editCost(edit), 0.0);
    // kAll asks for the whole update in the edit's frame, time or not.
    if (budget.updateVoxels != GiBudget::kAll)
        out.updateVoxels = voxelsFor(update == Work::Refine ? Work::Update : update, ms, budget.updateVoxels);
    if (budget.refineVoxels > 0 && budget.refineVoxels != GiBudget::kAll)
        out.refineVoxels = voxelsFor(Work::Refine, ms, budget.refineVoxels);
    return out;
}

void GiPacer::editMeasured(Edit edit, double gpuMs) {
    if (edit == Edit::None || !(gpuMs > 0.0) || !std::isfinite(gpuMs)) return;
    double& estimate = editCost_[static_cast<std::size_t>(edit)];
    estimate = estimate > 0.0 ? estimate + kSmoothing * (gpuMs - estimate) : gpuMs;
}

std::uint32_t GiPacer::voxelsFor(Work work, double milliseconds, std::uint32_t most) const {
    const std::size_t i = index(work);
    double voxels = kFirstVoxels;
    const double cost = estimatedCostPerVoxel(work);
    if (cost > 0.0) {
        voxels = milliseconds / cost;
        // Growth is bounded by what the last measured frames traced, not by the last budget given:
        // frames that waited (no work of this kind) do not ratchet it up.
        if (lastTraced_[i] > 0) voxels = std::min(voxels, kMaxGrowth * lastTraced_[i]);
    }
    voxels = std::clamp(voxels, static_cast<double>(kMinVoxels), static_cast<double>(most));
    return static_cast<std::uint32_t>(std::max(std::floor(voxels), 1.0));
}

double GiPacer::estimatedCostPerVoxel(Work work) const {
    // An update work not measured yet takes the dearest known cost of the update's others (they are
    // counted in units that make them cost alike), not kFirstVoxels' slow start: every edit begins
    // a new kind of pass, and a move's update passes through four.
    double cost = cost_[index(work)];
    if (!(cost > 0.0) && work != Work::Refine)
        for (std::size_t k = 0; k < kWorks; ++k)
            if (k != index(Work::Refine)) cost = std::max(cost, cost_[k]);
    return cost;
}

void GiPacer::traced(std::uint64_t frame, Work work, std::uint32_t voxels, std::uint32_t allowed) {
    if (voxels == 0) return;
    const auto same = std::find_if(traced_.begin(), traced_.end(),
                                   [&](const Traced& t) { return t.frame == frame && t.work == work; });
    if (same != traced_.end()) {
        same->voxels += voxels;
        lastTraced_[index(work)] = std::max(same->voxels, allowed);
        return;
    }
    traced_.push_back({frame, work, voxels});
    lastTraced_[index(work)] = std::max(voxels, allowed);
    while (traced_.size() > kMaxWaiting) traced_.pop_front();
}

void GiPacer::measured(std::uint64_t frame, double gpuMs) {
    // Frames older than this one will not be measured any more (timings arrive in frame order).
    while (!traced_.empty() && traced_.front().frame < frame) traced_.pop_front();
    std::vector<Traced> kinds;
    while (!traced_.empty() && traced_.front().frame == frame) {
        kinds.push_back(traced_.front());
        traced_.pop_front();
    }
    if (kinds.empty() || !(gpuMs > 0.0) || !std::isfinite(gpuMs)) return;
    // Each kind's share of the time by what its voxels were expected to cost (alike while no cost
    // is known).
    std::vector<double> expected;
    double total = 0.0;
    for (const Traced& t : kinds) {
        const double cost = estimatedCostPerVoxel(t.work);
        expected.push_back(t.voxels * (cost > 0.0 ? cost : 1.0));
        total += expected.back();
    }
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        const double cost = gpuMs * expected[k] / total / kinds[k].voxels;
        double& estimate = cost_[index(kinds[k].work)];
        estimate = estimate > 0.0 ? estimate + kSmoothing * (cost - estimate) : cost;
    }
}

}  // namespace lit
