// Exact barrier lists for small graphs, as plain data: the planner must emit exactly the barriers a
// careful human would write (no more, no fewer).
#include "graph/graph.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <ostream>

namespace ppr::graph {
// Readable failure output for barrier comparisons.
void PrintTo(const PlannedBarrier& b, std::ostream* os) {
    *os << std::hex << "{res " << b.resource << (b.isImage ? " image" : " buffer") << " src 0x" << b.srcStage << "/0x"
        << b.srcAccess << " dst 0x" << b.dstStage << "/0x" << b.dstAccess << std::dec << " layout " << b.oldLayout
        << "->" << b.newLayout << "}";
}
}  // namespace ppr::graph

using namespace ppr::graph;

namespace {

struct NoData {};
void addPass(RenderGraph& g, const std::string& name, QueueKind kind, const std::function<void(PassBuilder&)>& setup) {
    g.addPass<NoData>(name, kind, [&](PassBuilder& b, NoData&) { setup(b); }, nullptr);
}

PlannedBarrier barrier(uint32_t resource, bool isImage, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                       VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                       VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
                       VkImageLayout newLayout = VK_IMAGE_LAYOUT_UNDEFINED) {
    return {resource, isImage, srcStage, srcAccess, dstStage, dstAccess, oldLayout, newLayout};
}

using Barriers = std::vector<PlannedBarrier>;
const Barriers& barriersOf(const RenderGraph& g, uint32_t pass) { return g.compiledPasses()[pass].barriers; }

constexpr VkPipelineStageFlags2 kCS = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kGfxShader = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kAll = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
constexpr VkPipelineStageFlags2 kColorOut = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkPipelineStageFlags2 kXfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
constexpr VkAccessFlags2 kStoreW = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
constexpr VkAccessFlags2 kStoreR = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
constexpr VkAccessFlags2 kMemW = VK_ACCESS_2_MEMORY_WRITE_BIT;
constexpr VkAccessFlags2 kColorRW = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;

const ImageDesc kColor{64, 32, VK_FORMAT_R16G16B16A16_SFLOAT, 1};

}  // namespace

// (a) compute writes indirect args, a later compute pass dispatches indirectly from them.
TEST(GraphBarriers, StorageWriteThenIndirectArgs) {
    RenderGraph g;
    BufferHandle args = g.createBuffer("args", {16});
    addPass(g, "classify", QueueKind::Compute, [&](PassBuilder& b) { args = b.storageWrite(args); });
    addPass(g, "reflect", QueueKind::Compute, [&](PassBuilder& b) {
        b.indirectArgs(args);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0), (Barriers{barrier(args.id, false, kAll, kMemW, kCS, kStoreW)}));
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(args.id, false, kCS, kStoreW, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                                                  VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT)}));
    EXPECT_TRUE(g.finalBarriers().empty());
}

// (b) compute storage image sampled by a graphics pass: layout and stages change together.
TEST(GraphBarriers, StorageImageThenSampledInGraphics) {
    RenderGraph g;
    ImageHandle ao = g.createImage("ao", kColor);
    addPass(g, "ao", QueueKind::Compute, [&](PassBuilder& b) { ao = b.storageWrite(ao); });
    addPass(g, "shade", QueueKind::Graphics, [&](PassBuilder& b) {
        b.sampled(ao);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0),
              (Barriers{barrier(ao.id, true, kAll, kMemW, kCS, kStoreW, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL)}));
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(ao.id, true, kCS, kStoreW, kGfxShader, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                                  VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)}));
}

// (c) readers of one version: one barrier per newly needed (stage, access), never one per reader.
TEST(GraphBarriers, SameStageReadersShareOneBarrier) {
    RenderGraph g;
    BufferHandle buf = g.createBuffer("tiles", {1024});
    addPass(g, "write", QueueKind::Compute, [&](PassBuilder& b) { buf = b.storageWrite(buf); });
    addPass(g, "readA", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    addPass(g, "readB", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(buf.id, false, kCS, kStoreW, kCS, kStoreR)}));
    EXPECT_TRUE(barriersOf(g, 2).empty());
}

