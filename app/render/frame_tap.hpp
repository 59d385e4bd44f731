#pragma once
// Taps: what a caller attaches to one frame without the renderer knowing it — read-backs, the
// editor's pick, the viewer's A/B comparison and its ImGui overlay. A tap runs at a point of the
// frame, finds the handles it reads on the blackboard and may publish new versions there (A/B's
// split replaces ShownReflection; an overlay replaces FinalColor).
#include "common/frame_inputs.hpp"
#include "frame/frame_resources.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ppr::app {

enum class TapPoint {
    AfterReflection,  // G-buffer, lit colour, shadow map, the technique's reflection (if any)
    AfterGlass,       // + HdrColor: the composited scene with glass, before tonemapping
    AfterOutput,      // + FinalColor: the tonemapped target
};

struct TapContext {
    graph::RenderGraph& graph;
    graph::Blackboard& board;
    const passes::FrameInputs& in;
    const std::string& technique;  // the one this frame renders
    const std::string& referenceName;  // the ground truth reference() renders (FrameRequest::reference)
    // The reference technique's reflection of this frame, added on first call.
    std::function<std::optional<graph::ImageHandle>()> reference;
};

struct FrameTap {
    TapPoint point = TapPoint::AfterOutput;
    std::function<void(TapContext&)> add;
};

}  // namespace ppr::app
