#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "ProcessMemory.h"

namespace {

using lit::editor::ProcessMemory;

// The figures follow what the process allocates: 64 MiB held raise the heap in use and the
// resident size by about that much, and freeing them brings the heap in use back.
TEST(ProcessMemory, FollowsAnAllocationAndItsRelease) {
    const ProcessMemory before = ProcessMemory::query();
    ASSERT_GT(before.residentBytes, 0u);
    if (!before.heapInUseBytes) GTEST_SKIP() << "no allocator figures here (not glibc)";
    constexpr std::size_t kBytes = 64u << 20;
    std::vector<char> block(kBytes, 'x');  // touched, so resident
    const ProcessMemory during = ProcessMemory::query();
    EXPECT_GE(*during.heapInUseBytes, *before.heapInUseBytes + kBytes);
    EXPECT_GE(during.residentBytes, before.residentBytes + kBytes * 9 / 10);
    block = {};
    block.shrink_to_fit();
    const ProcessMemory after = ProcessMemory::query();
    EXPECT_LT(*after.heapInUseBytes, *during.heapInUseBytes - kBytes * 9 / 10);
}

TEST(ProcessMemory, DescribeNamesEveryFigure) {
    ProcessMemory memory;
    memory.residentBytes = 3u << 20;
    memory.heapInUseBytes = 2u << 20;
    memory.heapMappedBytes = 1u << 20;
    memory.heapFreeBytes = 512u << 10;
    EXPECT_EQ(memory.describe(),
              "memory: heap in use 2048 KiB (1024 KiB in own mappings), heap free 512 KiB, resident 3072 KiB");
    EXPECT_EQ(ProcessMemory{}.describe(),
              "memory: heap in use unknown (unknown in own mappings), heap free unknown, resident 0 KiB");
}

}  // namespace
