#include "render/headless.hpp"

#include "cli/cli.hpp"
#include "metrics/median.hpp"
#include "render/memory_log.hpp"
#include "render/render_scale.hpp"
#include "scene/glass_atlas.hpp"
#include "techniques/technique_table.hpp"

#include "hiz/hiz.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace ppr::app {

namespace {
constexpr size_t kMaxTimedFrames = 256;  // frames a capture keeps timings of (the median's window)

// A host-readable buffer of `bytes` and its import into the graph, which leaves it readable by the host.
void createReadback(const vk::Context& ctx, VkDeviceSize bytes, const char* name, vk::Buffer& buffer, graph::ExternalBuffer& import) {
    buffer = vk::createBuffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, name);
    import = {};
    import.buffer = buffer.buffer;
    import.desc = {bytes};
    import.finalAccess = graph::Access::HostRead;
}
}  // namespace

void HeadlessRenderer::setTechnique(const std::string& technique) { technique_ = techniqueDesc(technique).name; }

Settings HeadlessRenderer::setVariant(const std::string& text) {
    const TechniqueVariant variant = parseTechniqueVariant(text);
    Settings before = settings_;
    for (const std::string& kv : variant.sets) settings_.apply(kv);
    setTechnique(variant.name);
    return before;
}

HeadlessRenderer::HeadlessRenderer(const vk::Context& ctx, Renderer& renderer) : ctx_(ctx), renderer_(renderer), abTaps_(ctx) {
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = ctx.queueFamily();
    VK_CHECK(vkCreateCommandPool(ctx.device(), &pci, nullptr, &pool_));
    ctx.name(pool_, VK_OBJECT_TYPE_COMMAND_POOL, "headless frames");
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = Renderer::kFramesInFlight;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, cmds_));
    for (uint32_t i = 0; i < Renderer::kFramesInFlight; ++i) {
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(ctx.device(), &fci, nullptr, &fences_[i]));
        ctx.name(cmds_[i], VK_OBJECT_TYPE_COMMAND_BUFFER, "frame " + std::to_string(i));
        ctx.name(fences_[i], VK_OBJECT_TYPE_FENCE, "frame fence " + std::to_string(i));
    }
}

HeadlessRenderer::~HeadlessRenderer() {
    vkDeviceWaitIdle(ctx_.device());
    for (VkFence f : fences_) vkDestroyFence(ctx_.device(), f, nullptr);
    vkDestroyCommandPool(ctx_.device(), pool_, nullptr);
    vk::destroyBuffer(ctx_, readback_);
    vk::destroyBuffer(ctx_, reflectionReadback_);
    vk::destroyBuffer(ctx_, pathReadback_);
    vk::destroyBuffer(ctx_, glassReadback_);
    vk::destroyImage(ctx_, target_);
}

void HeadlessRenderer::ensureTargets(VkExtent2D extent) {
    const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
    if (readback_.buffer && target_.extent.width == extent.width && target_.extent.height == extent.height) return;
    vkDeviceWaitIdle(ctx_.device());
    vk::destroyBuffer(ctx_, readback_);
    vk::destroyBuffer(ctx_, reflectionReadback_);
    vk::destroyBuffer(ctx_, pathReadback_);
    vk::destroyImage(ctx_, target_);
    target_ = vk::createImage(ctx_, extent, Renderer::kCaptureFormat,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, 1, "capture target");
    targetImport_ = {};
    targetImport_.image = target_.image;
    targetImport_.view = target_.view;
    targetImport_.desc = {extent.width, extent.height, Renderer::kCaptureFormat, 1};
    createReadback(ctx_, bytes, "capture readback", readback_, readbackImport_);
    createReadback(ctx_, bytes * 2, "reflection readback", reflectionReadback_, reflectionImport_);  // RGBA16F
    createReadback(ctx_, bytes * 2, "path readback", pathReadback_, pathImport_);                    // RG32F
}

void HeadlessRenderer::ensureGlassReadback(uint32_t atlasSize) {
    if (atlasSize <= glassReadbackSize_) return;
    vkDeviceWaitIdle(ctx_.device());
    vk::destroyBuffer(ctx_, glassReadback_);
    const VkDeviceSize bytes = VkDeviceSize(atlasSize) * atlasSize * 8;
    createReadback(ctx_, bytes, "glass readback", glassReadback_, glassImport_);
    glassReadbackSize_ = atlasSize;
}

VkCommandBuffer HeadlessRenderer::beginSlot(uint32_t slot) {
    VK_CHECK(vkResetFences(ctx_.device(), 1, &fences_[slot]));
    VkCommandBuffer cmd = cmds_[slot];
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    return cmd;
}

