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

// Pages freed below a live block stay resident until releaseFreeHeap hands them back: 64 MiB of
// small blocks, all freed but every 64th, must leave well under half of them resident after it.
TEST(ProcessMemory, ReleaseFreeHeapReturnsPagesFreedBelowLiveBlocks) {
    if (!ProcessMemory::query().heapFreeBytes) GTEST_SKIP() << "no allocator figures here (not glibc, or AddressSanitizer)";
    constexpr std::size_t kBlock = 4096, kCount = (64u << 20) / kBlock;
    std::vector<std::unique_ptr<char[]>> blocks(kCount);
    for (auto& block : blocks) {
        block = std::make_unique<char[]>(kBlock);
        block[0] = 1;  // touched, so resident
    }
    for (std::size_t i = 0; i < kCount; ++i)
        if (i % 64 != 63) blocks[i].reset();  // the last block of every 64 stays: the heap cannot shrink from the top
    const ProcessMemory before = ProcessMemory::query();
    ProcessMemory::releaseFreeHeap();
    const ProcessMemory after = ProcessMemory::query();
    EXPECT_LT(after.residentBytes + (32u << 20), before.residentBytes)
        << "resident " << before.residentBytes / 1024 << " KiB -> " << after.residentBytes / 1024 << " KiB";
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
