#include "common/clear_pass.hpp"

#include "clear_float_comp.h"
#include "clear_uint_comp.h"
#include "common/clear.h"
#include "common/compute_pass.hpp"
#include "common/transfer_batch.hpp"

#include <cstring>

namespace ppr::passes {
namespace {

bool isUnsignedIntegerFormat(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UINT:
        case VK_FORMAT_R8G8_UINT:
        case VK_FORMAT_R8G8B8A8_UINT:
        case VK_FORMAT_R16_UINT:
        case VK_FORMAT_R16G16_UINT:
        case VK_FORMAT_R16G16B16A16_UINT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R32G32_UINT:
        case VK_FORMAT_R32G32B32A32_UINT: return true;
        default: return false;
    }
}

}  // namespace

ImageClear::ImageClear(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::ClearPush);
    float_ = shader::createComputePipeline(ctx, PPR_SPIRV(clear_float_comp), layout, "clear.float");
    uint_ = shader::createComputePipeline(ctx, PPR_SPIRV(clear_uint_comp), layout, "clear.uint");
}

bool ImageClear::computeIsCheaper(const vk::DeviceInfo& device) { return device.type != "cpu"; }

graph::ImageHandle ImageClear::addCompute(graph::RenderGraph& g, const std::string& passName, graph::ImageHandle image,
                                          const VkClearColorValue& value) const {
    const graph::ImageDesc& desc = g.imageDesc(image);
    gpu::ClearPush push{};
    std::memcpy(&push.value, value.uint32, sizeof(push.value));  // the union's bits, whichever member was set
    push.extent = {desc.width, desc.height};
    graph::ImageHandle out;
    ComputePass(g, ctx_, passName, isUnsignedIntegerFormat(desc.format) ? uint_ : float_)
        .storageWrite(image, &out)
        .push(push)
        .dispatch({desc.width, desc.height}, gpu::kClearGroupSize);
    return out;
}

graph::ImageHandle addClearPass(graph::RenderGraph& g, const FrameInputs& in, const std::string& passName, graph::ImageHandle image,
                                const VkClearColorValue& value) {
    TransferBatch batch(in);
    graph::ImageHandle cleared;
    batch.clearImage(image, value, passName, &cleared);
    batch.add(g, passName);
    return cleared;
}

}  // namespace ppr::passes
