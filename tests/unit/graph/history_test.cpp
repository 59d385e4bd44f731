// History resources across simulated frames, without a GPU: a fake allocator hands out dummy handles
// and each frame is "new RenderGraph, compile, commitImportStates, endFrame" — exactly the bookkeeping
// GraphExecutor::execute does around the Vulkan recording.
#include "graph/history.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <stdexcept>

using namespace ppr::graph;

namespace {

struct NoData {};
void addPass(RenderGraph& g, const std::string& name, QueueKind kind, const std::function<void(PassBuilder&)>& setup) {
    g.addPass<NoData>(name, kind, [&](PassBuilder& b, NoData&) { setup(b); }, nullptr);
}

// Counts allocations and records frees; handles are non-null integers cast to Vulkan handles.
struct FakeGpu {
    uint64_t next = 0x1000;
    std::set<VkImage> liveImages;
    std::set<VkBuffer> liveBuffers;
    std::vector<VkImage> freedImages;
    std::vector<VkBuffer> freedBuffers;
    std::vector<std::string> createdNames;

    HistoryAllocator allocator() {
        HistoryAllocator a;
        a.createImage = [this](const std::string& name, const ImageDesc&) {
            createdNames.push_back(name);
            ExternalImage e;
            e.image = reinterpret_cast<VkImage>(next++);
            e.view = reinterpret_cast<VkImageView>(next++);
            liveImages.insert(e.image);
            return e;
        };
        a.destroyImage = [this](const ExternalImage& e) {
            liveImages.erase(e.image);
            freedImages.push_back(e.image);
        };
        a.createBuffer = [this](const std::string& name, const BufferDesc&) {
            createdNames.push_back(name);
            ExternalBuffer e;
            e.buffer = reinterpret_cast<VkBuffer>(next++);
            liveBuffers.insert(e.buffer);
            return e;
        };
        a.destroyBuffer = [this](const ExternalBuffer& e) {
            liveBuffers.erase(e.buffer);
            freedBuffers.push_back(e.buffer);
        };
        return a;
    }
};

const ImageDesc kColor{64, 32, VK_FORMAT_R16G16B16A16_SFLOAT, 1};
constexpr VkPipelineStageFlags2 kCS = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kColorOut = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;

// The executor's post-recording bookkeeping, minus Vulkan.
void finishFrame(RenderGraph& g, HistoryStore& store) {
    g.commitImportStates();
    store.endFrame();
}

// A TAA-like compute pass: samples last frame's result, writes this frame's.
HistoryImage taaFrame(RenderGraph& g, HistoryStore& store, const ImageDesc& desc = kColor) {
    HistoryImage h = g.history(store, "taa.color", desc);
    addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) {
        b.sampled(h.previous);
        h.current = b.storageWrite(h.current);
    });
    return h;
}

const PlannedBarrier* barrierFor(const RenderGraph& g, uint32_t pass, uint32_t resource) {
    for (const PlannedBarrier& b : g.compiledPasses()[pass].barriers)
        if (b.resource == resource) return &b;
    return nullptr;
}

}  // namespace

TEST(GraphHistory, SameNameSamePhysicalPairSwappedEachFrame) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    VkImage lastCurrent = VK_NULL_HANDLE;
    std::set<VkImage> seen;
    for (int frame = 0; frame < 4; ++frame) {
        RenderGraph g;
        HistoryImage h = taaFrame(g, store);
        EXPECT_EQ(g.resourceName(h.previous.id), "taa.color[previous]");
        EXPECT_EQ(g.resourceName(h.current.id), "taa.color[current]");
        const VkImage prev = store.previousImage("taa.color").image;
        const VkImage cur = store.currentImage("taa.color").image;
        EXPECT_NE(prev, cur);
        if (frame > 0) {
            EXPECT_EQ(prev, lastCurrent) << "frame " << frame << ": previous is not last frame's current";
        }
        lastCurrent = cur;
        seen.insert(prev);
        seen.insert(cur);
        g.compile();
        finishFrame(g, store);
    }
    EXPECT_EQ(seen.size(), 2u);
    EXPECT_EQ(gpu.createdNames, (std::vector<std::string>{"taa.color#0", "taa.color#1"}));
    EXPECT_TRUE(gpu.freedImages.empty());
}

TEST(GraphHistory, PreviousValidOnlyAfterAFrameWroteCurrent) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    for (int frame = 0; frame < 3; ++frame) {
        RenderGraph g;
        EXPECT_EQ(taaFrame(g, store).previousValid, frame > 0) << "frame " << frame;
        g.compile();
        finishFrame(g, store);
    }
    EXPECT_EQ(store.status("taa.color")->resets, 0u);  // creation is not a reset
    EXPECT_TRUE(store.resetLog().empty());
}

