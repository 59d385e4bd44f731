#pragma once
// A CPU Vulkan device (lavapipe) runs inside this process, and its rasterizer bins every frame's draws
// into memory it allocates and frees again. glibc hands a freed heap top back to the kernel (trimming
// above 128 KiB, and large blocks are their own mappings), so the next frame takes a page fault for
// every page of it again: on lavapipe a third of the frame's time at 640x360 (docs/performance.md,
// "The heap kept"). keepFreedHeapMemory() keeps freed memory in the process's heaps instead; the
// process's resident size stays at its high-water mark.

#include <cstddef>  // defines __GLIBC__ (through the C library's features.h) before the test below

// glibc's allocator, not a sanitizer's (which ignores mallopt): where keepFreedHeapMemory() can work.
// GCC names a sanitizer with a macro, clang with __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PPR_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define PPR_SANITIZER_ALLOCATOR 1
#endif
#endif
#if defined(__GLIBC__) && !defined(PPR_SANITIZER_ALLOCATOR)
#define PPR_HEAP_KEEPABLE 1
#else
#define PPR_HEAP_KEEPABLE 0
#endif

namespace ppr::util {

inline constexpr bool kHeapKeepable = PPR_HEAP_KEEPABLE != 0;

// The settings keepFreedHeapMemory() makes: no trimming below this much free memory at a heap's top,
// blocks below the mmap threshold from the heap (glibc's largest: larger ones are mapped anyway), and
// each heap grown by this much more than asked.
constexpr long kHeapTrimThreshold = 1L << 30;
constexpr long kHeapMmapThreshold = 32L << 20;
constexpr long kHeapTopPad = 64L << 20;

// Whether the user's GLIBC_TUNABLES (null: unset) already choose how the heap is trimmed or mapped, in
// which case theirs stand.
bool heapTunedByUser(const char* glibcTunables);

// Applies the settings above (glibc's mallopt); false where they cannot be made (!kHeapKeepable).
bool keepFreedHeapMemory();

}  // namespace ppr::util
