#pragma once
// Composite: lit scene + the reflection technique's image (Fresnel × reflectance on reflector
// pixels) and the debug views → HDR colour.
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"

#include <optional>

namespace ppr::passes {

struct CompositeReflection {
    graph::ImageHandle image;              // common/reflection.h
    VkBuffer reflectors = VK_NULL_HANDLE;  // ReflectorData[] (reflectance per reflector)
};

class CompositePass {
public:
    explicit CompositePass(const vk::Context& ctx);
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle sceneColor,
                           const std::optional<CompositeReflection>& reflection) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline plain_, withReflection_;
};

}  // namespace ppr::passes
