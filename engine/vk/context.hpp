#pragma once
// Vulkan instance + device + VMA + debug utils + validation message counting. One object per run.
#include "vk/check.hpp"

#include <vk_mem_alloc.h>
#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ppr::vk {

struct ContextOptions {
    bool validation = false;                     // Khronos validation + synchronization validation
    std::vector<const char*> instanceExtensions;  // e.g. from glfwGetRequiredInstanceExtensions
    bool swapchain = false;                       // enable VK_KHR_swapchain on the device
    bool preferSoftware = false;                  // PPR_DEVICE=cpu: pick lavapipe even if a GPU exists
};

struct DeviceInfo {
    std::string name;
    std::string type;  // "discrete", "integrated", "cpu", ...
    std::string driver;
    uint32_t apiVersion = 0;
    std::string apiVersionString;
    float timestampPeriodNs = 1.0f;
    uint32_t subPixelPrecisionBits = 4;  // how finely the rasterizer snaps vertices (the ray-traced reference's rt_coverage=raster)
    uint32_t timestampValidBits = 0;
    uint32_t subgroupSize = 0;  // lanes per subgroup (on lavapipe its SIMD row: util/driver_defects.hpp)
    // A CPU device: the process keeps the memory it frees rather than return it to the kernel, which
    // the driver's per-frame binning would fault in again (util/process_heap.hpp).
    bool heapKept = false;
};

// Ray queries from compute shaders (the `raytraced` reference): VK_KHR_acceleration_structure,
// VK_KHR_ray_query, VK_KHR_deferred_host_operations and bufferDeviceAddress, enabled together when the
// device has them all. PPR_HIDE_RAY_QUERY=1 makes the context behave as if it had none of them.
struct RayQuerySupport {
    bool available = false;
    std::string missing;  // when unavailable: what the device lacks, e.g. "VK_KHR_ray_query"
    bool hidden = false;  // unavailable because PPR_HIDE_RAY_QUERY is set
    VkDeviceSize scratchAlignment = 1;  // minAccelerationStructureScratchOffsetAlignment
    PFN_vkGetAccelerationStructureBuildSizesKHR getBuildSizes = nullptr;
    PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR cmdBuild = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR getDeviceAddress = nullptr;
};

// Validation messages are counted (and printed) from the debug-utils callback.
struct ValidationCounters {
    std::atomic<uint32_t> errors{0};
    std::atomic<uint32_t> warnings{0};
};

class Context {
public:
    static std::unique_ptr<Context> create(const ContextOptions& options);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    VmaAllocator allocator() const { return allocator_; }
    const DeviceInfo& info() const { return info_; }
    bool validationEnabled() const { return validation_; }
    uint32_t validationErrors() const { return counters_->errors.load(); }
    uint32_t validationWarnings() const { return counters_->warnings.load(); }

    // VK_EXT_debug_utils object name (no-op when the extension is unavailable).
    void setName(VkObjectType type, uint64_t handle, const std::string& name) const;
    template <class T>
    void name(T handle, VkObjectType type, const std::string& n) const {
        setName(type, reinterpret_cast<uint64_t>(handle), n);
    }
    void beginLabel(VkCommandBuffer cmd, const char* label) const;
    PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet() const { return pushDescriptorSet_; }
    void endLabel(VkCommandBuffer cmd) const;
    // Ray queries and acceleration structures (entry points loaded when available).
    const RayQuerySupport& rayQuery() const { return rayQuery_; }
    // "this device lacks VK_KHR_ray_query (llvmpipe ...)" when ray queries are unavailable, else "".
    std::string rayQueryUnavailableReason() const;

    // Synchronous one-off command buffer (uploads at load time only, never per frame).
    void immediateSubmit(const std::function<void(VkCommandBuffer)>& record) const;

private:
    Context() = default;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    VmaAllocator allocator_ = VK_NULL_HANDLE;
    VkCommandPool uploadPool_ = VK_NULL_HANDLE;
    DeviceInfo info_;
    bool validation_ = false;
    bool debugUtils_ = false;
    std::unique_ptr<ValidationCounters> counters_ = std::make_unique<ValidationCounters>();
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel_ = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel_ = nullptr;
    PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet_ = nullptr;
    RayQuerySupport rayQuery_;
};

// One command buffer to the context's queue, optionally waiting on / signalling a semaphore.
void submit(const Context& ctx, VkCommandBuffer cmd, VkFence fence, VkSemaphore wait = VK_NULL_HANDLE,
            VkPipelineStageFlags2 waitStage = VK_PIPELINE_STAGE_2_NONE, VkSemaphore signal = VK_NULL_HANDLE);

// GPU allocations through VMA. Owned objects destroy themselves.
struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VmaAllocation allocation = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // persistently mapped when created host-visible
};
enum class MemoryUse { GpuOnly, Upload, Readback };
// Buffers whose device address is taken (usage SHADER_DEVICE_ADDRESS) need bufferDeviceAddress, which
// the context enables together with ray queries (Context::rayQuery().available).
Buffer createBuffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                    const std::string& name);
void destroyBuffer(const Context& ctx, Buffer& buffer);

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VmaAllocation allocation = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    uint32_t mipLevels = 1;
};
// A 2D image's create info: optimal tiling, one sample, undefined initial layout.
VkImageCreateInfo imageCreateInfo2D(VkExtent2D extent, VkFormat format, VkImageUsageFlags usage, uint32_t mipLevels, uint32_t layers);
Image createImage(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  uint32_t mipLevels, const std::string& name);
void destroyImage(const Context& ctx, Image& image);
VkImageAspectFlags aspectFor(VkFormat format);

}  // namespace ppr::vk
