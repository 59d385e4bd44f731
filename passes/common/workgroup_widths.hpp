#pragma once
// A compute pipeline whose workgroup width is the shader's specialization constant 0
// (`layout(local_size_x_id = 0)`), where the best width depends on the device: on lavapipe a barrier
// costs in proportion to the invocations it stops, on a GPU wider groups share the work. One
// pipeline per width asked for: the device's default made up front, another when a setting first
// asks for it (never per frame).
#include "shader/pipeline.hpp"

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace ppr::passes {

struct WorkgroupWidths {
    std::span<const uint32_t> offered;  // what the setting may choose
    uint32_t cpu = 0, gpu = 0;          // the default on a CPU device, and on any other
    uint32_t defaultFor(const vk::DeviceInfo& device) const { return device.type == "cpu" ? cpu : gpu; }
    // Every width offered gives each invocation as many of `items` and is at least `least`; both
    // defaults are offered. For the passes' static_asserts.
    constexpr bool valid(uint32_t items, uint32_t least) const {
        bool cpuOffered = false, gpuOffered = false;
        for (uint32_t w : offered) {
            if (w < least || items % w != 0) return false;
            cpuOffered |= w == cpu;
            gpuOffered |= w == gpu;
        }
        return cpuOffered && gpuOffered;
    }
};

class WidthPipelines {
public:
    // `more`: the values of constant_id 1, 2, ... (a variant of the shader), the same for every width.
    WidthPipelines(const vk::Context& ctx, shader::Spirv spirv, shader::PipelineLayoutDesc layout, std::string name,
                   WorkgroupWidths widths, std::vector<uint32_t> more = {});
    // The width `asked` stands for: itself, or for 0 the device's default.
    uint32_t resolve(uint32_t asked) const;
    // The pipeline for `width` invocations per workgroup (0: the device's default); throws for a width not offered.
    const shader::Pipeline& get(uint32_t width) const;

private:
    const vk::Context& ctx_;
    shader::Spirv spirv_;
    shader::PipelineLayoutDesc layout_;
    std::string name_;
    WorkgroupWidths widths_;
    std::vector<uint32_t> more_;
    mutable std::map<uint32_t, shader::Pipeline> pipelines_;
};

}  // namespace ppr::passes
