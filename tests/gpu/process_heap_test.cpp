// On a CPU device the context keeps the memory the process frees (util/process_heap.hpp): the driver
// bins each frame's draws into blocks it frees again, which glibc would hand back to the kernel and the
// next frame fault in anew. On a GPU nothing changes.
#include "gpu_test_util.hpp"
#include "util/process_heap.hpp"

#include <malloc.h>

#include <vector>

namespace ppr::test {
namespace {

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
constexpr bool kGlibcHeap = true;
#else
constexpr bool kGlibcHeap = false;
#endif

TEST(ProcessHeap, ACpuDeviceKeepsFreedMemoryInTheProcess) {
    vk::ContextOptions o;
    const auto ctx = vk::Context::create(o);
    const bool cpu = ctx->info().type == "cpu";
    EXPECT_EQ(ctx->info().heapKept, cpu && kGlibcHeap && !util::heapTunedByUser(std::getenv("GLIBC_TUNABLES"))) << ctx->info().name;
    if (!ctx->info().heapKept) GTEST_SKIP() << ctx->info().name << ": the heap is glibc's own";
    // A frame's worth of binning blocks, freed: the top of the heap stays (glibc alone trims it; the
    // unit test ProcessHeap.GlibcAloneGivesAFreedHeapTopBack is the control).
    std::vector<char*> blocks;
    for (int i = 0; i < 256; ++i) {
        blocks.push_back(static_cast<char*>(std::malloc(64 << 10)));
        for (size_t b = 0; b < (64 << 10); b += 4096) blocks.back()[b] = 1;
    }
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
    EXPECT_GE(mallinfo2().keepcost, size_t(16) << 20);
}

}  // namespace
}  // namespace ppr::test
