// On a CPU device the context keeps the memory the process frees (util/process_heap.hpp): the driver
// bins each frame's draws into blocks it frees again, which glibc would hand back to the kernel and the
// next frame fault in anew. On a GPU, or with the user's own GLIBC_TUNABLES, the heap is glibc's own.
// That the settings keep freed memory is unit.util.ProcessHeap.KeptMemoryStaysInTheHeap's (with its
// control).
#include "gpu_test_util.hpp"
#include "util/process_heap.hpp"

namespace ppr::test {
namespace {

TEST(ProcessHeap, ACpuDeviceKeepsFreedMemoryInTheProcess) {
    vk::ContextOptions o;
    const auto ctx = vk::Context::create(o);
    const bool cpu = ctx->info().type == "cpu";
    EXPECT_EQ(ctx->info().heapKept, cpu && util::kHeapKeepable && !util::heapTunedByUser(std::getenv("GLIBC_TUNABLES"))) << ctx->info().name;
}

}  // namespace
}  // namespace ppr::test
