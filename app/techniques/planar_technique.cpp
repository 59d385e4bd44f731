#include "techniques/planar_technique.hpp"

namespace ppr::app {

std::optional<graph::ImageHandle> PlanarTechnique::addReference(TechniqueFrame& f) {
    const std::vector<passes::PlanarView>& views = f.services.constants.mirroredViews(f.services.reflectors);
    return pass_.add(f.graph, f.in, f.gbuffer, f.shadowMap, views, f.reflectorData());
}

std::optional<graph::ImageHandle> PlanarTechnique::addReflection(TechniqueFrame& f) {
    FrameServices& s = f.services;
    const std::vector<passes::PlanarView>& views = s.constants.mirroredViews(s.reflectors);
    s.glass.pack(f.slot, f.settings.glass, s.reflectors, s.constants.main().viewProj, f.camera.position, f.in.extent);
    const std::optional<GlassStats>& stats = s.glass.stats(f.slot);
    if (!stats || stats->regions() == 0) return pass_.add(f.graph, f.in, f.gbuffer, f.shadowMap, views, f.reflectorData());
    const passes::GlassRegionBuffers regions = s.glass.upload(f.graph);
    passes::PlanarGlass glass;
    glass.regions = regions.table;
    glass.regionList = regions.list;
    glass.regionCount = stats->regions();
    glass.atlasSize = stats->atlasSize;
    glass.usedHeight = stats->usedHeight();
    const scene::ReflectorGroups& groups = s.reflectors.buffer().groups();
    glassPlaneGroups_.assign(groups.planeGroupCount, false);
    for (const scene::GlassRegion& r : stats->layout) glassPlaneGroups_[groups.planeGroup[r.reflectorIndex]] = true;
    glass.planeGroups = &glassPlaneGroups_;
    graph::ImageHandle glassAtlas;
    const graph::ImageHandle reflection = pass_.add(f.graph, f.in, f.gbuffer, f.shadowMap, views, f.reflectorData(), &glass, &glassAtlas);
    f.board.put(passes::GlassReflection{glassAtlas, regions.table});
    return reflection;
}

}  // namespace ppr::app
