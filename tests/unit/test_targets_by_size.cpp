// TargetsBySize keeps a pass's targets for the size in use and the size before it (the editor's
// interactive render scale switches between two sizes; see passes/TargetsBySize.h).

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

TEST(TargetsBySize, AThirdSizeReplacesTheOlderSetAndKeepsTheNewer) {
    TargetsBySize<FakeTargets> targets;
    int nextSerial = 1;
    ASSERT_EQ(targets.select(100, 100), Selected::Empty);
    allocate(targets, nextSerial);
    ASSERT_EQ(targets.select(50, 50), Selected::Empty);
    const int fifty = allocate(targets, nextSerial);
    ASSERT_EQ(targets.select(25, 25), Selected::Empty);  // the 100×100 set is dropped
    EXPECT_EQ(targets->serial, nullptr) << "a new size starts from an empty set";
    EXPECT_EQ(targets->width, 25);
    allocate(targets, nextSerial);
    EXPECT_EQ(targets.select(50, 50), Selected::Reused);
    EXPECT_EQ(*targets->serial, fifty);
    EXPECT_EQ(targets.select(100, 100), Selected::Empty);
}

}  // namespace
}  // namespace lit
