// GraphExecutor: realizes resources, then records each kept pass as
//   label, timestamp, one vkCmdPipelineBarrier2, [dynamic rendering], body, timestamp, end label
// and finally the barriers that hand imports over to their final access.
#include "graph/executor.hpp"

#include <stdexcept>

namespace ppr::graph {

namespace {

VkAttachmentLoadOp loadOpFor(LoadOp op) {
    switch (op) {
        case LoadOp::Load: return VK_ATTACHMENT_LOAD_OP_LOAD;
        case LoadOp::Clear: return VK_ATTACHMENT_LOAD_OP_CLEAR;
        case LoadOp::DontCare: return VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    }
    return VK_ATTACHMENT_LOAD_OP_LOAD;
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, const AttachmentInfo& a,
                                     VkAttachmentStoreOp store) {
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = view;
    info.imageLayout = layout;
    info.loadOp = loadOpFor(a.load);
    info.storeOp = store;
    info.clearValue = a.clear;
    return info;
}

// Dynamic rendering over the given attachments, with a full viewport and scissor.
void beginRendering(VkCommandBuffer cmd, VkExtent2D extent, const std::vector<VkRenderingAttachmentInfo>& colors,
                    const VkRenderingAttachmentInfo* depth) {
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, extent};
    info.layerCount = 1;
    info.colorAttachmentCount = static_cast<uint32_t>(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = depth;
    vkCmdBeginRendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace

GraphExecutor::GraphExecutor(const vk::Context& ctx, uint32_t framesInFlight, uint32_t maxPassesPerFrame)
    : ctx_(ctx),
      history_(std::make_unique<HistoryStore>(vkHistoryAllocator(ctx))),
      framesInFlight_(framesInFlight),
      maxPasses_(maxPassesPerFrame) {
    if (framesInFlight == 0 || maxPassesPerFrame == 0)
        throw std::runtime_error("graph: GraphExecutor needs framesInFlight > 0 and maxPassesPerFrame > 0");
    timingSlots_.resize(framesInFlight);
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = framesInFlight * maxPassesPerFrame * 2;
    VK_CHECK(vkCreateQueryPool(ctx_.device(), &info, nullptr, &queryPool_));
    ctx_.name(queryPool_, VK_OBJECT_TYPE_QUERY_POOL, "graph:timestamps");
}

GraphExecutor::~GraphExecutor() {
    history_.reset();  // first, while ctx_ is certainly alive; its deallocator waits for the device
    for (PooledImage& p : images_) vk::destroyImage(ctx_, p.object);
    for (PooledBuffer& p : buffers_) vk::destroyBuffer(ctx_, p.object);
    if (queryPool_) vkDestroyQueryPool(ctx_.device(), queryPool_, nullptr);
}

void GraphExecutor::execute(RenderGraph& graph, VkCommandBuffer cmd, uint32_t frameSlot) {
    if (frameSlot >= framesInFlight_)
        throw std::runtime_error("graph: frame slot " + std::to_string(frameSlot) + " >= framesInFlight " +
                                 std::to_string(framesInFlight_));
    if (!graph.compiled) graph.compile();
    ++frameCounter_;

    std::vector<uint32_t> kept;
    for (const CompiledPass& cp : graph.compiledPasses())
        if (!cp.culled) kept.push_back(cp.index);
    if (kept.size() > maxPasses_)
        throw std::runtime_error("graph: " + std::to_string(kept.size()) + " passes exceed the executor's " +
                                 "maxPassesPerFrame (" + std::to_string(maxPasses_) + ")");

    // Realize: imports bring their own objects; transients come from the pool (created on a miss).
    std::vector<bool> used(graph.resources_.size(), false);
    for (uint32_t p : kept)
        for (const ResourceUse& u : graph.passes_[p].uses) used[u.resource] = true;
    for (uint32_t id = 0; id < graph.resources_.size(); ++id) {
        RenderGraph::Resource& r = graph.resources_[id];
        if (r.importedImage) {
            r.image = r.importedImage->image;
            r.view = r.importedImage->view;
        } else if (r.importedBuffer) {
            r.buffer = r.importedBuffer->buffer;
        } else if (used[id] && r.isImage) {
            const vk::Image& img = acquire(images_, r.imageDesc, r.imageUsage, [&] {
                return vk::createImage(ctx_, {r.imageDesc.width, r.imageDesc.height}, r.imageDesc.format, r.imageUsage,
                                       r.imageDesc.mipLevels, "graph:" + r.name);
            }).object;
            r.image = img.image;
            r.view = img.view;
        } else if (used[id]) {
            r.buffer = acquire(buffers_, r.bufferDesc, r.bufferUsage, [&] {
                return vk::createBuffer(ctx_, r.bufferDesc.size, r.bufferUsage, vk::MemoryUse::GpuOnly, "graph:" + r.name);
            }).object.buffer;
        }
    }
    // Everything recorded here is only submitted later; the pool is free for the next execute() as the
    // first-use barrier (ALL_COMMANDS) orders the next frame after this one's use of the memory.
    for (PooledImage& p : images_) p.inUse = false;
    for (PooledBuffer& p : buffers_) p.inUse = false;

    const bool timed = ctx_.info().timestampValidBits > 0;
    const uint32_t firstQuery = frameSlot * maxPasses_ * 2;
    TimingSlot& slot = timingSlots_[frameSlot];
    slot.passNames.clear();
    slot.queryCount = 0;
    if (timed) vkCmdResetQueryPool(cmd, queryPool_, firstQuery, maxPasses_ * 2);

    auto recordBarriers = [&](const std::vector<PlannedBarrier>& planned) {
        if (planned.empty()) return;
        std::vector<VkImageMemoryBarrier2> images;
        std::vector<VkBufferMemoryBarrier2> buffers;
        for (const PlannedBarrier& b : planned) {
            const RenderGraph::Resource& r = graph.resources_[b.resource];
            if (b.isImage) {
                VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
                ib.srcStageMask = b.srcStage;
                ib.srcAccessMask = b.srcAccess;
                ib.dstStageMask = b.dstStage;
                ib.dstAccessMask = b.dstAccess;
                ib.oldLayout = b.oldLayout;
                ib.newLayout = b.newLayout;
                ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
                ib.image = r.image;
                ib.subresourceRange = {isDepthFormat(r.imageDesc.format) ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT)
                                                                         : VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT),
                                       0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
                images.push_back(ib);
            } else {
                VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
                bb.srcStageMask = b.srcStage;
                bb.srcAccessMask = b.srcAccess;
                bb.dstStageMask = b.dstStage;
                bb.dstAccessMask = b.dstAccess;
                bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
                bb.buffer = r.buffer;
                bb.offset = 0;
                bb.size = VK_WHOLE_SIZE;
                buffers.push_back(bb);
            }
        }
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = static_cast<uint32_t>(images.size());
        dep.pImageMemoryBarriers = images.data();
        dep.bufferMemoryBarrierCount = static_cast<uint32_t>(buffers.size());
        dep.pBufferMemoryBarriers = buffers.data();
        vkCmdPipelineBarrier2(cmd, &dep);
    };

    for (uint32_t p : kept) {
        const RenderGraph::Pass& pass = graph.passes_[p];
        const uint32_t query = firstQuery + 2 * static_cast<uint32_t>(slot.passNames.size());
        ctx_.beginLabel(cmd, pass.name.c_str());
        if (timed) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queryPool_, query);
        recordBarriers(graph.compiled_[p].barriers);

        PassContext context(graph, p, cmd);
        const bool rendering = pass.kind == QueueKind::Graphics && !pass.customRendering &&
                               (!pass.colorAttachments.empty() || pass.depthAttachment);
        if (rendering) {
            std::vector<VkRenderingAttachmentInfo> colors;
            for (const AttachmentInfo& a : pass.colorAttachments)
                colors.push_back(attachment(graph.resources_[a.image.id].view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                            a, VK_ATTACHMENT_STORE_OP_STORE));
            VkRenderingAttachmentInfo depth{};
            if (pass.depthAttachment)
                // A read-only depth attachment must not be stored: STORE would count as a write.
                depth = pass.depthReadOnly
                            ? attachment(graph.resources_[pass.depthAttachment->image.id].view,
                                         VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, *pass.depthAttachment,
                                         VK_ATTACHMENT_STORE_OP_NONE)
                            : attachment(graph.resources_[pass.depthAttachment->image.id].view,
                                         VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, *pass.depthAttachment,
                                         VK_ATTACHMENT_STORE_OP_STORE);
            const VkExtent2D extent = context.renderExtent();
            beginRendering(cmd, extent, colors, pass.depthAttachment ? &depth : nullptr);
        }
        if (pass.body) pass.body->run(context);
        if (rendering) vkCmdEndRendering(cmd);

        if (timed) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queryPool_, query + 1);
        ctx_.endLabel(cmd);
        slot.passNames.push_back(pass.name);
    }
    if (timed) slot.queryCount = 2 * static_cast<uint32_t>(slot.passNames.size());
    else slot.passNames.clear();

