#include "vk/context.hpp"

namespace ppr::vk {

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
    Buffer b;
    b.size = size;
    VmaAllocationInfo info{};
    VK_CHECK(vmaCreateBuffer(ctx.allocator(), &bci, &aci, &b.buffer, &b.allocation, &info));
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

Image createImage(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage, uint32_t mipLevels,
                  const std::string& name) {
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = format;
    ici.extent = {extent.width, extent.height, 1};
    ici.mipLevels = mipLevels;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = usage;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VmaAllocationCreateInfo aci{};
    aci.usage = VMA_MEMORY_USAGE_AUTO;
    Image img;
    img.format = format;
    img.extent = extent;
    img.mipLevels = mipLevels;
    VK_CHECK(vmaCreateImage(ctx.allocator(), &ici, &aci, &img.image, &img.allocation, nullptr));
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