CaptureResult HeadlessRenderer::capture(const scene::CameraPose& camera, VkExtent2D extent, uint32_t frames, bool dumpGraph,
                                        bool readReflection, bool newShot) {
    ensureTargets(extent);
    if (readReflection && renderScale_ != 1.0f) throw std::logic_error("capture: the reflection is read back at the frame's size; render scale 1 only");
    frames = std::max(frames, 1u);
    CaptureResult result;
    result.frames = frames;
    std::map<std::string, std::vector<double>> perPass;
    std::vector<double> totals;
    bool reflectionCopied = false, glassCopied = false, pathCopied = false;
    uint32_t lastSlot = 0;
    const uint32_t glassAtlas = settings_.values().glass.atlas;
    if (readReflection) ensureGlassReadback(glassAtlas);
    auto collect = [&](uint32_t slot) {
        if (!slotBusy_[slot]) return;
        VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fences_[slot], VK_TRUE, UINT64_MAX));
        slotBusy_[slot] = false;
        double total = 0.0;
        std::vector<std::string> order;
        // Medians over the last kMaxTimedFrames frames: a soak of 10 000 frames keeps a fixed window
        // instead of growing with every frame (the median does not depend on the order).
        auto keep = [&](std::vector<double>& v, double ms) {
            if (v.size() < kMaxTimedFrames) v.push_back(ms);
            else v[result.timedFrames % kMaxTimedFrames] = ms;
        };
        for (const graph::PassTiming& t : renderer_.timings(slot)) {
            keep(perPass[t.name], t.gpuMs);
            total += t.gpuMs;
            order.push_back(t.name);
        }
        if (!order.empty()) {
            keep(totals, total);
            result.timedFrames++;
        }
        if (order.size() >= result.passOrder.size()) result.passOrder = order;
    };

    for (uint32_t f = 0; f < frames; ++f) {
        const uint32_t slot = f % Renderer::kFramesInFlight;
        collect(slot);
        logMemoryEvery(ctx_, f);
        VkCommandBuffer cmd = beginSlot(slot);
        FrameRequest req;
        req.camera = camera;
        req.extent = scaledExtent(extent, renderScale_);  // the tonemap pass upscales it into the target
        req.technique = technique_;
        req.reference = reference_;
        req.settings = settings_.values();
        req.target = &targetImport_;
        req.cameraCut = newShot && f == 0;  // TAA starts from this camera's own frames
        req.jitter = jitter_;
        req.sceneTime = sceneTime_;
        const bool last = f + 1 == frames;
        abTaps_.attach(req.taps, ab_, abSplit_);
        if (last) req.taps.push_back(readbackTap(ReadbackSource::Final, &readbackImport_));
        if (last && readReflection) {
            req.taps.push_back(readbackTap(ReadbackSource::Reflection, &reflectionImport_, &reflectionCopied));
            req.taps.push_back(readbackTap(ReadbackSource::GlassAtlas, &glassImport_, &glassCopied));
            req.taps.push_back(readbackTap(ReadbackSource::ReflectedPath, &pathImport_, &pathCopied));
        }
        req.dumpGraph = last && dumpGraph;
        FrameRecord rec = renderer_.record(cmd, slot, req);
        if (last) {
            lastSlot = slot;
            result.warning = rec.warning;
            result.cullLog = rec.cullLog;
            result.dot = rec.dot;
        }
        VK_CHECK(vkEndCommandBuffer(cmd));
        vk::submit(ctx_, cmd, fences_[slot]);
        slotBusy_[slot] = true;
    }
    for (uint32_t s = 0; s < Renderer::kFramesInFlight; ++s) collect(s);
    result.pprStats = renderer_.frameStats(lastSlot);
    result.glass = renderer_.glassStats(lastSlot);
    result.environmentProbe = renderer_.environmentProbe().stats();
    if (result.glass && result.glass->overflowed())
        result.warning += (result.warning.empty() ? "" : "; ") + result.glass->overflowMessage();

    vmaInvalidateAllocation(ctx_.allocator(), readback_.allocation, 0, VK_WHOLE_SIZE);
    result.image.width = extent.width;
    result.image.height = extent.height;
    result.image.pixels.resize(size_t(extent.width) * extent.height * 4);
    std::memcpy(result.image.pixels.data(), readback_.mapped, size_t(extent.width) * extent.height * 4);
    if (reflectionCopied) {
        vmaInvalidateAllocation(ctx_.allocator(), reflectionReadback_.allocation, 0, VK_WHOLE_SIZE);
        result.reflection = floatImageFromHalf(reflectionReadback_.mapped, extent.width, extent.height);
    }
    if (pathCopied) {
        vmaInvalidateAllocation(ctx_.allocator(), pathReadback_.allocation, 0, VK_WHOLE_SIZE);
        const float* path = static_cast<const float*>(pathReadback_.mapped);
        result.reflectedPath.assign(path, path + size_t(extent.width) * extent.height * 2);
    }
    if (glassCopied) {
        vmaInvalidateAllocation(ctx_.allocator(), glassReadback_.allocation, 0, VK_WHOLE_SIZE);
        const FloatImage read = floatImageFromHalf(glassReadback_.mapped, glassAtlas, glassAtlas);
        // Only the regions and their rings are defined (PPR's resolve leaves the rest as it finds
        // it); the rest reads as "no reflection", as a cleared atlas would.
        result.glassReflection.width = result.glassReflection.height = glassAtlas;
        result.glassReflection.rgba.assign(read.rgba.size(), 0.0f);
        if (result.glass)
            for (const scene::ScreenRect& t : scene::glassAtlasDefinedRects(result.glass->layout, glassAtlas))
                for (int32_t y = t.y0; y < t.y1; ++y) {
                    const size_t row = (size_t(y) * glassAtlas + size_t(t.x0)) * 4;
                    std::copy(read.rgba.begin() + row, read.rgba.begin() + row + size_t(t.width()) * 4, result.glassReflection.rgba.begin() + row);
                }
    }
    for (auto& [name, values] : perPass) result.passMedianMs[name] = median(values);
    result.totalMedianMs = median(totals);
    result.medianFrames = uint32_t(totals.size());
    return result;
}