TEST(GraphBarriers, ReadersInTwoStagesGetTwoBarriers) {
    RenderGraph g;
    BufferHandle buf = g.createBuffer("tiles", {1024});
    addPass(g, "write", QueueKind::Compute, [&](PassBuilder& b) { buf = b.storageWrite(buf); });
    addPass(g, "readCompute", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    addPass(g, "readGraphics", QueueKind::Graphics, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    addPass(g, "readComputeAgain", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(buf.id, false, kCS, kStoreW, kCS, kStoreR)}));
    EXPECT_EQ(barriersOf(g, 2), (Barriers{barrier(buf.id, false, kCS, kStoreW, kGfxShader, kStoreR)}));
    EXPECT_TRUE(barriersOf(g, 3).empty());
}

// (d) write after read: the writer must wait for the readers (execution dependency).
TEST(GraphBarriers, WriteAfterReadIsAnExecutionBarrier) {
    RenderGraph g;
    ExternalBuffer ext{};
    ext.desc = {256};
    BufferHandle buf = g.importBuffer("constants", &ext);  // valid contents, no pending write
    addPass(g, "read", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    addPass(g, "upload", QueueKind::Transfer, [&](PassBuilder& b) { b.transferDst(buf); });
    g.compile();
    EXPECT_TRUE(barriersOf(g, 0).empty());  // nothing to wait for
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(buf.id, false, kCS, VK_ACCESS_2_NONE, kXfer,
                                                  VK_ACCESS_2_TRANSFER_WRITE_BIT)}));
}

TEST(GraphBarriers, WriteAfterWriteAndReadWaitsForBoth) {
    RenderGraph g;
    BufferHandle buf = g.createBuffer("counts", {64});
    addPass(g, "clear", QueueKind::Transfer, [&](PassBuilder& b) { buf = b.transferDst(buf); });
    addPass(g, "read", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(buf);
        b.sideEffect();
    });
    addPass(g, "accumulate", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageReadWrite(buf);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 2), (Barriers{barrier(buf.id, false, kXfer | kCS, VK_ACCESS_2_TRANSFER_WRITE_BIT, kCS,
                                                  kStoreR | kStoreW)}));
}

// An animated scene's TLAS: last frame's ray queries read it, this frame rebuilds it and this
// frame's ray queries read the new one. The build waits for the old readers (write after read) and
// the readers for the build, at the acceleration-structure stages and accesses.
TEST(GraphBarriers, AccelerationStructureRebuildBetweenRayQueries) {
    constexpr VkPipelineStageFlags2 kBuild = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;
    constexpr VkAccessFlags2 kAsRead = VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    constexpr VkAccessFlags2 kAsWrite = VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    RenderGraph g;
    ExternalBuffer storage{};
    storage.desc = {4096};
    storage.state = {VK_IMAGE_LAYOUT_UNDEFINED, kCS, kAsRead};  // left by last frame's ray queries
    BufferHandle tlas = g.importBuffer("tlas", &storage);
    addPass(g, "build", QueueKind::Compute, [&](PassBuilder& b) { tlas = b.accelerationStructureBuild(tlas); });
    addPass(g, "trace", QueueKind::Compute, [&](PassBuilder& b) {
        b.accelerationStructureRead(tlas);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0), (Barriers{barrier(tlas.id, false, kCS, VK_ACCESS_2_NONE, kBuild, kAsRead | kAsWrite)}));
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(tlas.id, false, kBuild, kAsWrite, kCS, kAsRead)}));
    EXPECT_EQ(bufferUsageFor(Access::AccelerationStructureBuild), VkBufferUsageFlags(VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR));
}

// (e) render into the swapchain, copy it to a read-back buffer, then present.
TEST(GraphBarriers, ColorThenTransferSrcThenPresent) {
    RenderGraph g;
    ExternalImage sc{};
    sc.desc = {64, 32, VK_FORMAT_B8G8R8A8_UNORM, 1};
    sc.state = {VK_IMAGE_LAYOUT_UNDEFINED, kColorOut, VK_ACCESS_2_NONE};  // acquire semaphore waits here
    sc.finalAccess = Access::Present;
    ExternalBuffer readback{};
    readback.desc = {64 * 32 * 4};
    readback.finalAccess = Access::HostRead;
    ImageHandle img = g.importImage("swapchain", &sc);
    BufferHandle rb = g.importBuffer("readback", &readback);
    addPass(g, "draw", QueueKind::Graphics, [&](PassBuilder& b) { img = b.colorAttachment(img, LoadOp::Clear); });
    addPass(g, "capture", QueueKind::Transfer, [&](PassBuilder& b) {
        b.transferSrc(img);
        b.transferDst(rb);
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0), (Barriers{barrier(img.id, true, kColorOut, VK_ACCESS_2_NONE, kColorOut, kColorRW,
                                                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)}));
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(img.id, true, kColorOut, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, kXfer,
                                                  VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)}));
    EXPECT_EQ(g.finalBarriers(),
              (Barriers{barrier(img.id, true, kXfer, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT,
                                VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR),
                        barrier(rb.id, false, kXfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                VK_ACCESS_2_HOST_READ_BIT)}));
    // compile() plans only; the executor writes the new state back after recording.
    EXPECT_EQ(sc.state.layout, VK_IMAGE_LAYOUT_UNDEFINED);
    EXPECT_EQ(sc.state.stage, kColorOut);
    EXPECT_EQ(readback.state.stage, VK_PIPELINE_STAGE_2_NONE);
}

