#include "gi/VoxelRegions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lit {

VoxelBox voxelBoxOf(const Aabb& world, const VoxelPlacement& placement, int padding) {
    if (world.empty() || placement.resolution <= 0) return {};
    const glm::vec3 lo = glm::floor((world.min - placement.min) / placement.voxelSize);
    const glm::vec3 hi = glm::floor((world.max - placement.min) / placement.voxelSize) + 1.0f;
    const glm::vec3 limit(static_cast<float>(placement.resolution));
    const glm::vec3 pad(static_cast<float>(padding));
    VoxelBox box;
    box.min = glm::ivec3(glm::clamp(lo - pad, glm::vec3(0.0f), limit));
    box.max = glm::ivec3(glm::clamp(hi + pad, glm::vec3(0.0f), limit));
    return box;
}

std::optional<glm::ivec3> scrollShift(const VoxelPlacement& before, const VoxelPlacement& after) {
    if (before.resolution <= 0 || before.resolution != after.resolution || before.voxelSize != after.voxelSize)
        return std::nullopt;
    const glm::vec3 voxels = (after.min - before.min) / after.voxelSize;
    const glm::vec3 whole = glm::round(voxels);
    // The corners are sums of metres in float: a few ulps off a whole voxel at city coordinates.
    if (glm::any(glm::greaterThan(glm::abs(voxels - whole), glm::vec3(1e-2f)))) return std::nullopt;
    const glm::ivec3 shift(whole);
    if (glm::any(glm::greaterThanEqual(glm::abs(shift), glm::ivec3(before.resolution)))) return std::nullopt;
    return shift;
}

std::vector<VoxelBox> uncoveredSlabs(glm::ivec3 shift, int resolution) {
    std::vector<VoxelBox> slabs;
    VoxelBox rest{glm::ivec3(0), glm::ivec3(resolution)};  // what the slabs so far leave
    for (int axis = 0; axis < 3; ++axis) {
        const int s = shift[axis];
        if (s == 0) continue;
        VoxelBox slab = rest;
        // Moved towards +axis: the voxels past the old far face, now at the top of the range.
        if (s > 0) {
            slab.min[axis] = resolution - s;
            rest.max[axis] = resolution - s;
        } else {
            slab.max[axis] = -s;
            rest.min[axis] = -s;
        }
        if (!slab.empty()) slabs.push_back(slab);
    }
    return slabs;
}

namespace {
// Joins overlapping boxes until none overlap: a voxel in two boxes would be cleared and drawn twice.
void joinOverlapping(std::vector<VoxelBox>& boxes) {
    for (bool joined = true; joined;) {
        joined = false;
        for (std::size_t i = 0; i < boxes.size() && !joined; ++i)
            for (std::size_t j = i + 1; j < boxes.size() && !joined; ++j)
                if (boxes[i].overlaps(boxes[j])) {
                    boxes[i] = boxes[i].joined(boxes[j]);
                    boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
                    joined = true;
                }
    }
}
}  // namespace

std::pair<std::size_t, std::size_t> cheapestJoin(const std::vector<VoxelBox>& boxes) {
    std::pair<std::size_t, std::size_t> best{0, 1};
    std::int64_t bestGrowth = std::numeric_limits<std::int64_t>::max();
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            const std::int64_t growth = boxes[i].joined(boxes[j]).voxels() - boxes[i].voxels() - boxes[j].voxels();
            if (growth < bestGrowth) {
                bestGrowth = growth;
                best = {i, j};
            }
        }
    return best;
}

ListBoxShares::ListBoxShares(const std::vector<glm::ivec3>& list, const std::vector<VoxelBox>& boxes)
    : perBlock_((list.size() + kBlock - 1) / kBlock, 0u), entries_(static_cast<std::uint32_t>(list.size())) {
    for (std::size_t i = 0; i < list.size(); ++i) {
        const VoxelBox voxel{list[i], list[i] + 1};
        if (std::any_of(boxes.begin(), boxes.end(), [&](const VoxelBox& b) { return b.overlaps(voxel); })) {
            ++perBlock_[i / kBlock];
            ++inBoxes_;
        }
    }
}

std::uint32_t ListBoxShares::entriesFor(std::uint32_t first, double voxels) const {
    if (first >= entries_) return 1;
    double need = voxels;
    std::uint32_t at = first;
    while (at < entries_) {
        const std::uint32_t block = at / kBlock;
        const std::uint32_t blockEnd = std::min((block + 1) * kBlock, entries_);
        const std::uint32_t blockSize = std::min(kBlock, entries_ - block * kBlock);
        const double density = static_cast<double>(perBlock_[block]) / blockSize;
        const double here = density * (blockEnd - at);
        if (here >= need && density > 0.0) {
            at += static_cast<std::uint32_t>(std::ceil(need / density));
            break;
        }
        need -= here;
        at = blockEnd;
    }
    return std::max(std::min(at, entries_) - first, 1u);
}

double ListBoxShares::inRange(std::uint32_t first, std::uint32_t count) const {
    const std::uint32_t end = std::min(first + count, entries_);
    double sum = 0.0;
    for (std::uint32_t at = first; at < end;) {
        const std::uint32_t block = at / kBlock;
        const std::uint32_t blockEnd = std::min((block + 1) * kBlock, end);
        const std::uint32_t blockSize = std::min(kBlock, entries_ - block * kBlock);
        sum += static_cast<double>(perBlock_[block]) * (blockEnd - at) / blockSize;
        at = blockEnd;
    }
    return sum;
}

std::vector<VoxelBox> mergeVoxelBoxes(std::vector<VoxelBox> boxes, std::size_t maxBoxes) {
    std::erase_if(boxes, [](const VoxelBox& b) { return b.empty(); });
    joinOverlapping(boxes);
    while (boxes.size() > std::max<std::size_t>(maxBoxes, 1)) {
        const auto [bestI, bestJ] = cheapestJoin(boxes);
        boxes[bestI] = boxes[bestI].joined(boxes[bestJ]);
        boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(bestJ));
        joinOverlapping(boxes);  // the joined box may now overlap another
    }
    return boxes;
}

void VoxelChangeTracker::voxelizedAll(std::vector<ItemPose> items, const VoxelPlacement& placement) {
    items_ = std::move(items);
    placement_ = placement;
    valid_ = true;
}

std::optional<std::vector<VoxelBox>> VoxelChangeTracker::voxelizeChanged(const std::vector<ItemPose>& items,
                                                                         const VoxelPlacement& placement) {
    if (!valid_ || !(placement == placement_) || items.size() != items_.size()) return std::nullopt;
    std::vector<VoxelBox> boxes;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i] == items_[i]) continue;
        boxes.push_back(voxelBoxOf(items_[i].bounds, placement, kPadding));
        boxes.push_back(voxelBoxOf(items[i].bounds, placement, kPadding));
    }
    if (boxes.empty()) return std::nullopt;  // a re-voxelization asked for without a move
    boxes = mergeVoxelBoxes(std::move(boxes), kMaxBoxes);
    std::int64_t voxels = 0;
    for (const VoxelBox& box : boxes) voxels += box.voxels();
    const double n = placement.resolution;
    if (static_cast<double>(voxels) > kMaxShare * n * n * n) return std::nullopt;
    items_ = items;
    return boxes;
}

}  // namespace lit
