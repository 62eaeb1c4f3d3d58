// VoxelChangeTracker: which voxels a move changed, and when the whole volume is voxelized instead.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "gi/VoxelRegions.h"

namespace lit {
namespace {

// A 1 m cube at `at`, as an item pose.
ItemPose cubeAt(glm::vec3 at) {
    ItemPose pose;
    pose.world = glm::translate(glm::mat4(1.0f), at);
    pose.bounds = Aabb{at - glm::vec3(0.5f), at + glm::vec3(0.5f)};
    return pose;
}

// A 64³ volume of 0.25 m voxels with its corner at (−8, −8, −8).
const VoxelPlacement kPlacement{glm::vec3(-8.0f), 0.25f, 64};

TEST(VoxelRegions, BoxOfAWorldBoxIsPaddedAndClamped) {
    const VoxelBox box = voxelBoxOf(Aabb{glm::vec3(-0.5f), glm::vec3(0.5f)}, kPlacement, 2);
    // −0.5 m is voxel 30; 0.5 m is voxel 34, the last it touches (exclusive end 35), ±2.
    EXPECT_EQ(box.min, glm::ivec3(28));
    EXPECT_EQ(box.max, glm::ivec3(37));
    const VoxelBox edge = voxelBoxOf(Aabb{glm::vec3(-9.0f), glm::vec3(-7.0f)}, kPlacement, 2);
    EXPECT_EQ(edge.min, glm::ivec3(0));
    EXPECT_EQ(edge.max, glm::ivec3(7));
    EXPECT_TRUE(voxelBoxOf(Aabb{}, kPlacement, 2).empty());
}

TEST(VoxelRegions, MergingJoinsOverlapsAndKeepsAtMostTheLimit) {
    const VoxelBox a{glm::ivec3(0), glm::ivec3(4)}, b{glm::ivec3(2), glm::ivec3(6)}, far{glm::ivec3(40), glm::ivec3(44)};
    const std::vector<VoxelBox> joined = mergeVoxelBoxes({a, b, far}, 8);
    ASSERT_EQ(joined.size(), 2u);
    EXPECT_EQ(joined[0], (VoxelBox{glm::ivec3(0), glm::ivec3(6)}));
    EXPECT_EQ(joined[1], far);
    // Ten separate boxes along x, merged down to three: no two overlap, every voxel still covered.
    std::vector<VoxelBox> row;
    for (int i = 0; i < 10; ++i) row.push_back({glm::ivec3(6 * i, 0, 0), glm::ivec3(6 * i + 3, 3, 3)});
    const std::vector<VoxelBox> three = mergeVoxelBoxes(row, 3);
    ASSERT_EQ(three.size(), 3u);
    for (std::size_t i = 0; i < three.size(); ++i)
        for (std::size_t j = i + 1; j < three.size(); ++j) EXPECT_FALSE(three[i].overlaps(three[j]));
    for (const VoxelBox& box : row) {
        bool covered = false;
        for (const VoxelBox& m : three)
            covered = covered || (glm::all(glm::greaterThanEqual(box.min, m.min)) && glm::all(glm::lessThanEqual(box.max, m.max)));
        EXPECT_TRUE(covered);
    }
}

TEST(VoxelRegions, AMovedItemChangesItsOldAndNewBoxOnly) {
    VoxelChangeTracker tracker;
    const std::vector<ItemPose> before{cubeAt(glm::vec3(0.0f)), cubeAt(glm::vec3(4.0f, 0.0f, 0.0f))};
    EXPECT_FALSE(tracker.voxelizeChanged(before, kPlacement)) << "nothing voxelized yet";
    tracker.voxelizedAll(before, kPlacement);
    std::vector<ItemPose> after = before;
    after[1] = cubeAt(glm::vec3(4.0f, 0.5f, 0.0f));
    const auto boxes = tracker.voxelizeChanged(after, kPlacement);
    ASSERT_TRUE(boxes);
    ASSERT_EQ(boxes->size(), 1u) << "the old and new box overlap: one box";
    const VoxelBox expected = voxelBoxOf(before[1].bounds, kPlacement, VoxelChangeTracker::kPadding)
                                  .joined(voxelBoxOf(after[1].bounds, kPlacement, VoxelChangeTracker::kPadding));
    EXPECT_EQ((*boxes)[0], expected);
    EXPECT_FALSE((*boxes)[0].overlaps(voxelBoxOf(before[0].bounds, kPlacement, 0))) << "the still cube is not redone";
    // The poses are now the voxelized ones: the same poses again change nothing and ask for the
    // whole volume (a re-voxelization asked for without a move).
    EXPECT_FALSE(tracker.voxelizeChanged(after, kPlacement));
    // A rotation in place keeps the box but changes the voxels.
    std::vector<ItemPose> turned = after;
    turned[0].world = glm::rotate(turned[0].world, 0.3f, glm::vec3(0.0f, 1.0f, 0.0f));
    ASSERT_TRUE(tracker.voxelizeChanged(turned, kPlacement));
}

TEST(VoxelRegions, TheWholeVolumeWhenThePlacementOrTheItemsChangeOrTheBoxesAreLarge) {
    VoxelChangeTracker tracker;
    const std::vector<ItemPose> before{cubeAt(glm::vec3(0.0f))};
    tracker.voxelizedAll(before, kPlacement);
    const std::vector<ItemPose> moved{cubeAt(glm::vec3(1.0f))};
    VoxelPlacement shifted = kPlacement;
    shifted.min.x += 0.25f;
    EXPECT_FALSE(tracker.voxelizeChanged(moved, shifted));
    EXPECT_FALSE(tracker.voxelizeChanged({cubeAt(glm::vec3(1.0f)), cubeAt(glm::vec3(2.0f))}, kPlacement));
    // A 12 m item moved: its boxes cover more than a quarter of the volume.
    ItemPose big = cubeAt(glm::vec3(0.0f));
    big.bounds = Aabb{glm::vec3(-6.0f), glm::vec3(6.0f)};
    tracker.voxelizedAll({big}, kPlacement);
    ItemPose bigMoved = big;
    bigMoved.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0.0f, 0.0f));
    EXPECT_FALSE(tracker.voxelizeChanged({bigMoved}, kPlacement));
}