// (f) a transient's first use waits for whatever used its pooled memory last, from UNDEFINED.
TEST(GraphBarriers, TransientFirstUseStartsFromUndefined) {
    RenderGraph g;
    ImageHandle hdr = g.createImage("hdr", kColor);
    addPass(g, "lighting", QueueKind::Graphics, [&](PassBuilder& b) {
        b.colorAttachment(hdr, LoadOp::Clear);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0), (Barriers{barrier(hdr.id, true, kAll, kMemW, kColorOut, kColorRW,
                                                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)}));
}

// The first *kept* use gets the first-use barrier, even when a culled pass declared the resource earlier.
TEST(GraphBarriers, FirstUseIgnoresCulledPasses) {
    RenderGraph g;
    BufferHandle buf = g.createBuffer("buf", {64});
    addPass(g, "culled", QueueKind::Compute, [&](PassBuilder& b) { buf = b.storageWrite(buf); });
    addPass(g, "kept", QueueKind::Compute, [&](PassBuilder& b) {
        buf = b.storageWrite(buf);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"culled"}));
    EXPECT_EQ(barriersOf(g, 1), (Barriers{barrier(buf.id, false, kAll, kMemW, kCS, kStoreW)}));
}

// Depth: written, then tested read-only and sampled in the same read-only layout (no second transition).
TEST(GraphBarriers, DepthReadOnlyThenSampledKeepsLayout) {
    RenderGraph g;
    const ImageDesc depthDesc{64, 32, VK_FORMAT_D32_SFLOAT, 1};
    ImageHandle depth = g.createImage("depth", depthDesc);
    ImageHandle color = g.createImage("color", kColor);
    constexpr VkPipelineStageFlags2 kTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    addPass(g, "gbuffer", QueueKind::Graphics, [&](PassBuilder& b) { depth = b.depthAttachment(depth, LoadOp::Clear); });
    addPass(g, "glass", QueueKind::Graphics, [&](PassBuilder& b) {
        b.depthAttachmentRead(depth);
        color = b.colorAttachment(color, LoadOp::Clear);
    });
    addPass(g, "ssr", QueueKind::Graphics, [&](PassBuilder& b) {
        b.sampled(depth);
        b.sampled(color);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0),
              (Barriers{barrier(depth.id, true, kAll, kMemW, kTests,
                                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL)}));
    ASSERT_EQ(barriersOf(g, 1).size(), 2u);
    EXPECT_EQ(barriersOf(g, 1)[0],
              barrier(depth.id, true, kTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kTests,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL));
    ASSERT_EQ(barriersOf(g, 2).size(), 2u);
    EXPECT_EQ(barriersOf(g, 2)[0], barrier(depth.id, true, kTests, VK_ACCESS_2_NONE, kGfxShader,
                                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                                           VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL));
}

// An import whose previous frame left a pending write gets a barrier from that write.
TEST(GraphBarriers, ImportStartsFromItsState) {
    RenderGraph g;
    ExternalImage history{};
    history.desc = kColor;
    history.state = {VK_IMAGE_LAYOUT_GENERAL, kCS, kStoreW};
    ImageHandle h = g.importImage("history", &history);
    addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) {
        b.storageRead(h);
        b.sideEffect();
    });
    g.compile();
    EXPECT_EQ(barriersOf(g, 0), (Barriers{barrier(h.id, true, kCS, kStoreW, kCS, kStoreR, VK_IMAGE_LAYOUT_GENERAL,
                                                  VK_IMAGE_LAYOUT_GENERAL)}));
}
