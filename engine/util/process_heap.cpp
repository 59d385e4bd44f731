#include "util/process_heap.hpp"

#include <string_view>

#if PPR_HEAP_KEEPABLE
#include <malloc.h>
#endif

namespace ppr::util {

bool heapTunedByUser(const char* glibcTunables) {
    if (!glibcTunables) return false;
    const std::string_view t(glibcTunables);
    for (std::string_view key : {"glibc.malloc.trim_threshold", "glibc.malloc.mmap_threshold", "glibc.malloc.top_pad"})
        if (t.find(key) != std::string_view::npos) return true;
    return false;
}

bool keepFreedHeapMemory() {
#if PPR_HEAP_KEEPABLE
    // mallopt returns 1 on success; every one must hold for the heap to stay resident.
    return mallopt(M_TRIM_THRESHOLD, static_cast<int>(kHeapTrimThreshold)) == 1 &&
           mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHeapMmapThreshold)) == 1 && mallopt(M_TOP_PAD, static_cast<int>(kHeapTopPad)) == 1;
#else
    return false;
#endif
}

}  // namespace ppr::util
