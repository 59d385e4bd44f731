#include "techniques/planar_technique.hpp"

#include "frame/frame_resources.hpp"

namespace ppr::app {

passes::PlanarReflectors PlanarTechnique::reflectors(const TechniqueFrame& f) {
    return {f.reflectorData(), f.services.reflectors.buffer().count()};
}

std::optional<graph::ImageHandle> PlanarTechnique::addReference(TechniqueFrame& f) {
    const std::vector<passes::PlanarView>& views = f.services.constants.mirroredViews(f.services.reflectors);
    return pass_.add(f.graph, f.in, f.gbuffer, f.shadowMap, views, reflectors(f)).reflection;
}

std::optional<graph::ImageHandle> PlanarTechnique::addReflection(TechniqueFrame& f) {
    FrameServices& s = f.services;
    const std::vector<passes::PlanarView>& views = s.constants.mirroredViews(s.reflectors);
    const std::optional<GlassRegionsBound> bound =
        s.glass.packAndUpload(f.graph, f.slot, f.settings.glass, s.reflectors, s.constants.main().viewProj, f.camera.position, f.in.extent);
    if (!bound) {
        const passes::PlanarOutputs out = pass_.add(f.graph, f.in, f.gbuffer, f.shadowMap, views, reflectors(f));
        f.board.put(ReflectedPath{out.path});
        f.board.put(ReflectionDistance{out.path});
        return out.reflection;
    }
    passes::PlanarGlass glass;
    glass.regions = bound->buffers.table;
    glass.regionList = bound->buffers.list;
    glass.regionCount = bound->count;
    glass.atlasSize = bound->atlasSize;
    glass.used = bound->used;
    const scene::ReflectorGroups& groups = s.reflectors.buffer().groups();
    glassPlaneGroups_.assign(groups.planeGroupCount, false);
    for (const scene::GlassRegion& r : s.glass.stats(f.slot)->layout) glassPlaneGroups_[groups.planeGroup[r.reflectorIndex]] = true;
    glass.planeGroups = &glassPlaneGroups_;
    const passes::PlanarOutputs out = pass_.add(f.graph, f.in, f.gbuffer, f.shadowMap, views, reflectors(f), &glass);
    f.board.put(passes::GlassReflection{out.glass, bound->buffers.table});
    f.board.put(ReflectedPath{out.path});
    f.board.put(ReflectionDistance{out.path});
    return out.reflection;
}

}  // namespace ppr::app
