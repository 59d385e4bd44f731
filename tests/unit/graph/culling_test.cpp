// Ordering and culling: passes run in declaration order, passes nobody consumes are culled (with a
// log line saying why), and culled passes contribute nothing (no barriers, no usage flags).
#include "graph/graph.hpp"

#include <gtest/gtest.h>

#include <functional>

using namespace ppr::graph;

namespace {

struct NoData {};
void addPass(RenderGraph& g, const std::string& name, QueueKind kind, const std::function<void(PassBuilder&)>& setup) {
    g.addPass<NoData>(name, kind, [&](PassBuilder& b, NoData&) { setup(b); }, nullptr);
}

std::vector<std::string> keptPasses(const RenderGraph& g) {
    std::vector<std::string> names;
    for (const CompiledPass& p : g.compiledPasses())
        if (!p.culled) names.push_back(p.name);
    return names;
}

const ImageDesc kColor{64, 32, VK_FORMAT_R16G16B16A16_SFLOAT, 1};

}  // namespace

TEST(GraphCulling, DeclarationOrderWithoutCulledPasses) {
    RenderGraph g;
    ImageHandle a = g.createImage("a", kColor);
    ImageHandle unused = g.createImage("unused", kColor);
    addPass(g, "first", QueueKind::Compute, [&](PassBuilder& b) { a = b.storageWrite(a); });
    addPass(g, "orphan", QueueKind::Compute, [&](PassBuilder& b) { b.storageWrite(unused); });
    addPass(g, "second", QueueKind::Compute, [&](PassBuilder& b) { a = b.storageReadWrite(a); });
    addPass(g, "third", QueueKind::Graphics, [&](PassBuilder& b) {
        b.sampled(a);
        b.sideEffect();
    });
    g.compile();
    ASSERT_EQ(g.compiledPasses().size(), 4u);
    for (uint32_t i = 0; i < 4; ++i) EXPECT_EQ(g.compiledPasses()[i].index, i);
    EXPECT_EQ(keptPasses(g), (std::vector<std::string>{"first", "second", "third"}));
    EXPECT_TRUE(g.compiledPasses()[1].barriers.empty());  // culled passes get no barriers
}

TEST(GraphCulling, UnreadOutputIsCulledAndLogged) {
    RenderGraph g;
    ImageHandle junk = g.createImage("junk", kColor);
    BufferHandle more = g.createBuffer("more", {64});
    addPass(g, "orphan", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageWrite(junk);
        b.storageWrite(more);
    });
    addPass(g, "idle", QueueKind::Compute, [](PassBuilder&) {});
    g.compile();
    EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"orphan", "idle"}));
    EXPECT_EQ(g.cullLog(),
              "graph: culled pass 'orphan' (nothing reads: junk, more)\n"
              "graph: culled pass 'idle' (writes nothing and has no sideEffect())");
}

TEST(GraphCulling, SideEffectKeepsPass) {
    RenderGraph g;
    ImageHandle img = g.createImage("img", kColor);
    addPass(g, "capture", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageWrite(img);
        b.sideEffect();
    });
    g.compile();
    EXPECT_TRUE(g.culledPasses().empty());
    EXPECT_EQ(g.cullLog(), "");
}

TEST(GraphCulling, WritingAnImportKeepsPassAndItsInputs) {
    RenderGraph g;
    ExternalImage swapchain{};
    swapchain.desc = kColor;
    ImageHandle sc = g.importImage("swapchain", &swapchain);
    ImageHandle hdr = g.createImage("hdr", kColor);
    addPass(g, "lighting", QueueKind::Compute, [&](PassBuilder& b) { hdr = b.storageWrite(hdr); });
    addPass(g, "tonemap", QueueKind::Graphics, [&](PassBuilder& b) {
        b.sampled(hdr);
        b.colorAttachment(sc, LoadOp::DontCare);
    });
    g.compile();
    EXPECT_TRUE(g.culledPasses().empty());
}

TEST(GraphCulling, ChainFeedingOnlyACulledPassIsCulled) {
    RenderGraph g;
    ImageHandle x = g.createImage("x", kColor);
    ImageHandle y = g.createImage("y", kColor);
    ImageHandle z = g.createImage("z", kColor);
    ImageHandle out = g.createImage("out", kColor);
    addPass(g, "makeX", QueueKind::Compute, [&](PassBuilder& b) { x = b.storageWrite(x); });
    addPass(g, "makeY", QueueKind::Compute, [&](PassBuilder& b) {
        b.sampled(x);
        y = b.storageWrite(y);
    });
    addPass(g, "makeZ", QueueKind::Compute, [&](PassBuilder& b) {
        b.sampled(y);
        z = b.storageWrite(z);
    });
    addPass(g, "kept", QueueKind::Compute, [&](PassBuilder& b) {
        out = b.storageWrite(out);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"makeX", "makeY", "makeZ"}));
}

TEST(GraphCulling, OverwrittenVersionDoesNotKeepItsProducer) {
    RenderGraph g;
    BufferHandle b0 = g.createBuffer("buf", {64});
    BufferHandle b1, b2;
    addPass(g, "dead", QueueKind::Compute, [&](PassBuilder& b) { b1 = b.storageWrite(b0); });
    addPass(g, "live", QueueKind::Compute, [&](PassBuilder& b) { b2 = b.storageWrite(b1); });  // no read of v1
    addPass(g, "use", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(b2);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"dead"}));
}

TEST(GraphCulling, UsageComesOnlyFromKeptPasses) {
    RenderGraph g;
    ImageHandle img = g.createImage("img", kColor);
    ImageHandle junk = g.createImage("junk", kColor);
    BufferHandle args = g.createBuffer("args", {16});
    addPass(g, "write", QueueKind::Compute, [&](PassBuilder& b) {
        img = b.storageWrite(img);
        args = b.storageWrite(args);
        b.sideEffect();
    });
    addPass(g, "culledReader", QueueKind::Compute, [&](PassBuilder& b) {
        b.sampled(img);
        b.indirectArgs(args);
        b.transferDst(junk);
    });
    g.compile();
    EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"culledReader"}));
    EXPECT_EQ(g.imageUsage(img.id), VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT));
    EXPECT_EQ(g.bufferUsage(args.id), VkBufferUsageFlags(VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
    EXPECT_EQ(g.imageUsage(junk.id), 0u);
}

TEST(GraphCulling, ImportUsageIncludesFinalAccess) {
    RenderGraph g;
    ExternalImage sc{};
    sc.desc = kColor;
    sc.finalAccess = Access::TransferSrc;  // e.g. a capture copies it out afterwards
    ImageHandle h = g.importImage("sc", &sc);
    addPass(g, "draw", QueueKind::Graphics, [&](PassBuilder& b) { b.colorAttachment(h, LoadOp::Clear); });
    g.compile();
    EXPECT_EQ(g.imageUsage(h.id), VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT));
}
