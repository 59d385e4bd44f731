#include "techniques/ssr_technique.hpp"

namespace ppr::app {

passes::SsrInputs ssrInputs(TechniqueFrame& f, const passes::TileLists& tiles) {
    passes::SsrInputs s;
    s.gbuffer = &f.gbuffer;
    s.sceneColor = f.lit;
    s.reflectors = f.reflectorData();
    s.tiles = &tiles;
    s.params.maxDistance = f.settings.ssr.distance;
    s.params.thickness = f.settings.ssr.thickness;
    s.params.thicknessScale = f.settings.ssr.thicknessScale;
    s.params.maxSteps = f.settings.ssr.steps;
    s.params.hizSkip = f.settings.ssr.hizSkip;
    s.indirect = f.settings.tiles.indirect;
    s.mappedNormals = f.settings.ppr.normalMap != NormalMap::Off;
    s.environment = f.environment();
    return s;
}

std::optional<graph::ImageHandle> SsrTechnique::addReflection(TechniqueFrame& f) {
    // Every reflector id makes a tile planar here: SSR has no reflector budget.
    const passes::TileLists tiles = f.classifyTiles(UINT32_MAX);
    passes::SsrInputs inputs = ssrInputs(f, tiles);
    if (usesHierarchy_) {
        const passes::HizAtlas hiz = f.depthHierarchy();
        inputs.hiz = hiz.image;
        inputs.hizLevels = hiz.levels;
    }
    // TAA's reflection history reprojects through the virtual point, which needs each pixel's path length.
    const bool taa = f.settings.taa.enabled && f.settings.view.debug == gpu::kDebugNone;
    graph::ImageHandle distance;
    const graph::ImageHandle reflection = pass_->addTechnique(f.graph, f.in, inputs, taa ? &distance : nullptr);
    if (taa) f.board.put(ReflectionDistance{distance});
    return reflection;
}

}  // namespace ppr::app
