#pragma once
// The common case of a compute pass in one expression (DESIGN.md practice 5):
//
//   graph::ImageHandle out;
//   ComputePass(g, ctx, "lighting", pipeline)
//       .uniform(frameBuffer, offset, size)
//       .sampled(gbuffer.depth, sampler)
//       .storageWrite(color, &out)
//       .dispatch(extent, 8);
//
// Each call declares the graph access and the push-descriptor binding, numbered in call order. The
// order must match the shader's `layout(set = 0, binding = N)` lines: dispatch() throws
// std::logic_error naming the pass and the first binding whose type differs (or the missing one).
#include "graph/graph.hpp"
#include "shader/pipeline.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ppr::passes {

class ComputePass {
public:
    ComputePass(graph::RenderGraph& g, const vk::Context& ctx, std::string name, const shader::Pipeline& pipeline)
        : graph_(g), ctx_(ctx), name_(std::move(name)), pipeline_(pipeline) {}

    ComputePass& uniform(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);  // outside the graph
    ComputePass& hostStorage(VkBuffer buffer);  // a host-written storage buffer outside the graph (scene data)
    // The same image may be sampled twice with different samplers (declared to the graph once).
    ComputePass& sampled(graph::ImageHandle image, VkSampler sampler);
    ComputePass& storageRead(graph::ImageHandle image);
    ComputePass& storageWrite(graph::ImageHandle image, graph::ImageHandle* written);
    ComputePass& storageReadWrite(graph::ImageHandle image, graph::ImageHandle* written);
    ComputePass& storageRead(graph::BufferHandle buffer);
    ComputePass& storageWrite(graph::BufferHandle buffer, graph::BufferHandle* written);
    ComputePass& storageReadWrite(graph::BufferHandle buffer, graph::BufferHandle* written);
    template <class T>
    ComputePass& push(const T& constants) {
        pushConstants_.assign(reinterpret_cast<const uint8_t*>(&constants), reinterpret_cast<const uint8_t*>(&constants) + sizeof(T));
        return *this;
    }

    // Adds the pass: workgroups of groupSize² threads covering `extent`, or an indirect dispatch.
    void dispatch(VkExtent2D extent, uint32_t groupSize);
    void dispatchIndirect(graph::BufferHandle args, VkDeviceSize offset = 0);

private:
    enum class Kind { Uniform, HostStorage, Sampled, StorageImage, StorageBuffer };
    struct Binding {
        Kind kind;
        graph::Access access = graph::Access::Sampled;
        graph::ImageHandle image;
        graph::BufferHandle buffer;
        graph::ImageHandle* writtenImage = nullptr;
        graph::BufferHandle* writtenBuffer = nullptr;
        VkBuffer rawBuffer = VK_NULL_HANDLE;
        VkDeviceSize offset = 0, range = 0;
        VkSampler sampler = VK_NULL_HANDLE;
    };
    static VkDescriptorType descriptorType(Kind kind);
    ComputePass& bind(Kind kind, graph::Access access, graph::ImageHandle image, graph::BufferHandle buffer);
    void add(VkExtent2D extent, uint32_t groupSize, std::optional<graph::BufferHandle> indirect, VkDeviceSize indirectOffset);

    graph::RenderGraph& graph_;
    const vk::Context& ctx_;
    std::string name_;
    const shader::Pipeline& pipeline_;
    std::vector<Binding> bindings_;
    std::vector<uint8_t> pushConstants_;
};

}  // namespace ppr::passes
