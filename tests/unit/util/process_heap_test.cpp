// util/process_heap: the user's GLIBC_TUNABLES stand, and keepFreedHeapMemory really keeps freed memory
// in the heap. Each test runs in a process of its own under ctest (gtest_discover_tests), so the first
// sees glibc's own behaviour.
#include "util/process_heap.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ppr::util {
namespace {

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
constexpr bool kGlibcHeap = true;
#else
constexpr bool kGlibcHeap = false;
#endif

// Allocates 16 MiB in 64 KiB blocks (the size of lavapipe's binning blocks), touches and frees them
// newest first, and returns how much free memory the main heap then keeps at its top.
size_t topKeptAfterAFrame() {
    std::vector<char*> blocks;
    for (int i = 0; i < 256; ++i) {
        blocks.push_back(static_cast<char*>(std::malloc(64 << 10)));
        for (size_t b = 0; b < (64 << 10); b += 4096) blocks.back()[b] = 1;
    }
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
#if defined(__GLIBC__)
    return mallinfo2().keepcost;
#else
    return 0;
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

// The control: left to itself, glibc gives a freed 16 MiB heap top back to the kernel.
TEST(ProcessHeap, GlibcAloneGivesAFreedHeapTopBack) {
    if (!kGlibcHeap) GTEST_SKIP() << "not glibc's allocator";
    EXPECT_LT(topKeptAfterAFrame(), size_t(1) << 20);
}

TEST(ProcessHeap, KeptMemoryStaysInTheHeap) {
    if (!kGlibcHeap) {
        EXPECT_FALSE(keepFreedHeapMemory());
        GTEST_SKIP() << "not glibc's allocator";
    }
    ASSERT_TRUE(keepFreedHeapMemory());
    EXPECT_GE(topKeptAfterAFrame(), size_t(16) << 20);
}

}  // namespace
}  // namespace ppr::util
