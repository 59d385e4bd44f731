#pragma once
// The one table that maps purpose-named accesses to Vulkan stage/access/layout/usage.
// Passes only ever say *why* they touch a resource; everything Vulkan-specific is derived here.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace ppr::graph {

enum class QueueKind : uint8_t { Graphics, Compute, Transfer };

enum class Access : uint8_t {
    Sampled,              // texture fetch / sampler read (image)
    StorageRead,          // imageLoad / SSBO read
    StorageWrite,         // imageStore / SSBO write (contents before the pass are not needed)
    StorageReadWrite,     // atomics, read-modify-write
    ColorAttachment,      // render target write (+ blend read)
    DepthAttachment,      // depth test + write
    DepthAttachmentRead,  // depth test only, no write
    IndirectArgs,         // vkCmdDispatchIndirect / vkCmdDrawIndirect argument buffer
    UniformRead,          // uniform buffer
    VertexRead,           // vertex / index buffer
    TransferSrc,          // copy / blit source
    TransferDst,          // copy / blit / clear destination
    Present,              // final state of a swapchain image (only as an import's final access)
    HostRead,             // final state of a read-back buffer (only as an import's final access)
    AccelerationStructureBuild,  // vkCmdBuildAccelerationStructuresKHR: the structure's storage or its scratch
    AccelerationStructureRead,   // ray queries (rayQueryInitializeEXT) against the structure
};

// Stage/access/layout one access needs, for a pass running on the given queue kind.
struct AccessInfo {
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // images only
    bool writes = false;
};

AccessInfo accessInfo(Access access, QueueKind kind, bool isDepthFormat);
VkImageUsageFlags imageUsageFor(Access access);
VkBufferUsageFlags bufferUsageFor(Access access);
const char* accessName(Access access);
bool isWrite(Access access);

}  // namespace ppr::graph
