#include "ProcessMemory.h"

#include <fstream>

#include <unistd.h>
#if defined(__SANITIZE_ADDRESS__)
// From the sanitizer runtime (<sanitizer/allocator_interface.h>, which Debian ships with clang but
// not with GCC).
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lit::editor {

namespace {
std::string kib(std::optional<std::size_t> bytes) {
    return bytes ? std::to_string(*bytes / 1024) + " KiB" : std::string("unknown");
}
}  // namespace

ProcessMemory ProcessMemory::query() {
    ProcessMemory memory;
    // statm: total and resident sizes in pages.
    std::ifstream statm("/proc/self/statm");
    std::size_t totalPages = 0, residentPages = 0;
    if (statm >> totalPages >> residentPages)
        memory.residentBytes = residentPages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
#if defined(__SANITIZE_ADDRESS__)
    // malloc is ASan's own: glibc's figures would describe an arena nobody uses. Its free memory
    // (quarantine, caches) has no figure that maps onto resident pages, so it stays unknown.
    memory.heapInUseBytes = __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
    const struct mallinfo2 info = mallinfo2();
    memory.heapInUseBytes = info.uordblks + info.hblkhd;  // arena blocks in use + mmapped blocks
    memory.heapMappedBytes = info.hblkhd;
    memory.heapFreeBytes = info.fordblks;
#endif
    return memory;
}

void ProcessMemory::releaseFreeHeap() {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
    malloc_trim(0);
#endif
}

std::string ProcessMemory::describe() const {
    return "memory: heap in use " + kib(heapInUseBytes) + " (" + kib(heapMappedBytes) + " in own mappings), heap free " +
           kib(heapFreeBytes) + ", resident " + std::to_string(residentBytes / 1024) + " KiB";
}

}  // namespace lit::editor