util::Rgba8Image HeadlessRenderer::captureSupersampled(const scene::CameraPose& camera, VkExtent2D extent, uint32_t samples) {
    const Settings before = settings_;
    settings_.set("taa", "0");
    std::vector<double> sum(size_t(extent.width) * extent.height * 4, 0.0);
    for (uint32_t i = 0; i < samples; ++i) {
        jitter_ = scene::haltonJitter(i);
        const CaptureResult frame = capture(camera, extent, 1);
        for (size_t k = 0; k < sum.size(); ++k) sum[k] += frame.image.pixels[k];
    }
    jitter_.reset();
    settings_ = before;
    util::Rgba8Image out;
    out.width = extent.width;
    out.height = extent.height;
    out.pixels.resize(sum.size());
    for (size_t k = 0; k < sum.size(); ++k) out.pixels[k] = static_cast<uint8_t>(std::lround(sum[k] / std::max(samples, 1u)));
    return out;
}

DepthCapture HeadlessRenderer::captureDepth(const scene::CameraPose& camera, VkExtent2D extent) {
    ensureTargets(extent);
    // Frames still in flight finish first: this frame reuses slot 0.
    for (uint32_t s = 0; s < Renderer::kFramesInFlight; ++s)
        if (slotBusy_[s]) {
            VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fences_[s], VK_TRUE, UINT64_MAX));
            slotBusy_[s] = false;
        }
    const glm::uvec2 atlas = gpu::hizAtlasSize(gpu::hizPaddedSize({extent.width, extent.height}));
    const VkDeviceSize depthBytes = VkDeviceSize(extent.width) * extent.height * sizeof(float);
    const VkDeviceSize atlasBytes = VkDeviceSize(atlas.x) * atlas.y * sizeof(float);
    vk::Buffer depthBuffer = vk::createBuffer(ctx_, depthBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, "depth readback");
    vk::Buffer atlasBuffer = vk::createBuffer(ctx_, atlasBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, "hiz readback");
    graph::ExternalBuffer depthImport{depthBuffer.buffer, {depthBytes}, {}, graph::Access::HostRead};
    graph::ExternalBuffer atlasImport{atlasBuffer.buffer, {atlasBytes}, {}, graph::Access::HostRead};

    const uint32_t slot = 0;
    VkCommandBuffer cmd = beginSlot(slot);
    FrameRequest req;
    req.camera = camera;
    req.extent = extent;
    req.technique = technique_;
    req.settings = settings_.values();
    req.target = &targetImport_;
    bool hizCopied = false;
    req.taps = {readbackTap(ReadbackSource::Depth, &depthImport), readbackTap(ReadbackSource::Hierarchy, &atlasImport, &hizCopied)};
    renderer_.record(cmd, slot, req);
    VK_CHECK(vkEndCommandBuffer(cmd));
    vk::submit(ctx_, cmd, fences_[slot]);
    VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fences_[slot], VK_TRUE, UINT64_MAX));

    DepthCapture result;
    result.width = extent.width;
    result.height = extent.height;
    result.depth.resize(size_t(extent.width) * extent.height);
    vmaInvalidateAllocation(ctx_.allocator(), depthBuffer.allocation, 0, VK_WHOLE_SIZE);
    std::memcpy(result.depth.data(), depthBuffer.mapped, depthBytes);
    if (hizCopied) {
        result.atlasWidth = atlas.x;
        result.atlasHeight = atlas.y;
        result.hizAtlas.resize(size_t(atlas.x) * atlas.y);
        vmaInvalidateAllocation(ctx_.allocator(), atlasBuffer.allocation, 0, VK_WHOLE_SIZE);
        std::memcpy(result.hizAtlas.data(), atlasBuffer.mapped, atlasBytes);
    }
    vk::destroyBuffer(ctx_, depthBuffer);
    vk::destroyBuffer(ctx_, atlasBuffer);
    return result;
}

}  // namespace ppr::app
