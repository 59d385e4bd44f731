// The one access table: every Vulkan stage/access/layout/usage the graph uses comes from here, so a
// pass never names a Vulkan flag for synchronization.
#include "graph/access.hpp"

#include "graph/graph.hpp"

namespace ppr::graph {

namespace {

// Graphics passes may sample or load in either shader stage; one mask keeps the table simple and safe.
VkPipelineStageFlags2 shaderStage(QueueKind kind) {
    switch (kind) {
        case QueueKind::Compute: return VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        case QueueKind::Graphics: return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        case QueueKind::Transfer: break;
    }
    // Shader work never runs in a transfer pass; a conservative stage keeps a mistake synchronized.
    return VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
}

constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

AccessInfo accessInfo(Access access, QueueKind kind, bool depth) {
    const VkPipelineStageFlags2 shader = shaderStage(kind);
    switch (access) {
        case Access::Sampled:
            return {shader, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                    depth ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false};
        case Access::StorageRead:
            return {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, false};
        case Access::StorageWrite:
            return {shader, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL, true};
        case Access::StorageReadWrite:
            return {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, true};
        case Access::ColorAttachment:
            return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true};
        case Access::DepthAttachment:
            return {kDepthTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true};
        case Access::DepthAttachmentRead:
            return {kDepthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false};
        case Access::IndirectArgs:
            return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                    VK_IMAGE_LAYOUT_UNDEFINED, false};
        case Access::UniformRead:
            return {shader, VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, false};
        case Access::VertexRead:
            return {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT,
                    VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                    false};
        case Access::TransferSrc:
            return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false};
        case Access::TransferDst:
            return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true};
        case Access::Present:
            // The presentation engine waits on a semaphore, not on a stage: nothing in the queue waits.
            return {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, false};
        case Access::HostRead:
            return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, false};
        case Access::AccelerationStructureBuild:
            // A build reads its scratch and (on update) its source as well as writing its destination.
            return {VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                    VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR | VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                    VK_IMAGE_LAYOUT_UNDEFINED, true};
        case Access::AccelerationStructureRead:
            return {shader, VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR, VK_IMAGE_LAYOUT_UNDEFINED, false};
    }
    return {};
}

VkImageUsageFlags imageUsageFor(Access access) {
    switch (access) {
        case Access::Sampled: return VK_IMAGE_USAGE_SAMPLED_BIT;
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite: return VK_IMAGE_USAGE_STORAGE_BIT;
        case Access::ColorAttachment: return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        case Access::DepthAttachment:
        case Access::DepthAttachmentRead: return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        case Access::TransferSrc: return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        case Access::TransferDst: return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        default: return 0;
    }
}

VkBufferUsageFlags bufferUsageFor(Access access) {
    switch (access) {
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite: return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        case Access::IndirectArgs: return VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
        case Access::UniformRead: return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
        case Access::VertexRead: return VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
        case Access::TransferSrc: return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        case Access::TransferDst: return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        case Access::AccelerationStructureBuild:
        case Access::AccelerationStructureRead: return VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR;
        default: return 0;
    }
}

const char* accessName(Access access) {
    switch (access) {
        case Access::Sampled: return "sampled";
        case Access::StorageRead: return "storageRead";
        case Access::StorageWrite: return "storageWrite";
        case Access::StorageReadWrite: return "storageReadWrite";
        case Access::ColorAttachment: return "colorAttachment";
        case Access::DepthAttachment: return "depthAttachment";
        case Access::DepthAttachmentRead: return "depthAttachmentRead";
        case Access::IndirectArgs: return "indirectArgs";
        case Access::UniformRead: return "uniformRead";
        case Access::VertexRead: return "vertexRead";
        case Access::TransferSrc: return "transferSrc";
        case Access::TransferDst: return "transferDst";
        case Access::Present: return "present";
        case Access::HostRead: return "hostRead";
        case Access::AccelerationStructureBuild: return "accelerationStructureBuild";
        case Access::AccelerationStructureRead: return "accelerationStructureRead";
    }
    return "unknown";
}

bool isWrite(Access access) { return accessInfo(access, QueueKind::Graphics, false).writes; }

bool isDepthFormat(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D16_UNORM_S8_UINT:
        case VK_FORMAT_X8_D24_UNORM_PACK32:
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT: return true;
        default: return false;
    }
}

}  // namespace ppr::graph