    recordBarriers(graph.finalBarriers_);
    // Imports leave the frame in the state the recorded commands put them in; one execute() is one
    // frame (slots, timings and trimPool count it so too), so it also ends the history store's frame.
    graph.commitImportStates();
    history_->endFrame();
}

std::vector<PassTiming> GraphExecutor::readTimings(uint32_t frameSlot) {
    if (frameSlot >= framesInFlight_) return {};
    const TimingSlot& slot = timingSlots_[frameSlot];
    if (slot.queryCount == 0) return {};
    std::vector<uint64_t> ticks(slot.queryCount);
    VK_CHECK(vkGetQueryPoolResults(ctx_.device(), queryPool_, frameSlot * maxPasses_ * 2, slot.queryCount,
                                   ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint32_t bits = ctx_.info().timestampValidBits;
    const uint64_t mask = bits >= 64 ? ~0ull : (1ull << bits) - 1;  // differences wrap at the valid bits
    std::vector<PassTiming> timings;
    for (size_t i = 0; i < slot.passNames.size(); ++i) {
        const uint64_t delta = (ticks[2 * i + 1] - ticks[2 * i]) & mask;
        timings.push_back({slot.passNames[i], double(delta) * ctx_.info().timestampPeriodNs * 1e-6});
    }
    return timings;
}

void GraphExecutor::trimPool(uint32_t unusedFrames) {
    auto stale = [&](const auto& entry) { return entry.lastUsedFrame + unusedFrames < frameCounter_; };
    for (PooledImage& p : images_)
        if (stale(p)) vk::destroyImage(ctx_, p.object);
    for (PooledBuffer& p : buffers_)
        if (stale(p)) vk::destroyBuffer(ctx_, p.object);
    std::erase_if(images_, stale);
    std::erase_if(buffers_, stale);
    history_->trim(unusedFrames);  // history of a mode switched off, too
}

template <class Entry, class Create>
Entry& GraphExecutor::acquire(std::vector<Entry>& pool, const decltype(Entry::desc)& desc, decltype(Entry::usage) usage,
                              Create&& create) {
    Entry* hit = nullptr;
    for (Entry& p : pool)
        if (!p.inUse && p.desc == desc && (p.usage & usage) == usage) hit = &p;
    if (!hit) {
        pool.push_back(Entry{desc, usage, create()});
        ++allocations_;
        hit = &pool.back();
    }
    hit->inUse = true;
    hit->lastUsedFrame = frameCounter_;
    return *hit;
}

}  // namespace ppr::graph
