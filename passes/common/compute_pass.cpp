#include "common/compute_pass.hpp"

#include "shader/layout_check.hpp"

#include <algorithm>
#include <utility>

namespace ppr::passes {

ComputePass& ComputePass::bind(Kind kind, graph::Access access, graph::ImageHandle image, graph::BufferHandle buffer) {
    Binding b{kind, access};
    b.image = image;
    b.buffer = buffer;
    bindings_.push_back(b);
    return *this;
}

ComputePass& ComputePass::uniform(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
    bind(Kind::Uniform, graph::Access::UniformRead, {}, {});
    bindings_.back().rawBuffer = buffer;
    bindings_.back().offset = offset;
    bindings_.back().range = range;
    return *this;
}

ComputePass& ComputePass::hostStorage(VkBuffer buffer) {
    bind(Kind::HostStorage, graph::Access::StorageRead, {}, {});
    bindings_.back().rawBuffer = buffer;
    return *this;
}

ComputePass& ComputePass::sampled(graph::ImageHandle image, VkSampler sampler) {
    bind(Kind::Sampled, graph::Access::Sampled, image, {});
    bindings_.back().sampler = sampler;
    return *this;
}

ComputePass& ComputePass::storageRead(graph::ImageHandle image) { return bind(Kind::StorageImage, graph::Access::StorageRead, image, {}); }

ComputePass& ComputePass::storageWrite(graph::ImageHandle image, graph::ImageHandle* written) {
    bind(Kind::StorageImage, graph::Access::StorageWrite, image, {});
    bindings_.back().writtenImage = written;
    return *this;
}

ComputePass& ComputePass::storageReadWrite(graph::ImageHandle image, graph::ImageHandle* written) {
    bind(Kind::StorageImage, graph::Access::StorageReadWrite, image, {});
    bindings_.back().writtenImage = written;
    return *this;
}

ComputePass& ComputePass::storageRead(graph::BufferHandle buffer) { return bind(Kind::StorageBuffer, graph::Access::StorageRead, {}, buffer); }

ComputePass& ComputePass::storageWrite(graph::BufferHandle buffer, graph::BufferHandle* written) {
    bind(Kind::StorageBuffer, graph::Access::StorageWrite, {}, buffer);
    bindings_.back().writtenBuffer = written;
    return *this;
}

ComputePass& ComputePass::storageReadWrite(graph::BufferHandle buffer, graph::BufferHandle* written) {
    bind(Kind::StorageBuffer, graph::Access::StorageReadWrite, {}, buffer);
    bindings_.back().writtenBuffer = written;
    return *this;
}

void ComputePass::dispatch(VkExtent2D extent, uint32_t groupSize) { add(extent, groupSize, std::nullopt, 0); }

void ComputePass::dispatchIndirect(graph::BufferHandle args, VkDeviceSize offset) { add({}, 0, args, offset); }

VkDescriptorType ComputePass::descriptorType(Kind kind) {
    switch (kind) {
        case Kind::Uniform: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case Kind::Sampled: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case Kind::StorageImage: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case Kind::HostStorage:
        case Kind::StorageBuffer: break;
    }
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

void ComputePass::add(VkExtent2D extent, uint32_t groupSize, std::optional<graph::BufferHandle> indirect, VkDeviceSize indirectOffset) {
    // Checked where the pass is declared, so the error points at the builder calls, not at recording.
    std::vector<VkDescriptorType> given;
    for (const Binding& b : bindings_) given.push_back(descriptorType(b.kind));
    shader::checkBindings(pipeline_.name(), name_, pipeline_.bindingTypes(), given);
    struct Data {
        std::vector<Binding> bindings;  // handles as declared (the versions this pass uses)
        std::optional<graph::BufferHandle> indirect;
    };
    const vk::Context& ctx = ctx_;
    const shader::Pipeline& pipeline = pipeline_;
    std::vector<uint8_t> constants = std::move(pushConstants_);
    graph_.addPass<Data>(
        name_, graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            std::vector<std::pair<graph::ImageHandle, graph::ImageHandle>> sampledOnce;  // declared → returned
            for (Binding binding : bindings_) {
                if (binding.kind == Kind::Sampled) {
                    auto seen = std::find_if(sampledOnce.begin(), sampledOnce.end(), [&](const auto& p) {
                        return p.first.id == binding.image.id && p.first.version == binding.image.version;
                    });
                    if (seen != sampledOnce.end()) binding.image = seen->second;
                    else {
                        graph::ImageHandle declared = b.sampled(binding.image);
                        sampledOnce.emplace_back(binding.image, declared);
                        binding.image = declared;
                    }
                }
                else if (binding.kind == Kind::StorageImage) {
                    graph::ImageHandle h = binding.access == graph::Access::StorageRead    ? b.storageRead(binding.image)
                                           : binding.access == graph::Access::StorageWrite ? b.storageWrite(binding.image)
                                                                                           : b.storageReadWrite(binding.image);
                    if (binding.writtenImage) *binding.writtenImage = h;
                    binding.image = h;
                } else if (binding.kind == Kind::StorageBuffer) {
                    graph::BufferHandle h = binding.access == graph::Access::StorageRead    ? b.storageRead(binding.buffer)
                                            : binding.access == graph::Access::StorageWrite ? b.storageWrite(binding.buffer)
                                                                                            : b.storageReadWrite(binding.buffer);
                    if (binding.writtenBuffer) *binding.writtenBuffer = h;
                    binding.buffer = h;
                }
                binding.writtenImage = nullptr;
                binding.writtenBuffer = nullptr;
                data.bindings.push_back(binding);
            }
            if (indirect) data.indirect = b.indirectArgs(*indirect);
        },
        [&ctx, &pipeline, constants, extent, groupSize, indirectOffset](const Data& data, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            pipeline.bind(cmd);
            shader::PushDescriptors writes(ctx);
            for (const Binding& b : data.bindings) {
                switch (b.kind) {
                    case Kind::Uniform: writes.uniformBuffer(b.rawBuffer, b.offset, b.range); break;
                    case Kind::HostStorage: writes.storageBuffer(b.rawBuffer); break;
                    case Kind::Sampled: writes.sampled(pc.view(b.image), pc.layout(b.image), b.sampler); break;
                    case Kind::StorageImage: writes.storageImage(pc.view(b.image)); break;
                    case Kind::StorageBuffer: writes.storageBuffer(pc.buffer(b.buffer)); break;
                }
            }
            writes.push(cmd, pipeline);
            if (!constants.empty()) pipeline.pushConstants(cmd, constants.data(), static_cast<uint32_t>(constants.size()));
            if (data.indirect) pc.dispatchIndirect(*data.indirect, indirectOffset);
            else shader::dispatchCovering(cmd, extent, groupSize);
        });
    bindings_.clear();
}

}  // namespace ppr::passes
