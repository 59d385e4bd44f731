// The Graphviz dump names every pass and resource version and marks culled passes.
#include "graph/graph.hpp"

#include <gtest/gtest.h>

using namespace ppr::graph;

namespace {
struct NoData {};
}  // namespace

TEST(GraphDot, ContainsPassesVersionsAndCulledMarks) {
    RenderGraph g;
    ExternalImage sc{};
    sc.desc = {16, 16, VK_FORMAT_B8G8R8A8_UNORM, 1};
    ImageHandle out = g.importImage("swapchain", &sc);
    ImageHandle img = g.createImage("lit", {16, 16, VK_FORMAT_R16G16B16A16_SFLOAT, 1});
    ImageHandle junk = g.createImage("junk", {16, 16, VK_FORMAT_R8_UNORM, 1});
    g.addPass<NoData>("lighting", QueueKind::Compute, [&](PassBuilder& b, NoData&) { img = b.storageWrite(img); }, nullptr);
    g.addPass<NoData>("debugView", QueueKind::Compute, [&](PassBuilder& b, NoData&) { b.storageWrite(junk); }, nullptr);
    g.addPass<NoData>(
        "tonemap", QueueKind::Graphics,
        [&](PassBuilder& b, NoData&) {
            b.sampled(img);
            b.colorAttachment(out, LoadOp::DontCare);
        },
        nullptr);
    g.compile();
    const std::string dot = g.toDot();
    EXPECT_EQ(dot.rfind("digraph", 0), 0u);
    for (const char* name : {"lighting", "debugView", "tonemap"}) EXPECT_NE(dot.find(name), std::string::npos) << name;
    EXPECT_NE(dot.find(R"x("debugView\n(culled)")x"), std::string::npos);
    EXPECT_NE(dot.find("style=dashed"), std::string::npos);
    EXPECT_EQ(dot.find("lighting\\n(culled)"), std::string::npos);
    EXPECT_NE(dot.find("\"lit v1\""), std::string::npos);
    EXPECT_NE(dot.find("\"swapchain v1\", style=filled"), std::string::npos);
    EXPECT_NE(dot.find("r1v1 -> p2"), std::string::npos);  // lit v1 read by tonemap
    EXPECT_NE(dot.find("p0 -> r1v1"), std::string::npos);  // written by lighting
}
