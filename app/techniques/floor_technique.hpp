#pragma once
// The cost floor of screen-space reflections: reads depth and the lit scene once and writes one value
// per pixel (it draws no reflection; bench's "x floor" column divides by it).
#include "floor/floor_pass.hpp"
#include "frame/technique.hpp"

namespace ppr::app {

class FloorTechnique final : public Technique {
public:
    explicit FloorTechnique(FrameServices& services) : pass_(services.ctx) {}
    std::optional<graph::ImageHandle> addReflection(TechniqueFrame& f) override { return pass_.add(f.graph, f.in, f.gbuffer.depth, f.lit); }

private:
    passes::FloorPass pass_;
};

}  // namespace ppr::app