// A near level moved by whole voxels scrolls by that shift; by a fraction of one, to another size
// or past its side it does not.
TEST(VoxelRegions, ScrollShiftIsWholeVoxelsWithinTheSide) {
    const VoxelPlacement before{glm::vec3(250.0f, -0.125f, 255.875f), 0.5f, 128};
    VoxelPlacement after = before;
    after.min += glm::vec3(8.0f, 0.0f, -16.0f);
    const std::optional<glm::ivec3> shift = scrollShift(before, after);
    ASSERT_TRUE(shift);
    EXPECT_EQ(*shift, glm::ivec3(16, 0, -32));
    EXPECT_EQ(scrollShift(before, before), glm::ivec3(0));
    VoxelPlacement fraction = before;
    fraction.min.x += 0.25f;
    EXPECT_FALSE(scrollShift(before, fraction));
    VoxelPlacement far = before;
    far.min.z += 64.0f;  // 128 voxels: nothing kept
    EXPECT_FALSE(scrollShift(before, far));
    VoxelPlacement coarser = after;
    coarser.voxelSize = 1.0f;
    EXPECT_FALSE(scrollShift(before, coarser));
}

// The slabs a scroll uncovers are disjoint, cover exactly the voxels whose old coordinates (v +
// shift) lie outside the volume, and nothing else.
TEST(VoxelRegions, UncoveredSlabsAreExactlyTheVoxelsNotKept) {
    constexpr int n = 16;
    for (const glm::ivec3 shift :
         {glm::ivec3(3, 0, 0), glm::ivec3(0, -5, 0), glm::ivec3(2, -1, 7), glm::ivec3(-15, 15, -1)}) {
        const std::vector<VoxelBox> slabs = uncoveredSlabs(shift, n);
        for (std::size_t i = 0; i < slabs.size(); ++i)
            for (std::size_t j = i + 1; j < slabs.size(); ++j) EXPECT_FALSE(slabs[i].overlaps(slabs[j]));
        std::int64_t covered = 0;
        for (const VoxelBox& slab : slabs) covered += slab.voxels();
        std::int64_t uncovered = 0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const glm::ivec3 v(x, y, z), old = v + shift;
                    const bool kept = glm::all(glm::greaterThanEqual(old, glm::ivec3(0))) &&
                                      glm::all(glm::lessThan(old, glm::ivec3(n)));
                    const bool inSlab = std::any_of(slabs.begin(), slabs.end(), [&](const VoxelBox& b) {
                        return b.overlaps(VoxelBox{v, v + 1});
                    });
                    EXPECT_NE(kept, inSlab) << "voxel " << x << " " << y << " " << z;
                    uncovered += kept ? 0 : 1;
                }
        EXPECT_EQ(covered, uncovered);
    }
}

