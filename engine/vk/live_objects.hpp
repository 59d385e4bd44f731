#pragma once
// Counts of the Vulkan objects that must not grow frame by frame (pipelines, descriptor set layouts,
// descriptor pools), kept by the code that creates and destroys them; the memory log and the soak
// read them (docs/reliability.md). Per process, not per context: one context per run.
#include <atomic>
#include <cstdint>

namespace ppr::vk {

struct LiveObjects {
    std::atomic<int64_t> pipelines{0};
    std::atomic<int64_t> descriptorSetLayouts{0};
    std::atomic<int64_t> descriptorPools{0};
};

LiveObjects& liveObjects();

}  // namespace ppr::vk
