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

GiBudget GiPacer::paced(const GiBudget& budget) const {
    if (!(budget.milliseconds > 0.0)) return budget;
    GiBudget out = budget;
    // kAll asks for the whole update in the edit's frame, time or not.
    if (budget.updateVoxels != GiBudget::kAll)
        out.updateVoxels = voxelsFor(Work::Update, budget.milliseconds, budget.updateVoxels);
    if (budget.refineVoxels > 0 && budget.refineVoxels != GiBudget::kAll) out.refineVoxels = voxelsFor(Work::Refine, budget.milliseconds, budget.refineVoxels);
    return out;
}

std::uint32_t GiPacer::voxelsFor(Work work, double milliseconds, std::uint32_t most) const {
    const std::size_t i = index(work);
    double voxels = kFirstVoxels;
    if (cost_[i] > 0.0) {
        voxels = milliseconds / cost_[i];
        // Growth is bounded by what the last measured frames traced, not by the last budget given:
        // frames that waited (no work of this kind) do not ratchet it up.
        if (lastTraced_[i] > 0) voxels = std::min(voxels, kMaxGrowth * lastTraced_[i]);
    }
    voxels = std::clamp(voxels, static_cast<double>(kMinVoxels), static_cast<double>(most));
    return static_cast<std::uint32_t>(std::max(std::floor(voxels), 1.0));
}

void GiPacer::traced(std::uint64_t frame, Work work, std::uint32_t voxels) {
    if (voxels == 0) return;
    traced_.push_back({frame, work, voxels});
    lastTraced_[index(work)] = voxels;
    while (traced_.size() > kMaxWaiting) traced_.pop_front();
}

void GiPacer::measured(std::uint64_t frame, double gpuMs) {
    // Frames older than this one will not be measured any more (timings arrive in frame order).
    while (!traced_.empty() && traced_.front().frame < frame) traced_.pop_front();
    if (traced_.empty() || traced_.front().frame != frame) return;
    const Traced t = traced_.front();
    traced_.pop_front();
    if (!(gpuMs > 0.0) || !std::isfinite(gpuMs)) return;
    const double cost = gpuMs / t.voxels;
    double& estimate = cost_[index(t.work)];
    estimate = estimate > 0.0 ? estimate + kSmoothing * (cost - estimate) : cost;
}

}  // namespace lit
