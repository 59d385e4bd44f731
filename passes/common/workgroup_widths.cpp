#include "common/workgroup_widths.hpp"

#include <algorithm>
#include <stdexcept>

namespace ppr::passes {

WidthPipelines::WidthPipelines(const vk::Context& ctx, shader::Spirv spirv, shader::PipelineLayoutDesc layout, std::string name,
                               WorkgroupWidths widths, std::vector<uint32_t> more)
    : ctx_(ctx), spirv_(spirv), layout_(std::move(layout)), name_(std::move(name)), widths_(widths), more_(std::move(more)) {
    get(0);
}

uint32_t WidthPipelines::resolve(uint32_t asked) const { return asked == 0 ? widths_.defaultFor(ctx_.info()) : asked; }

const shader::Pipeline& WidthPipelines::get(uint32_t width) const {
    width = resolve(width);
    if (std::find(widths_.offered.begin(), widths_.offered.end(), width) == widths_.offered.end())
        throw std::invalid_argument(name_ + ": " + std::to_string(width) + " invocations per workgroup is not offered");
    auto it = pipelines_.find(width);
    if (it != pipelines_.end()) return it->second;
    std::vector<uint32_t> specialization{width};
    specialization.insert(specialization.end(), more_.begin(), more_.end());
    return pipelines_.emplace(width, shader::createComputePipeline(ctx_, spirv_, layout_, name_, specialization)).first->second;
}

}  // namespace ppr::passes