// Frame 1 writes current as a storage image (GENERAL, compute); frame 2 samples it as previous: the
// barrier must start from exactly that state, carried across frames through the import.
TEST(GraphHistory, BarrierForPreviousStartsFromLastFramesState) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    {
        RenderGraph g;
        HistoryImage h = taaFrame(g, store);
        g.compile();
        // First frame: nothing ran on the fresh images, so only a layout change from UNDEFINED.
        const PlannedBarrier* b = barrierFor(g, 0, h.current.id);
        ASSERT_NE(b, nullptr);
        EXPECT_EQ(b->oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
        EXPECT_EQ(b->srcStage, VK_PIPELINE_STAGE_2_NONE);
        finishFrame(g, store);
    }
    RenderGraph g;
    HistoryImage h = taaFrame(g, store);
    g.compile();
    const PlannedBarrier* prev = barrierFor(g, 0, h.previous.id);
    ASSERT_NE(prev, nullptr);
    EXPECT_EQ(prev->srcStage, kCS);
    EXPECT_EQ(prev->srcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(prev->oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(prev->dstStage, kCS);
    EXPECT_EQ(prev->dstAccess, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    EXPECT_EQ(prev->newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    // And the other half: last frame sampled it, so writing it now waits for that read (WAR).
    const PlannedBarrier* cur = barrierFor(g, 0, h.current.id);
    ASSERT_NE(cur, nullptr);
    EXPECT_EQ(cur->srcStage, kCS);
    EXPECT_EQ(cur->srcAccess, VK_ACCESS_2_NONE);
    EXPECT_EQ(cur->oldLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(cur->newLayout, VK_IMAGE_LAYOUT_GENERAL);
}

// Same, written by a graphics pass as a color attachment and read by compute next frame.
TEST(GraphHistory, BarrierAfterColorAttachmentWrite) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    {
        RenderGraph g;
        HistoryImage h = g.history(store, "taa.color", kColor);
        addPass(g, "resolve", QueueKind::Graphics, [&](PassBuilder& b) { b.colorAttachment(h.current, LoadOp::Clear); });
        g.compile();
        finishFrame(g, store);
    }
    RenderGraph g;
    HistoryImage h = taaFrame(g, store);
    g.compile();
    const PlannedBarrier* prev = barrierFor(g, 0, h.previous.id);
    ASSERT_NE(prev, nullptr);
    EXPECT_EQ(prev->srcStage, kColorOut);
    EXPECT_EQ(prev->srcAccess, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(prev->oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(prev->newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(GraphHistory, ResizeReallocatesFreesOldAndResets) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    for (int frame = 0; frame < 2; ++frame) {
        RenderGraph g;
        taaFrame(g, store);
        g.compile();
        finishFrame(g, store);
    }
    const std::set<VkImage> old{store.previousImage("taa.color").image, store.currentImage("taa.color").image};

    RenderGraph g;
    const ImageDesc bigger{128, 64, kColor.format, 1};
    HistoryImage h = taaFrame(g, store, bigger);
    EXPECT_FALSE(h.previousValid);
    EXPECT_EQ(std::set<VkImage>(gpu.freedImages.begin(), gpu.freedImages.end()), old);
    EXPECT_EQ(gpu.liveImages.size(), 2u);
    EXPECT_EQ(gpu.liveImages.count(store.currentImage("taa.color").image), 1u);
    EXPECT_EQ(store.currentImage("taa.color").desc, bigger);
    const HistoryStatus s = *store.status("taa.color");
    EXPECT_EQ(s.lastResetReason, "resize");
    EXPECT_EQ(s.lastResetFrame, 2u);
    EXPECT_EQ(store.resetLog(), (std::vector<std::string>{"history 'taa.color' reset: resize"}));
    // New memory: the barrier starts from UNDEFINED again, not from the old images' state.
    g.compile();
    EXPECT_EQ(barrierFor(g, 0, h.previous.id)->oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
    finishFrame(g, store);

    RenderGraph g2;
    EXPECT_TRUE(taaFrame(g2, store, bigger).previousValid);
}

TEST(GraphHistory, FormatChangeResetsWithItsOwnReason) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    {
        RenderGraph g;
        taaFrame(g, store);
        g.compile();
        finishFrame(g, store);
    }
    RenderGraph g;
    EXPECT_FALSE(taaFrame(g, store, {64, 32, VK_FORMAT_R32G32B32A32_SFLOAT, 1}).previousValid);
    EXPECT_EQ(store.status("taa.color")->lastResetReason, "format change");
    EXPECT_EQ(gpu.freedImages.size(), 2u);
}

TEST(GraphHistory, ExplicitResetIsLoggedAndKeepsResources) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    for (int frame = 0; frame < 2; ++frame) {
        RenderGraph g;
        taaFrame(g, store);
        g.compile();
        finishFrame(g, store);
    }
    const VkImage prevBefore = store.previousImage("taa.color").image;
    store.reset("taa.color", "camera cut");
    EXPECT_EQ(store.status("taa.color")->lastResetReason, "camera cut");
    EXPECT_EQ(store.status("taa.color")->lastResetFrame, 2u);
    EXPECT_EQ(store.resetLog(), (std::vector<std::string>{"history 'taa.color' reset: camera cut"}));

    RenderGraph g;
    EXPECT_FALSE(taaFrame(g, store).previousValid);
    EXPECT_EQ(store.previousImage("taa.color").image, prevBefore);  // no reallocation
    EXPECT_TRUE(gpu.freedImages.empty());
    g.compile();
    finishFrame(g, store);
    RenderGraph g2;
    EXPECT_TRUE(taaFrame(g2, store).previousValid);

    EXPECT_THROW(store.reset("taa.colour", "typo"), std::runtime_error);
}

// A reset that arrives after this frame's request: the pass already blended stale history into
// `current`, so next frame's `previous` must not be trusted either.
TEST(GraphHistory, ResetAfterRequestAlsoInvalidatesNextFrame) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    for (int frame = 0; frame < 2; ++frame) {
        RenderGraph g;
        EXPECT_EQ(taaFrame(g, store).previousValid, frame > 0);
        if (frame == 1) store.resetAll("technique change");
        g.compile();
        finishFrame(g, store);
    }
    RenderGraph g;
    EXPECT_FALSE(taaFrame(g, store).previousValid);
    EXPECT_EQ(store.resetLog(), (std::vector<std::string>{"history 'taa.color' reset: technique change"}));
}

TEST(GraphHistory, PassWritingOnlyHistoryIsNotCulled) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    RenderGraph g;
    HistoryImage h = g.history(store, "taa.color", kColor);
    ImageHandle scratch = g.createImage("scratch", kColor);
    // No sideEffect(), nobody reads `current` this frame: kept because next frame does.
    addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) { b.storageWrite(h.current); });
    // Reading `previous` alone is not a reason to keep a pass.
    addPass(g, "debugPrev", QueueKind::Compute, [&](PassBuilder& b) {
        b.sampled(h.previous);
        b.storageWrite(scratch);
    });
    g.compile();
    EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"debugPrev"}));
    finishFrame(g, store);
    EXPECT_TRUE(store.status("taa.color")->previousValid);
}

