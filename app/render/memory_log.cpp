#include "render/memory_log.hpp"

#include "vk/live_objects.hpp"

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace ppr::app {

MemorySample sampleMemory(const vk::Context& ctx, uint64_t frame) {
    MemorySample s;
    s.frame = frame;
    // Free pages glibc keeps in its arenas (lavapipe's device memory is host memory: every transient
    // resized or re-created leaves some) go back to the system first, so resident memory counts what
    // is in use rather than the allocator's history.
    malloc_trim(0);
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        unsigned long long size = 0, resident = 0;
        if (std::fscanf(f, "%llu %llu", &size, &resident) == 2) s.residentKib = resident * uint64_t(sysconf(_SC_PAGESIZE)) / 1024;
        std::fclose(f);
    }
    // Resident memory by kind: anonymous (heaps, driver allocations), file-backed (code, JIT caches on
    // disk) and shared memory (the X server's presentation buffers), to tell a leak from a mapping.
    if (FILE* f = std::fopen("/proc/self/status", "r")) {
        char line[128];
        unsigned long long kib = 0;
        while (std::fgets(line, sizeof line, f)) {
            if (std::sscanf(line, "RssAnon: %llu", &kib) == 1) s.residentAnonKib = kib;
            else if (std::sscanf(line, "RssFile: %llu", &kib) == 1) s.residentFileKib = kib;
            else if (std::sscanf(line, "RssShmem: %llu", &kib) == 1) s.residentShmemKib = kib;
        }
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
    char line[320];
    std::snprintf(line, sizeof line,
                  "ppr: memory frame=%llu rss_kib=%llu rss_anon_kib=%llu rss_file_kib=%llu rss_shmem_kib=%llu heap_kib=%llu vma_allocations=%llu vma_bytes=%llu vma_block_bytes=%llu pipelines=%lld "
                  "descriptor_set_layouts=%lld descriptor_pools=%lld",
                  (unsigned long long)s.frame, (unsigned long long)s.residentKib, (unsigned long long)s.residentAnonKib,
                  (unsigned long long)s.residentFileKib, (unsigned long long)s.residentShmemKib, (unsigned long long)s.heapKib,
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

uint64_t memoryTestLeakBytes() {
    static const uint64_t bytes = [] {
        const char* v = std::getenv("PPR_MEMORY_TEST_LEAK");
        return v ? std::strtoull(v, nullptr, 10) : 0ull;
    }();
    return bytes;
}

namespace {
// The test leak's blocks, chained through their first bytes: never freed, but reachable, so that
// LeakSanitizer (which reports unreachable blocks at exit) leaves the soak's self-test to the soak's
// own figures in the sanitizer build. volatile keeps the compiler from dropping the allocations.
char* volatile testLeakChain = nullptr;
}

void logMemoryEvery(const vk::Context& ctx, uint64_t frame) {
    if (const uint64_t leak = memoryTestLeakBytes()) {
        // Never freed: the soak's self-test proves with it that its statistic sees a leak this size.
        // Written to, so that its pages are resident as well as counted by malloc.
        const size_t bytes = std::max<size_t>(leak, sizeof(char*));  // glibc's smallest chunk holds 24 bytes either way
        if (char* block = static_cast<char*>(std::malloc(bytes))) {
            std::memset(block, 1, bytes);
            char* previous = testLeakChain;
            std::memcpy(block, &previous, sizeof previous);
            testLeakChain = block;
        }
    }
    const uint64_t every = memoryLogInterval();
    if (every == 0 || frame % every != 0) return;
    // Sampled with the device idle: a frame still in flight holds command memory in the driver (up to
    // 1 MiB on lavapipe), which would show as jitter of that size depending on timing.
    vkDeviceWaitIdle(ctx.device());
    std::printf("%s\n", formatMemorySample(sampleMemory(ctx, frame)).c_str());
    std::fflush(stdout);
}

}  // namespace ppr::app
