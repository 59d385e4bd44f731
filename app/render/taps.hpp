#pragma once
// The taps callers attach to frames (render/frame_tap.hpp): read-backs of what the trunk publishes,
// the viewer's A/B comparison with the ground truth, and the editor's G-buffer pick.
#include "ab_compare/ab_compare_pass.hpp"
#include "pick/pick_pass.hpp"
#include "render/frame_tap.hpp"

#include <glm/glm.hpp>

namespace ppr::app {

enum class ReadbackSource {
    Final,       // the tonemapped image (RGBA8), after overlays
    Depth,       // the G-buffer depth (D32 floats)
    Reflection,  // the technique's reflection image (RGBA16F), when it has one
    Hierarchy,   // the depth hierarchy's atlas (r32f, hiz/hiz.h), when the frame built one
    GlassAtlas,  // the glass reflection atlas (RGBA16F), when a technique resolved one
    ReflectedPath,  // planar's reflected path lengths (RG32F, planar/planar.h), for compare's error classes
};

// Copies the source into `buffer` at the end of the frame; `*copied` says whether the frame had it.
FrameTap readbackTap(ReadbackSource source, graph::ExternalBuffer* buffer, bool* copied = nullptr);

// The viewer's A/B comparison of the frame's technique with the ground truth (FrameRequest::reference).
enum class AbView { Off, Split, ErrorHeat };

class AbCompareTaps {
public:
    explicit AbCompareTaps(const vk::Context& ctx) : pass_(ctx) {}
    // Split: the technique's reflection left of `split` (a fraction of the width), the reference's right.
    // ErrorHeat: the technique's reflection error over the frame. Nothing for the reference itself, none, or Off.
    void attach(std::vector<FrameTap>& taps, AbView view, float split) const;

private:
    passes::AbComparePass pass_;
};

// The reflector editor's pick: the G-buffer under one pixel (pick/pick.h PickResult) into a buffer.
class PickTap {
public:
    explicit PickTap(const vk::Context& ctx) : pass_(ctx) {}
    FrameTap tap(glm::ivec2 pixel, graph::ExternalBuffer* result) const;

private:
    passes::PickPass pass_;
};

}  // namespace ppr::app
