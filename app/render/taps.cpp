#include "render/taps.hpp"

#include "readback/readback_pass.hpp"

#include <algorithm>

namespace ppr::app {
namespace {

std::optional<graph::ImageHandle> sourceImage(ReadbackSource source, const graph::Blackboard& board) {
    switch (source) {
        case ReadbackSource::Final: return board.get<FinalColor>().image;
        case ReadbackSource::Depth: return board.get<passes::GBuffer>().depth;
        case ReadbackSource::Reflection:
            if (const TechniqueReflection* r = board.find<TechniqueReflection>()) return r->image;
            return std::nullopt;
        case ReadbackSource::Hierarchy:
            if (const DepthHierarchy* h = board.find<DepthHierarchy>()) return h->atlas.image;
            return std::nullopt;
        case ReadbackSource::GlassAtlas:
            if (const passes::GlassReflection* glass = board.find<passes::GlassReflection>()) return glass->atlas;
            return std::nullopt;
        case ReadbackSource::ReflectedPath:
            if (const ReflectedPath* p = board.find<ReflectedPath>()) return p->image;
            return std::nullopt;
    }
    return std::nullopt;
}

const char* passName(ReadbackSource source) {
    switch (source) {
        case ReadbackSource::Final: return "readback";
        case ReadbackSource::Depth: return "readback.depth";
        case ReadbackSource::Reflection: return "readback.reflection";
        case ReadbackSource::Hierarchy: return "readback.hiz";
        case ReadbackSource::GlassAtlas: return "readback.glass";
        case ReadbackSource::ReflectedPath: return "readback.path";
    }
    return "readback";
}

}  // namespace

FrameTap readbackTap(ReadbackSource source, graph::ExternalBuffer* buffer, bool* copied) {
    if (copied) *copied = false;
    return {TapPoint::AfterOutput, [source, buffer, copied](TapContext& t) {
                const std::optional<graph::ImageHandle> image = sourceImage(source, t.board);
                if (!image) return;
                const std::string name = passName(source);
                passes::addReadbackPass(t.graph, name, *image, t.graph.importBuffer(name + " buffer", buffer));
                if (copied) *copied = true;
            }};
}

void AbCompareTaps::attach(std::vector<FrameTap>& taps, AbView view, float split) const {
    if (view == AbView::Off) return;
    auto reference = [](TapContext& t) -> std::optional<graph::ImageHandle> {
        if (t.technique == t.referenceName || !t.board.has<TechniqueReflection>()) return std::nullopt;
        return t.reference();
    };
    if (view == AbView::Split) {
        taps.push_back({TapPoint::AfterReflection, [this, reference, split](TapContext& t) {
                            const std::optional<graph::ImageHandle> ref = reference(t);
                            if (!ref) return;
                            const float x = std::clamp(split, 0.0f, 1.0f) * float(t.in.extent.width);
                            t.board.put(ShownReflection{pass_.split(t.graph, t.in, t.board.get<TechniqueReflection>().image, *ref, x)});
                        }});
        return;
    }
    // The reference is rendered before the composite, as with the split, and drawn over after the glass.
    taps.push_back({TapPoint::AfterReflection, [reference](TapContext& t) { reference(t); }});
    taps.push_back({TapPoint::AfterGlass, [this, reference](TapContext& t) {
                        const std::optional<graph::ImageHandle> ref = reference(t);
                        if (!ref) return;
                        const graph::ImageHandle hdr = t.board.get<HdrColor>().image;
                        t.board.put(HdrColor{pass_.heat(t.graph, t.in, t.board.get<TechniqueReflection>().image, *ref, hdr)});
                    }});
}

FrameTap PickTap::tap(glm::ivec2 pixel, graph::ExternalBuffer* result) const {
    return {TapPoint::AfterReflection, [this, pixel, result](TapContext& t) {
                pass_.add(t.graph, t.in, t.board.get<passes::GBuffer>(), pixel, t.graph.importBuffer("pick", result));
            }};
}

}  // namespace ppr::app
