#include "techniques/raytraced_technique.hpp"

namespace ppr::app {

bool RaytracedTechnique::prepare() {
    if (!services_.ctx.rayQuery().available) return false;
    if (!pass_) pass_ = std::make_unique<passes::RaytracePass>(services_.ctx, services_.scene);
    if (!structures_) structures_ = std::make_unique<gpu::SceneAccelerationStructures>(services_.ctx, services_.scene, services_.framesInFlight);
    return true;
}

namespace {
struct TlasRebuilt {  // on the frame's blackboard: the reference and the technique share one rebuild
    graph::BufferHandle storage;
};
}  // namespace

passes::RaytraceInputs RaytracedTechnique::inputs(TechniqueFrame& f) const {
    passes::RaytraceInputs rt;
    if (structures_->rebuildsPerFrame()) {
        if (!f.board.find<TlasRebuilt>()) f.board.put(TlasRebuilt{pass_->addTlasRebuild(f.graph, *structures_, services_.scene, f.slot)});
        rt.tlasBuilt = f.board.get<TlasRebuilt>().storage;
    }
    rt.depth = f.gbuffer.depth;
    rt.shadowMap = f.shadowMap;
    rt.reflectors = f.reflectorData();
    rt.tlas = structures_->tlas();
    rt.rasterCoverage = f.settings.raytrace.coverage == RtCoverage::Raster;
    return rt;
}

std::optional<graph::ImageHandle> RaytracedTechnique::addReference(TechniqueFrame& f) {
    if (!prepare()) return std::nullopt;
    return pass_->addScreen(f.graph, f.in, inputs(f), f.gbuffer, f.settings.ppr.normalMap != NormalMap::Off);
}

std::optional<graph::ImageHandle> RaytracedTechnique::addReflection(TechniqueFrame& f) {
    if (!prepare()) return std::nullopt;
    const passes::RaytraceInputs rt = inputs(f);
    // TAA's reflection history reprojects through the virtual point, which needs each pixel's path length.
    const bool taa = f.settings.taa.enabled && f.settings.view.debug == gpu::kDebugNone;
    graph::ImageHandle distance;
    const graph::ImageHandle reflection =
        pass_->addScreen(f.graph, f.in, rt, f.gbuffer, f.settings.ppr.normalMap != NormalMap::Off, taa ? &distance : nullptr);
    if (taa) f.board.put(ReflectionDistance{distance});
    // Glass panes: the atlas layout PPR and the planar reference use this frame.
    FrameServices& s = f.services;
    const std::optional<GlassRegionsBound> bound =
        s.glass.packAndUpload(f.graph, f.slot, f.settings.glass, s.reflectors, s.constants.main().viewProj, f.camera.position, f.in.extent);
    if (!bound) return reflection;
    passes::RaytraceGlass glass;
    glass.regions = bound->buffers.table;
    glass.regionList = bound->buffers.list;
    glass.regionCount = bound->count;
    glass.atlasSize = bound->atlasSize;
    glass.used = bound->used;
    f.board.put(passes::GlassReflection{pass_->addGlass(f.graph, f.in, rt, glass), bound->buffers.table});
    return reflection;
}

}  // namespace ppr::app
