#include "vk/context.hpp"

#include <cstdio>

namespace ppr::vk {

namespace {

std::string mib(VkDeviceSize bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

// Every allocation asks VMA to stay within the heaps' budget (VMA_ALLOCATION_CREATE_WITHIN_BUDGET_BIT),
// so an absurd request (a huge --size, atlas or scene) is refused before the driver is asked, and named
// here with its size and what is left, instead of an out-of-memory abort somewhere inside the driver.
[[noreturn]] void refuseOverBudget(const Context& ctx, const std::string& name, VkDeviceSize bytes) {
    VkPhysicalDeviceMemoryProperties props{};
    vkGetPhysicalDeviceMemoryProperties(ctx.physicalDevice(), &props);
    VmaBudget budgets[VK_MAX_MEMORY_HEAPS]{};
    vmaGetHeapBudgets(ctx.allocator(), budgets);
    VkDeviceSize left = 0, budget = 0;
    for (uint32_t h = 0; h < props.memoryHeapCount; ++h) {
        const VmaBudget& b = budgets[h];
        const VkDeviceSize free = b.budget > b.usage ? b.budget - b.usage : 0;
        if (free >= left) left = free, budget = b.budget;
    }
    throw std::runtime_error("device memory: '" + name + "' needs " + mib(bytes) + ", but at most " + mib(left) + " of the heap's " +
                             mib(budget) + " budget is left");
}

}  // namespace

Buffer createBuffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, const std::string& name) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    VmaAllocationCreateInfo aci{};
    aci.usage = VMA_MEMORY_USAGE_AUTO;
    if (use == MemoryUse::Upload)
        aci.flags = VMA_ALLOCATION_CREATE_HOST_ACCESS_SEQUENTIAL_WRITE_BIT | VMA_ALLOCATION_CREATE_MAPPED_BIT;
    else if (use == MemoryUse::Readback)
        aci.flags = VMA_ALLOCATION_CREATE_HOST_ACCESS_RANDOM_BIT | VMA_ALLOCATION_CREATE_MAPPED_BIT;
    aci.flags |= VMA_ALLOCATION_CREATE_WITHIN_BUDGET_BIT;
    Buffer b;
    b.size = size;
    VmaAllocationInfo info{};
    const VkResult result = vmaCreateBuffer(ctx.allocator(), &bci, &aci, &b.buffer, &b.allocation, &info);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY) refuseOverBudget(ctx, name, size);
    VK_CHECK(result);
    b.mapped = info.pMappedData;
    ctx.name(b.buffer, VK_OBJECT_TYPE_BUFFER, name);
    vmaSetAllocationName(ctx.allocator(), b.allocation, name.c_str());
    return b;
}

void destroyBuffer(const Context& ctx, Buffer& b) {
    if (b.buffer) vmaDestroyBuffer(ctx.allocator(), b.buffer, b.allocation);
    b = {};
}

VkImageAspectFlags aspectFor(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_X8_D24_UNORM_PACK32: return VK_IMAGE_ASPECT_DEPTH_BIT;
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT: return VK_IMAGE_ASPECT_DEPTH_BIT;  // views sample depth only
        default: return VK_IMAGE_ASPECT_COLOR_BIT;
    }
}

VkImageCreateInfo imageCreateInfo2D(VkExtent2D extent, VkFormat format, VkImageUsageFlags usage, uint32_t mipLevels, uint32_t layers) {
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = format;
    ici.extent = {extent.width, extent.height, 1};
    ici.mipLevels = mipLevels;
    ici.arrayLayers = layers;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = usage;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    return ici;
}

Image createImage(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage, uint32_t mipLevels,
                  const std::string& name) {
    const VkImageCreateInfo ici = imageCreateInfo2D(extent, format, usage, mipLevels, 1);
    VmaAllocationCreateInfo aci{};
    aci.usage = VMA_MEMORY_USAGE_AUTO;
    aci.flags = VMA_ALLOCATION_CREATE_WITHIN_BUDGET_BIT;
    Image img;
    img.format = format;
    img.extent = extent;
    img.mipLevels = mipLevels;
    if (const VkResult result = vmaCreateImage(ctx.allocator(), &ici, &aci, &img.image, &img.allocation, nullptr);
        result == VK_ERROR_OUT_OF_DEVICE_MEMORY) {
        VkImage probe = VK_NULL_HANDLE;  // only to learn the size the refused request asked for
        VkMemoryRequirements req{};
        if (vkCreateImage(ctx.device(), &ici, nullptr, &probe) == VK_SUCCESS) {
            vkGetImageMemoryRequirements(ctx.device(), probe, &req);
            vkDestroyImage(ctx.device(), probe, nullptr);
        }
        refuseOverBudget(ctx, name, req.size);
    } else {
        VK_CHECK(result);
    }
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = img.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = format;
    vci.subresourceRange = {aspectFor(format), 0, mipLevels, 0, 1};
    VK_CHECK(vkCreateImageView(ctx.device(), &vci, nullptr, &img.view));
    ctx.name(img.image, VK_OBJECT_TYPE_IMAGE, name);
    ctx.name(img.view, VK_OBJECT_TYPE_IMAGE_VIEW, name + " view");
    vmaSetAllocationName(ctx.allocator(), img.allocation, name.c_str());
    return img;
}

void destroyImage(const Context& ctx, Image& img) {
    if (img.view) vkDestroyImageView(ctx.device(), img.view, nullptr);
    if (img.image) vmaDestroyImage(ctx.allocator(), img.image, img.allocation);
    img = {};
}

}  // namespace ppr::vk