TEST(GraphHistory, CurrentNotWrittenOrEntryUnusedInvalidates) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    auto frame = [&](bool request, bool write) {
        RenderGraph g;
        bool valid = false;
        if (request) {
            HistoryImage h = g.history(store, "taa.color", kColor);
            valid = h.previousValid;
            addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) {
                b.sampled(h.previous);
                if (write) b.storageWrite(h.current);
                b.sideEffect();
            });
        }
        g.compile();
        finishFrame(g, store);
        return valid;
    };
    EXPECT_FALSE(frame(true, true));
    EXPECT_TRUE(frame(true, false));   // previous fine, but this frame leaves `current` unwritten...
    EXPECT_FALSE(frame(true, true));   // ...so the next frame must not read it
    frame(false, false);               // TAA off for a frame: history is now two frames old
    EXPECT_FALSE(frame(true, true));
    EXPECT_EQ(store.resetLog(), (std::vector<std::string>{"history 'taa.color' reset: current not written",
                                                          "history 'taa.color' reset: unused for a frame"}));
}

TEST(GraphHistory, TwoEntriesAreIndependent) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    for (int frame = 0; frame < 3; ++frame) {
        RenderGraph g;
        HistoryImage color = g.history(store, "taa.color", kColor);
        HistoryBuffer moments = g.history(store, "denoise.moments", BufferDesc{4096});
        // Frame 2: only the color history was reset.
        EXPECT_EQ(color.previousValid, frame == 1) << "frame " << frame;
        EXPECT_EQ(moments.previousValid, frame > 0) << "frame " << frame;
        addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) {
            b.sampled(color.previous);
            b.storageWrite(color.current);
        });
        addPass(g, "denoise", QueueKind::Compute, [&](PassBuilder& b) {
            b.storageRead(moments.previous);
            b.storageWrite(moments.current);
        });
        g.compile();
        finishFrame(g, store);
        if (frame == 1) store.reset("taa.color", "camera cut");
    }
    EXPECT_EQ(store.size(), 2u);
    EXPECT_EQ(gpu.liveImages.size(), 2u);
    EXPECT_EQ(gpu.liveBuffers.size(), 2u);
    EXPECT_EQ(store.status("denoise.moments")->resets, 0u);
    EXPECT_FALSE(store.status("denoise.moments")->isImage);
    // Buffer state carries too: last frame's storage write is what this frame waits for.
    EXPECT_EQ(store.previousBuffer("denoise.moments").state.stage, kCS);
    EXPECT_EQ(store.previousBuffer("denoise.moments").state.access, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(GraphHistory, StaleHandleNamesPassAndResource) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    RenderGraph g;
    HistoryImage h = g.history(store, "taa.color", kColor);
    addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) { b.storageWrite(h.current); });  // result dropped
    try {
        addPass(g, "sharpen", QueueKind::Compute, [&](PassBuilder& b) { b.sampled(h.current); });
        FAIL() << "stale history handle accepted";
    } catch (const std::runtime_error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("pass 'sharpen'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("stale handle of 'taa.color[current]'"), std::string::npos) << msg;
    }
}

