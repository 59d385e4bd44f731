#include "frame/frame_services.hpp"

#include <cstring>

namespace ppr::app {

FrameStatsBuffers::FrameStatsBuffers(const vk::Context& ctx, uint32_t framesInFlight)
    : ctx_(ctx), buffers_(framesInFlight), imports_(framesInFlight), written_(framesInFlight, false) {
    for (uint32_t slot = 0; slot < framesInFlight; ++slot) {
        buffers_[slot] = vk::createBuffer(ctx, sizeof(gpu::PprFrameStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          vk::MemoryUse::Readback, "ppr stats[" + std::to_string(slot) + "]");
        imports_[slot].buffer = buffers_[slot].buffer;
        imports_[slot].desc = {sizeof(gpu::PprFrameStats)};
        imports_[slot].finalAccess = graph::Access::HostRead;
    }
}

FrameStatsBuffers::~FrameStatsBuffers() {
    for (vk::Buffer& b : buffers_) vk::destroyBuffer(ctx_, b);
}

std::optional<gpu::PprFrameStats> FrameStatsBuffers::read(uint32_t slot) const {
    if (!written_[slot]) return std::nullopt;
    vmaInvalidateAllocation(ctx_.allocator(), buffers_[slot].allocation, 0, VK_WHOLE_SIZE);
    gpu::PprFrameStats s;
    std::memcpy(&s, buffers_[slot].mapped, sizeof(s));
    return s;
}

passes::HizAtlas TechniqueFrame::depthHierarchy() {
    if (const DepthHierarchy* built = board.find<DepthHierarchy>()) return built->atlas;
    const DepthHierarchyTiles* tiles = board.find<DepthHierarchyTiles>();
    const passes::HizAtlas hiz = services.hiz.add(graph, in, gbuffer.depth, settings.ssr.hizThreads,
                                                  tiles ? std::optional<graph::ImageHandle>(tiles->atlas) : std::nullopt);
    board.put(DepthHierarchy{hiz});
    return hiz;
}

passes::Environment TechniqueFrame::environment() {
    if (const EnvironmentBound* bound = board.find<EnvironmentBound>()) return bound->environment;
    const bool probe = settings.env.fallback && settings.env.source == EnvSource::Probe;
    if (probe) services.environment.prepare(in, services.constants.main(), services.reflectors.list(), settings.view.shadowRes);
    const passes::Environment env = services.environment.bind(graph, settings.env.fallback, probe);
    board.put(EnvironmentBound{env});
    return env;
}

passes::TileLists TechniqueFrame::classifyTiles(uint32_t maxReflectorId) {
    return services.tileClassify.add(graph, in, gbuffer, services.stats.import(graph, slot), maxReflectorId,
                                     settings.tiles.classifyThreads);
}

passes::TileLists TechniqueFrame::classifyTiles(uint32_t maxReflectorId, const passes::TileClassifyTargets& cleared) {
    return services.tileClassify.add(graph, in, gbuffer, cleared, maxReflectorId, settings.tiles.classifyThreads);
}

}  // namespace ppr::app
