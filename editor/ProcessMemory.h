#pragma once
// What the editor process holds in memory, for the script's `memory` command and the soak test
// (tools/soak.sh). Resident memory alone cannot tell a leak from allocator fragmentation: freed
// heap pages below a live block stay resident, so RSS climbs for the first minutes of a session
// and then levels off while the live heap stays flat. The allocator's own figures (glibc's
// mallinfo2) count the bytes really held, including llvmpipe's textures, which it mallocs.

#include <cstddef>
#include <optional>
#include <string>

namespace lit::editor {

struct ProcessMemory {
    std::size_t residentBytes = 0;                 // VmRSS (/proc/self/statm); 0 when unknown
    std::optional<std::size_t> heapInUseBytes;     // malloc'd and not freed, own mappings included
    std::optional<std::size_t> heapMappedBytes;    // ... of which in blocks with their own mapping
    std::optional<std::size_t> heapFreeBytes;      // freed but kept by the allocator

    static ProcessMemory query();
    // Hands the heap's free pages back to the system (glibc's malloc_trim; nothing elsewhere).
    // glibc returns freed memory by itself only from the top of the heap: pages freed below a
    // live block stay resident, and the editor's resident size climbed by 20-35 MB of them over
    // its first minutes (docs/RELIABILITY.md, "Soak"). The editor calls this every 5 s; it took a
    // median 2.5 ms (worst 20 ms, 23 calls, a 2-core machine at load 8) in the soak session.
    static void releaseFreeHeap();
    // "memory: heap in use 123456 KiB (12 KiB in own mappings), heap free 789 KiB, resident 234567 KiB";
    // the heap figures read "unknown" off glibc.
    std::string describe() const;
};

}  // namespace lit::editor
