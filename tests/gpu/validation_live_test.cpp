// Guards the guard: the GPU tests assert "zero validation errors", which only means something if the
// layer is really loaded and synchronization validation really on. Provoke one of each and count.
#include "gpu_test_util.hpp"

namespace ppr::test {
namespace {

TEST(Validation, CountsApiErrors) {
    vk::ContextOptions o;
    o.validation = true;
    auto ctx = vk::Context::create(o);
    ASSERT_EQ(ctx->validationErrors(), 0u);
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = 0;  // invalid: VUID-VkBufferCreateInfo-size-00912
    bci.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(ctx->device(), &bci, nullptr, &buffer);
    if (buffer) vkDestroyBuffer(ctx->device(), buffer, nullptr);
    EXPECT_GT(ctx->validationErrors(), 0u);
}

TEST(Validation, SynchronizationValidationCatchesAMissingBarrier) {
    vk::ContextOptions o;
    o.validation = true;
    auto ctx = vk::Context::create(o);
    vk::Buffer a = vk::createBuffer(*ctx, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    vk::MemoryUse::GpuOnly, "hazard a");
    vk::Buffer b = vk::createBuffer(*ctx, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::GpuOnly, "hazard b");
    ctx->immediateSubmit([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, a.buffer, 0, 256, 1u);
        VkBufferCopy region{0, 0, 256};
        vkCmdCopyBuffer(cmd, a.buffer, b.buffer, 1, &region);  // read-after-write with no barrier
    });
    EXPECT_GT(ctx->validationErrors(), 0u) << "synchronization validation is not active";
    vk::destroyBuffer(*ctx, a);
    vk::destroyBuffer(*ctx, b);
}

}  // namespace
}  // namespace ppr::test
