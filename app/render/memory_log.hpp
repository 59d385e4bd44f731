#pragma once
// What the soak watches (docs/reliability.md): resident memory, VMA's allocations, and the Vulkan
// objects that must not grow per frame. PPR_MEMORY_LOG=N makes capture, compare, bench and the viewer
// print one `ppr: memory ...` line every N frames (scripts/soak.sh reads them).
#include "vk/context.hpp"

#include <cstdint>
#include <string>

namespace ppr::app {

struct MemorySample {
    uint64_t frame = 0;
    uint64_t residentKib = 0;       // /proc/self/statm, after malloc_trim(0)
    uint64_t residentAnonKib = 0, residentFileKib = 0, residentShmemKib = 0;  // its parts (/proc/self/status)
    uint64_t heapKib = 0;           // malloc's bytes in use (mallinfo2): growth here is held memory, not fragmentation
    uint64_t vmaAllocations = 0;    // live VMA allocations
    uint64_t vmaBytes = 0;          // bytes they hold
    uint64_t vmaBlockBytes = 0;     // device memory VMA holds in blocks
    int64_t pipelines = 0, descriptorSetLayouts = 0, descriptorPools = 0;  // vk::liveObjects()
};

MemorySample sampleMemory(const vk::Context& ctx, uint64_t frame);
std::string formatMemorySample(const MemorySample& s);  // "ppr: memory frame=... rss_kib=... ..."

// Frames between samples from PPR_MEMORY_LOG (0 = off).
uint64_t memoryLogInterval();

// PPR_MEMORY_TEST_LEAK=N: leak N bytes every frame on purpose. Only the soak's self-test sets it
// (tests/gpu/CMakeLists.txt), to prove that scripts/soak.sh fails on a leak; 0 or unset = none.
uint64_t memoryTestLeakBytes();

// Prints a sample when logging is on and `frame` is a multiple of the interval (waits for the device
// to be idle first); leaks PPR_MEMORY_TEST_LEAK bytes first when that is set. Called every frame.
void logMemoryEvery(const vk::Context& ctx, uint64_t frame);

}  // namespace ppr::app
