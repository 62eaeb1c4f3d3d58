#pragma once
// Which voxels a geometry edit changed (no GL here, so it is tested without a context). A node
// that moves (a gizmo drag, a node animation) changes only the voxels its items covered before and
// cover now: VoxelGi voxelizes those boxes again instead of the whole volume, and the voxel rays
// that do not cross them keep their recorded hits (RayHitCache). docs/GI.md, "Incremental
// voxelization".

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Aabb.h"

namespace lit {

// Voxels [min, max) of a volume, in voxel coordinates.
struct VoxelBox {
    glm::ivec3 min{0}, max{0};
    bool empty() const { return min.x >= max.x || min.y >= max.y || min.z >= max.z; }
    std::int64_t voxels() const {
        if (empty()) return 0;
        const glm::ivec3 s = max - min;
        return std::int64_t{s.x} * s.y * s.z;
    }
    bool overlaps(const VoxelBox& o) const {
        return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y && min.z < o.max.z &&
               o.min.z < max.z;
    }
    // The smallest box holding both.
    VoxelBox joined(const VoxelBox& o) const { return {glm::min(min, o.min), glm::max(max, o.max)}; }
    bool operator==(const VoxelBox&) const = default;
};

// Where a volume lies: its corner (m), voxel size (m) and voxels per side.
struct VoxelPlacement {
    glm::vec3 min{0.0f};
    float voxelSize = 1.0f;
    int resolution = 0;
    bool operator==(const VoxelPlacement&) const = default;
};

// The voxels a world box touches, with `padding` voxels around it (the voxelization's conservative
// rasterization writes up to a voxel beyond a triangle), clamped to the volume.
VoxelBox voxelBoxOf(const Aabb& world, const VoxelPlacement& placement, int padding);

// A near level that moved from `before` to `after` (same voxel size and resolution) by whole
// voxels, fewer than the resolution along each axis: the shift in voxels (a voxel at world voxel w
// moves from w − before's corner to w − after's, so its coordinates drop by the shift). nullopt
// when the volume cannot scroll (another size, a fraction of a voxel, a jump past its side).
std::optional<glm::ivec3> scrollShift(const VoxelPlacement& before, const VoxelPlacement& after);

// The voxels a scroll by `shift` uncovers in an N³ volume (N = `resolution`): a slab per axis that
// moved, as disjoint boxes (a voxel in two boxes would be cleared and drawn twice).
std::vector<VoxelBox> uncoveredSlabs(glm::ivec3 shift, int resolution);

// The two boxes whose joined box adds the fewest voxels (needs at least two).
std::pair<std::size_t, std::size_t> cheapestJoin(const std::vector<VoxelBox>& boxes);

// Merges overlapping boxes, then the pair whose joined box adds the fewest voxels, until at most
// `maxBoxes` are left.
std::vector<VoxelBox> mergeVoxelBoxes(std::vector<VoxelBox> boxes, std::size_t maxBoxes);

// Where the entries of a voxel list that lie in some boxes fall along the list, counted per block
// of kBlock entries. A pass limited to the boxes (VoxelVolume::onlyBoxes: a near level's update of
// the slabs a scroll uncovered) walks the list in ranges; its cost follows the entries in the
// boxes, which cluster (the list holds voxels in the order they were voxelized), so a range sized
// by the boxes' average share of the list cost up to 2.5× the frame's budget.
class ListBoxShares {
public:
    static constexpr std::uint32_t kBlock = 1024;
    ListBoxShares() = default;
    ListBoxShares(const std::vector<glm::ivec3>& list, const std::vector<VoxelBox>& boxes);

    std::uint32_t entries() const { return entries_; }
    std::uint32_t inBoxes() const { return inBoxes_; }
    // Entries from `first` that hold about `voxels` of the boxes' entries (each block's taken as
    // spread evenly over it), at least 1, at most the rest of the list.
    std::uint32_t entriesFor(std::uint32_t first, double voxels) const;
    // The boxes' entries among entries [first, first + count), as entriesFor reckons them.
    double inRange(std::uint32_t first, std::uint32_t count) const;

private:
    std::vector<std::uint32_t> perBlock_;
    std::uint32_t entries_ = 0, inBoxes_ = 0;
};

// One draw item as the last voxelization saw it: its node's world transform and world box.
struct ItemPose {
    glm::mat4 world{1.0f};
    Aabb bounds;
    bool operator==(const ItemPose& o) const { return world == o.world; }
};

class VoxelChangeTracker {
public:
    static constexpr std::size_t kMaxBoxes = 8;  // = LIT_CHANGED_BOXES
    // A partial voxelization pays only while its boxes are a small share of the volume; beyond
    // this share the whole volume is voxelized.
    static constexpr double kMaxShare = 0.25;
    // Voxels padded around each item's box (voxelize.geom.glsl's enlarged triangles reach one
    // voxel beyond the triangle; one more for rounding).
    static constexpr int kPadding = 2;

    // The whole volume was voxelized from `items` placed at `placement`.
    void voxelizedAll(std::vector<ItemPose> items, const VoxelPlacement& placement);
    // The boxes to voxelize again for the items as they are now: each moved item's box before and
    // after, merged; nullopt when the whole volume must be voxelized instead (nothing voxelized yet,
    // other items or another placement, no item moved: the edit is not a move, or the boxes cover
    // more than kMaxShare of the volume). On success the poses are taken as voxelized.
    std::optional<std::vector<VoxelBox>> voxelizeChanged(const std::vector<ItemPose>& items,
                                                         const VoxelPlacement& placement);

private:
    std::vector<ItemPose> items_;
    VoxelPlacement placement_;
    bool valid_ = false;
};

}  // namespace lit
