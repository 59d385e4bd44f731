#pragma once
// A CPU Vulkan device (lavapipe) runs inside this process, and its rasterizer bins every frame's draws
// into memory it allocates and frees again. glibc hands a freed heap top back to the kernel (trimming
// above 128 KiB, and large blocks are their own mappings), so the next frame takes a page fault for
// every page of it again: on lavapipe a third of the frame's time at 640x360 (docs/performance.md,
// "The heap kept"). keepFreedHeapMemory() keeps freed memory in the process's heaps instead; the
// process's resident size stays at its high-water mark.

namespace ppr::util {

// The settings keepFreedHeapMemory() makes: no trimming below this much free memory at a heap's top,
// blocks below the mmap threshold from the heap (glibc's largest: larger ones are mapped anyway), and
// each heap grown by this much more than asked.
constexpr long kHeapTrimThreshold = 1L << 30;
constexpr long kHeapMmapThreshold = 32L << 20;
constexpr long kHeapTopPad = 64L << 20;

// Whether the user's GLIBC_TUNABLES (null: unset) already choose how the heap is trimmed or mapped, in
// which case theirs stand.
bool heapTunedByUser(const char* glibcTunables);

// Applies the settings above (glibc's mallopt); false where they cannot be made (not glibc, or a
// sanitizer's allocator, which ignores them).
bool keepFreedHeapMemory();

}  // namespace ppr::util
