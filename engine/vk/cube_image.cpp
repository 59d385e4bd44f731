#include "vk/cube_image.hpp"

namespace ppr::vk {

CubeImage createCubeImage(const Context& ctx, uint32_t size, VkFormat format, VkImageUsageFlags usage, const std::string& name) {
    VkImageCreateInfo ici = imageCreateInfo2D({size, size}, format, usage, 1, 6);
    ici.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
    VmaAllocationCreateInfo aci{};
    aci.usage = VMA_MEMORY_USAGE_AUTO;
    CubeImage c;
    c.format = format;
    c.size = size;
    VmaAllocationInfo info{};
    VK_CHECK(vmaCreateImage(ctx.allocator(), &ici, &aci, &c.image, &c.allocation, &info));
    c.bytes = info.size;
    auto view = [&](VkImageViewType type, const std::string& viewName) {
        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = c.image;
        vci.viewType = type;
        vci.format = format;
        vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 6};
        VkImageView v = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(ctx.device(), &vci, nullptr, &v));
        ctx.name(v, VK_OBJECT_TYPE_IMAGE_VIEW, viewName);
        return v;
    };
    c.cubeView = view(VK_IMAGE_VIEW_TYPE_CUBE, name + " cube view");
    c.layersView = view(VK_IMAGE_VIEW_TYPE_2D_ARRAY, name + " layers view");
    ctx.name(c.image, VK_OBJECT_TYPE_IMAGE, name);
    vmaSetAllocationName(ctx.allocator(), c.allocation, name.c_str());
    return c;
}

void destroyCubeImage(const Context& ctx, CubeImage& c) {
    if (c.cubeView) vkDestroyImageView(ctx.device(), c.cubeView, nullptr);
    if (c.layersView) vkDestroyImageView(ctx.device(), c.layersView, nullptr);
    if (c.image) vmaDestroyImage(ctx.allocator(), c.image, c.allocation);
    c = {};
}

}  // namespace ppr::vk