TEST(GraphHistory, MisuseFailsLoudly) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    RenderGraph g;
    g.history(store, "taa.color", kColor);
    RenderGraph other;
    EXPECT_THROW(other.history(store, "taa.color", kColor), std::runtime_error);  // endFrame() missing
    EXPECT_THROW(other.history(store, "taa.color", BufferDesc{16}), std::runtime_error);  // wrong kind
    EXPECT_THROW(other.history(store, "empty", ImageDesc{}), std::runtime_error);
    EXPECT_THROW(g.commitImportStates(), std::runtime_error);  // before compile()
    HistoryStore noBuffers(HistoryAllocator{gpu.allocator().createImage, gpu.allocator().destroyImage, {}, {}});
    EXPECT_THROW(other.history(noBuffers, "moments", BufferDesc{16}), std::runtime_error);
    EXPECT_FALSE(noBuffers.contains("moments"));
}

TEST(GraphHistory, StoreFreesEverythingThroughTheDeallocator) {
    FakeGpu gpu;
    {
        HistoryStore store(gpu.allocator());
        RenderGraph g;
        g.history(store, "taa.color", kColor);
        g.history(store, "denoise.moments", BufferDesc{256});
    }
    EXPECT_TRUE(gpu.liveImages.empty());
    EXPECT_TRUE(gpu.liveBuffers.empty());
    EXPECT_EQ(gpu.freedImages.size(), 2u);
    EXPECT_EQ(gpu.freedBuffers.size(), 2u);
}

TEST(GraphHistory, TrimFreesOnlyEntriesUnusedLongEnough) {
    FakeGpu gpu;
    HistoryStore store(gpu.allocator());
    auto frame = [&](bool taa, bool moments) {
        RenderGraph g;
        if (taa) taaFrame(g, store);
        if (moments) g.history(store, "denoise.moments", BufferDesc{256});
        g.compile();
        finishFrame(g, store);
    };
    frame(true, true);
    frame(true, true);
    frame(true, false);  // the moments' last request was two frames ago
    store.trim(2);       // not more than 2: kept
    EXPECT_TRUE(store.contains("denoise.moments"));
    frame(true, false);
    store.trim(2);  // 3 frames unused: freed through the deallocator; the used entry stays
    EXPECT_FALSE(store.contains("denoise.moments"));
    EXPECT_TRUE(gpu.liveBuffers.empty());
    EXPECT_EQ(gpu.freedBuffers.size(), 2u);
    EXPECT_TRUE(store.contains("taa.color"));
    EXPECT_EQ(gpu.liveImages.size(), 2u);

    // Switched off (TAA off), trimmed, switched on again: a fresh pair with no valid history.
    frame(false, false);
    frame(false, false);
    store.trim(1);
    EXPECT_FALSE(store.contains("taa.color"));
    EXPECT_TRUE(gpu.liveImages.empty());
    RenderGraph g;
    EXPECT_FALSE(taaFrame(g, store).previousValid);
    EXPECT_EQ(gpu.liveImages.size(), 2u);
}
