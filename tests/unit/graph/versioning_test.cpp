// Versioned handles: every write returns a new version, stale or premature reads fail loudly, naming
// the pass and the resource.
#include "graph/graph.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

using namespace ppr::graph;

namespace {

struct NoData {};
void addPass(RenderGraph& g, const std::string& name, QueueKind kind, const std::function<void(PassBuilder&)>& setup) {
    g.addPass<NoData>(name, kind, [&](PassBuilder& b, NoData&) { setup(b); }, nullptr);
}

// Runs f, expects a std::runtime_error, and returns its message.
std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected std::runtime_error";
    return {};
}

const ImageDesc kColor{64, 32, VK_FORMAT_R16G16B16A16_SFLOAT, 1};
const ImageDesc kDepth{64, 32, VK_FORMAT_D32_SFLOAT, 1};

}  // namespace

TEST(GraphVersioning, WriteReturnsNextVersion) {
    RenderGraph g;
    ImageHandle img = g.createImage("img", kColor);
    EXPECT_EQ(img.version, 0u);
    ImageHandle v1, v2;
    addPass(g, "a", QueueKind::Compute, [&](PassBuilder& b) { v1 = b.storageWrite(img); });
    addPass(g, "b", QueueKind::Compute, [&](PassBuilder& b) { v2 = b.storageReadWrite(v1); });
    EXPECT_EQ(v1, (ImageHandle{img.id, 1}));
    EXPECT_EQ(v2, (ImageHandle{img.id, 2}));
    ASSERT_EQ(g.passUses(0).size(), 1u);
    EXPECT_EQ(g.passUses(0)[0].versionRead, 0u);  // storageWrite does not need old contents
    EXPECT_EQ(g.passUses(0)[0].versionWritten, 1u);
    EXPECT_EQ(g.passUses(1)[0].versionRead, 1u);  // read-modify-write does
    EXPECT_EQ(g.passUses(1)[0].versionWritten, 2u);
}

TEST(GraphVersioning, ReadsKeepTheVersion) {
    RenderGraph g;
    BufferHandle buf = g.createBuffer("buf", {256});
    BufferHandle w, r;
    addPass(g, "w", QueueKind::Compute, [&](PassBuilder& b) { w = b.storageWrite(buf); });
    addPass(g, "r", QueueKind::Compute, [&](PassBuilder& b) { r = b.storageRead(w); });
    EXPECT_EQ(r, w);
    EXPECT_EQ(g.passUses(1)[0].versionRead, 1u);
    EXPECT_EQ(g.passUses(1)[0].versionWritten, 0u);
}

TEST(GraphVersioning, StaleHandleThrowsNamingPassAndResource) {
    RenderGraph g;
    ImageHandle img = g.createImage("ao", kColor);
    addPass(g, "producer", QueueKind::Compute, [&](PassBuilder& b) { b.storageWrite(img); });
    std::string msg = errorOf([&] {
        addPass(g, "consumer", QueueKind::Compute, [&](PassBuilder& b) { b.sampled(img); });
    });
    EXPECT_EQ(msg, "graph: pass 'consumer' uses stale handle of 'ao' (version 0, latest 1)");
}

TEST(GraphVersioning, ReadingNeverWrittenTransientThrows) {
    RenderGraph g;
    ImageHandle img = g.createImage("hdr", kColor);
    EXPECT_EQ(errorOf([&] { addPass(g, "tonemap", QueueKind::Compute, [&](PassBuilder& b) { b.sampled(img); }); }),
              "graph: pass 'tonemap' reads 'hdr' before any pass wrote it");
    // Load reads the old contents, Clear does not.
    EXPECT_NE(errorOf([&] {
                  addPass(g, "load", QueueKind::Graphics, [&](PassBuilder& b) { b.colorAttachment(img, LoadOp::Load); });
              }).find("before any pass wrote it"),
              std::string::npos);
    EXPECT_NO_THROW(
        addPass(g, "clear", QueueKind::Graphics, [&](PassBuilder& b) { b.colorAttachment(img, LoadOp::Clear); }));
}

TEST(GraphVersioning, ImportsCountAsWritten) {
    RenderGraph g;
    ExternalImage history{};
    history.desc = kColor;
    ImageHandle h = g.importImage("history", &history);
    EXPECT_NO_THROW(addPass(g, "taa", QueueKind::Compute, [&](PassBuilder& b) { b.sampled(h); }));
}

TEST(GraphVersioning, SameResourceTwiceInOnePassThrows) {
    RenderGraph g;
    ImageHandle img = g.createImage("img", kColor);
    addPass(g, "init", QueueKind::Compute, [&](PassBuilder& b) { img = b.storageWrite(img); });
    std::string msg = errorOf([&] {
        addPass(g, "twice", QueueKind::Compute, [&](PassBuilder& b) {
            b.sampled(img);
            b.storageWrite(img);
        });
    });
    EXPECT_EQ(msg, "graph: pass 'twice' declares 'img' twice (sampled and storageWrite)");
}

TEST(GraphVersioning, AttachmentMisuseThrows) {
    RenderGraph g;
    ImageHandle color = g.createImage("color", kColor);
    ImageHandle depth = g.createImage("depth", kDepth);
    ImageHandle small = g.createImage("small", {8, 8, VK_FORMAT_R8G8B8A8_UNORM, 1});
    EXPECT_NE(errorOf([&] {
                  addPass(g, "cs", QueueKind::Compute, [&](PassBuilder& b) { b.colorAttachment(color, LoadOp::Clear); });
              }).find("outside a graphics pass"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  addPass(g, "d", QueueKind::Graphics, [&](PassBuilder& b) { b.depthAttachment(color, LoadOp::Clear); });
              }).find("'color'"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  addPass(g, "mix", QueueKind::Graphics, [&](PassBuilder& b) {
                      b.colorAttachment(color, LoadOp::Clear);
                      b.depthAttachment(depth, LoadOp::Clear);
                      b.colorAttachment(small, LoadOp::Clear);
                  });
              }).find("extent differs"),
              std::string::npos);
}

TEST(GraphVersioning, DuplicateNamesThrow) {
    RenderGraph g;
    g.createImage("img", kColor);
    EXPECT_THROW(g.createBuffer("img", {16}), std::runtime_error);
    addPass(g, "p", QueueKind::Compute, [](PassBuilder& b) { b.sideEffect(); });
    EXPECT_THROW(addPass(g, "p", QueueKind::Compute, [](PassBuilder&) {}), std::runtime_error);
    EXPECT_EQ(g.resourceId("img"), 0u);
    EXPECT_THROW(g.resourceId("nope"), std::runtime_error);
}