// A list whose box entries cluster: ranges sized by ListBoxShares hold the voxels asked, where
// ranges sized by the boxes' average share of the list would hold from none to all of a block.
TEST(VoxelRegions, ListBoxSharesSizeRangesByTheEntriesInTheBoxes) {
    const std::vector<VoxelBox> boxes{{glm::ivec3(0), glm::ivec3(4)}};
    std::vector<glm::ivec3> list;
    const auto add = [&](int count, bool inside) {
        for (int i = 0; i < count; ++i) list.push_back(inside ? glm::ivec3(i % 4) : glm::ivec3(10 + i % 4));
    };
    // Block 0 none in the boxes, block 1 all, block 2 a quarter (every fourth), block 3 half a block, none.
    add(1024, false);
    add(1024, true);
    for (int i = 0; i < 1024; ++i) add(1, i % 4 == 0);
    add(512, false);
    const ListBoxShares shares(list, boxes);
    EXPECT_EQ(shares.entries(), 3584u);
    EXPECT_EQ(shares.inBoxes(), 1024u + 256u);
    EXPECT_DOUBLE_EQ(shares.inRange(0, 3584), 1280.0);
    EXPECT_DOUBLE_EQ(shares.inRange(0, 1024), 0.0);
    EXPECT_DOUBLE_EQ(shares.inRange(1024, 512), 512.0);
    EXPECT_DOUBLE_EQ(shares.inRange(2048, 512), 128.0);
    EXPECT_DOUBLE_EQ(shares.inRange(3072, 512), 0.0);
    // 512 voxels from the start: past block 0's 1024 entries, half of block 1.
    EXPECT_EQ(shares.entriesFor(0, 512.0), 1536u);
    // 1024 + 64 from the start: block 1 whole, then a quarter-dense block: 256 entries more.
    EXPECT_EQ(shares.entriesFor(0, 1088.0), 2048u + 256u);
    // More than the rest holds: the rest of the list; and never less than one entry.
    EXPECT_EQ(shares.entriesFor(3000, 100.0), 584u);
    EXPECT_EQ(shares.entriesFor(1024, 0.0), 1u);
    // Every range it sizes holds what it was asked (within one entry's worth).
    for (std::uint32_t first = 0; first < 2500; first += 97) {
        const double asked = 100.0;
        const std::uint32_t count = shares.entriesFor(first, asked);
        if (first + count < shares.entries()) {
            EXPECT_GE(shares.inRange(first, count), asked - 1e-9) << first;
            EXPECT_LT(shares.inRange(first, count), asked + 1.0) << first;
        }
    }
}

}  // namespace
}  // namespace lit
