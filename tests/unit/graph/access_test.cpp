// The access table is the single source of stage/access/layout/usage: spot-check the entries every
// barrier depends on.
#include "graph/access.hpp"
#include "graph/graph.hpp"

#include <gtest/gtest.h>

using namespace ppr::graph;

TEST(GraphAccess, ShaderStageFollowsQueueKind) {
    EXPECT_EQ(accessInfo(Access::StorageWrite, QueueKind::Compute, false).stage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(accessInfo(Access::Sampled, QueueKind::Graphics, false).stage,
              VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(accessInfo(Access::UniformRead, QueueKind::Compute, false).access, VK_ACCESS_2_UNIFORM_READ_BIT);
}

TEST(GraphAccess, LayoutsAndWrites) {
    EXPECT_EQ(accessInfo(Access::Sampled, QueueKind::Compute, false).layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(accessInfo(Access::Sampled, QueueKind::Compute, true).layout, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL);
    EXPECT_EQ(accessInfo(Access::StorageReadWrite, QueueKind::Compute, false).layout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(accessInfo(Access::DepthAttachment, QueueKind::Graphics, true).layout,
              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(accessInfo(Access::Present, QueueKind::Graphics, false).layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    EXPECT_EQ(accessInfo(Access::IndirectArgs, QueueKind::Compute, false).stage, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT);
    EXPECT_EQ(accessInfo(Access::TransferDst, QueueKind::Transfer, false).stage, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
    EXPECT_TRUE(isWrite(Access::StorageWrite));
    EXPECT_TRUE(isWrite(Access::StorageReadWrite));
    EXPECT_TRUE(isWrite(Access::ColorAttachment));
    EXPECT_TRUE(isWrite(Access::TransferDst));
    EXPECT_FALSE(isWrite(Access::DepthAttachmentRead));
    EXPECT_FALSE(isWrite(Access::Sampled));
}

TEST(GraphAccess, UsageFlags) {
    EXPECT_EQ(imageUsageFor(Access::StorageReadWrite), VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT));
    EXPECT_EQ(imageUsageFor(Access::DepthAttachmentRead), VkImageUsageFlags(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT));
    EXPECT_EQ(bufferUsageFor(Access::IndirectArgs), VkBufferUsageFlags(VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT));
    EXPECT_EQ(bufferUsageFor(Access::VertexRead),
              VkBufferUsageFlags(VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT));
    EXPECT_EQ(imageUsageFor(Access::Present), 0u);
    EXPECT_STREQ(accessName(Access::IndirectArgs), "indirectArgs");
    EXPECT_TRUE(isDepthFormat(VK_FORMAT_D32_SFLOAT));
    EXPECT_FALSE(isDepthFormat(VK_FORMAT_R32_UINT));
}
