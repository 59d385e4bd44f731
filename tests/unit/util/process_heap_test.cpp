// util/process_heap: the user's GLIBC_TUNABLES stand, and keepFreedHeapMemory really keeps freed memory
// in the heap. Each test runs in a process of its own under ctest (gtest_discover_tests), so the first
// sees glibc's own behaviour.
#include "util/process_heap.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#if PPR_HEAP_KEEPABLE
#include <malloc.h>
#endif

namespace ppr::util {
namespace {

// The header decides before any C library header may have been included; here <cstdlib> has been.
TEST(ProcessHeap, KeepableWhereverGlibcAllocates) {
#if defined(__GLIBC__) && !defined(PPR_SANITIZER_ALLOCATOR)
    EXPECT_TRUE(kHeapKeepable);
#else
    EXPECT_FALSE(kHeapKeepable);
#endif
}

TEST(ProcessHeap, TheUsersOwnTunablesStand) {
    EXPECT_FALSE(heapTunedByUser(nullptr));
    EXPECT_FALSE(heapTunedByUser(""));
    EXPECT_FALSE(heapTunedByUser("glibc.rtld.optional_static_tls=512"));
    EXPECT_TRUE(heapTunedByUser("glibc.malloc.trim_threshold=0"));
    EXPECT_TRUE(heapTunedByUser("glibc.rtld.nns=2:glibc.malloc.top_pad=0"));
    EXPECT_TRUE(heapTunedByUser("glibc.malloc.mmap_threshold=4096"));
}

#if PPR_HEAP_KEEPABLE
// Allocates 16 MiB in 64 KiB blocks (below glibc's 128 KiB mmap threshold, so from the heap, as a
// driver's small allocations are), touches and frees them newest first, and returns how much free
// memory the main heap then keeps at its top.
size_t topKeptAfterAFrame() {
    std::vector<char*> blocks;
    for (int i = 0; i < 256; ++i) {
        blocks.push_back(static_cast<char*>(std::malloc(64 << 10)));
        for (size_t b = 0; b < (64 << 10); b += 4096) blocks.back()[b] = 1;
    }
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
    return mallinfo2().keepcost;
}

// The control: left to itself, glibc gives a freed 16 MiB heap top back to the kernel.
TEST(ProcessHeap, GlibcAloneGivesAFreedHeapTopBack) { EXPECT_LT(topKeptAfterAFrame(), size_t(1) << 20); }

TEST(ProcessHeap, KeptMemoryStaysInTheHeap) {
    ASSERT_TRUE(keepFreedHeapMemory());
    EXPECT_GE(topKeptAfterAFrame(), size_t(16) << 20);
}
#else
// A sanitizer's allocator (the sanitizer build) ignores the settings: they are not claimed to hold.
TEST(ProcessHeap, ASanitizersAllocatorIsLeftAsItIs) { EXPECT_FALSE(keepFreedHeapMemory()); }
#endif

}  // namespace
}  // namespace ppr::util
