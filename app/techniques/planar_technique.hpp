#pragma once
// The planar ground truth: the scene re-rendered once per visible reflector plane from the mirrored
// eye, resolved where each reflector shows it; glass panes get the same atlas layout as PPR's.
// Reads GlassSettings. Also the A/B reference beside any other technique (addReference).
#include "frame/technique.hpp"
#include "planar/planar_pass.hpp"

#include <vector>

namespace ppr::app {

class PlanarTechnique final : public Technique {
public:
    explicit PlanarTechnique(FrameServices& services) : pass_(services.ctx, services.gbufferPass, services.lightingPass) {}
    std::optional<graph::ImageHandle> addReflection(TechniqueFrame& frame) override;
    std::optional<graph::ImageHandle> addReference(TechniqueFrame& frame) override;

private:
    static passes::PlanarReflectors reflectors(const TechniqueFrame& f);
    passes::PlanarPass pass_;
    std::vector<bool> glassPlaneGroups_;  // plane groups holding a pane with a region (reused per frame)
};

}  // namespace ppr::app
