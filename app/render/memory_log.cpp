#include "render/memory_log.hpp"

#include "vk/live_objects.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace ppr::app {

MemorySample sampleMemory(const vk::Context& ctx, uint64_t frame) {
    MemorySample s;
    s.frame = frame;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        unsigned long long size = 0, resident = 0;
        if (std::fscanf(f, "%llu %llu", &size, &resident) == 2) s.residentKib = resident * uint64_t(sysconf(_SC_PAGESIZE)) / 1024;
        std::fclose(f);
    }
    s.heapKib = mallinfo2().uordblks / 1024;
    VmaTotalStatistics stats{};
    vmaCalculateStatistics(ctx.allocator(), &stats);
    s.vmaAllocations = stats.total.statistics.allocationCount;
    s.vmaBytes = stats.total.statistics.allocationBytes;
    s.vmaBlockBytes = stats.total.statistics.blockBytes;
    const vk::LiveObjects& live = vk::liveObjects();
    s.pipelines = live.pipelines;
    s.descriptorSetLayouts = live.descriptorSetLayouts;
    s.descriptorPools = live.descriptorPools;
    return s;
}

std::string formatMemorySample(const MemorySample& s) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "ppr: memory frame=%llu rss_kib=%llu heap_kib=%llu vma_allocations=%llu vma_bytes=%llu vma_block_bytes=%llu pipelines=%lld "
                  "descriptor_set_layouts=%lld descriptor_pools=%lld",
                  (unsigned long long)s.frame, (unsigned long long)s.residentKib, (unsigned long long)s.heapKib,
                  (unsigned long long)s.vmaAllocations,
                  (unsigned long long)s.vmaBytes, (unsigned long long)s.vmaBlockBytes, (long long)s.pipelines,
                  (long long)s.descriptorSetLayouts, (long long)s.descriptorPools);
    return line;
}

uint64_t memoryLogInterval() {
    static const uint64_t interval = [] {
        const char* v = std::getenv("PPR_MEMORY_LOG");
        return v ? std::strtoull(v, nullptr, 10) : 0ull;
    }();
    return interval;
}

void logMemoryEvery(const vk::Context& ctx, uint64_t frame) {
    const uint64_t every = memoryLogInterval();
    if (every == 0 || frame % every != 0) return;
    // Sampled with the device idle: a frame still in flight holds command memory in the driver (up to
    // 1 MiB on lavapipe), which would show as jitter of that size depending on timing.
    vkDeviceWaitIdle(ctx.device());
    std::printf("%s\n", formatMemorySample(sampleMemory(ctx, frame)).c_str());
    std::fflush(stdout);
}

}  // namespace ppr::app
