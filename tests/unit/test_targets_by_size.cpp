// TargetsBySize keeps a pass's targets for the size in use and one other size, the larger one when
// a third comes (the editor's interactive render scale switches between the full size and smaller
// ones; see passes/TargetsBySize.h).

#include "passes/TargetsBySize.h"

#include <gtest/gtest.h>

#include <memory>

namespace lit {
namespace {

// Stands for a pass's GL objects: move-only, and each allocation gets its own serial number.
struct FakeTargets {
    std::unique_ptr<int> serial;
    int width = 0, height = 0;
};

using Selected = TargetsBySize<FakeTargets>::Selected;

int allocate(TargetsBySize<FakeTargets>& targets, int& nextSerial) {
    targets.current().serial = std::make_unique<int>(nextSerial);
    return nextSerial++;
}

TEST(TargetsBySize, SwitchingBetweenTwoSizesReusesBothSets) {
    TargetsBySize<FakeTargets> targets;
    int nextSerial = 1;
    ASSERT_EQ(targets.select(1280, 720), Selected::Empty);
    const int full = allocate(targets, nextSerial);
    EXPECT_EQ(targets.select(1280, 720), Selected::Unchanged);
    EXPECT_EQ(*targets->serial, full);

    ASSERT_EQ(targets.select(256, 144), Selected::Empty);  // the interactive scale
    const int small = allocate(targets, nextSerial);
    EXPECT_EQ(targets->width, 256);
    EXPECT_EQ(targets->height, 144);

    for (int round = 0; round < 3; ++round) {  // still, moving, still, ...: no new allocation
        EXPECT_EQ(targets.select(1280, 720), Selected::Reused);
        EXPECT_EQ(*targets->serial, full);
        EXPECT_EQ(targets->width, 1280);
        EXPECT_EQ(targets.select(256, 144), Selected::Reused);
        EXPECT_EQ(*targets->serial, small);
    }
}

// A third size replaces the smaller set: the editor's interactive scale uses several small sizes in
// one motion, and the still (full) size must survive them.
TEST(TargetsBySize, AThirdSizeReplacesTheSmallerSetAndKeepsTheLarger) {
    TargetsBySize<FakeTargets> targets;
    int nextSerial = 1;
    ASSERT_EQ(targets.select(1280, 720), Selected::Empty);
    const int full = allocate(targets, nextSerial);
    ASSERT_EQ(targets.select(256, 144), Selected::Empty);  // the motion starts
    allocate(targets, nextSerial);
    ASSERT_EQ(targets.select(128, 72), Selected::Empty);   // its scale drops: 256×144 is dropped
    EXPECT_EQ(targets->serial, nullptr) << "a new size starts from an empty set";
    EXPECT_EQ(targets->width, 128);
    allocate(targets, nextSerial);
    ASSERT_EQ(targets.select(192, 108), Selected::Empty);  // and rises: 128×72 is dropped
    allocate(targets, nextSerial);
    EXPECT_EQ(targets.select(1280, 720), Selected::Reused) << "the still size survives the motion's sizes";
    EXPECT_EQ(*targets->serial, full);
    EXPECT_EQ(targets.select(128, 72), Selected::Empty) << "dropped by 192×108, not reused";
    // A larger third size (a bigger window) replaces the smaller set too: the old full size stays.
    allocate(targets, nextSerial);
    ASSERT_EQ(targets.select(1920, 1080), Selected::Empty);
    allocate(targets, nextSerial);
    EXPECT_EQ(targets.select(1280, 720), Selected::Reused);
    EXPECT_EQ(*targets->serial, full);
}

}  // namespace
}  // namespace lit
