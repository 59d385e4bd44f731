#include "techniques/ppr_technique.hpp"

#include "common/reflected_path.hpp"
#include "hiz/hiz_pass.hpp"
#include "ppr_clear/ppr_clear_pass.hpp"
#include "common/transfer_batch.hpp"
#include "ppr_common/encoding.h"
#include "ppr_reflect/ppr_reflect.h"
#include "ssr_hiz/ssr_hiz_pass.hpp"
#include "techniques/ssr_technique.hpp"
#include "util/driver_defects.hpp"

namespace ppr::app {
namespace {

uint32_t resolveFlags(const PprSettings& s) {  // holes / filter / antibleed
    uint32_t flags = 0;
    if (s.holes != HoleRule::Off) flags |= gpu::kPprHoleFilling;
    if (s.holes == HoleRule::Enclosed) flags |= gpu::kPprHoleEnclosed;
    if (s.filter) flags |= gpu::kPprFiltering;
    if (s.antibleed) flags |= gpu::kPprAntiBleeding;
    return flags;
}

uint32_t reflectFlags(const FrameSettings& s) {  // the screen's reflection pass adds normal maps and the environment
    uint32_t flags = resolveFlags(s.ppr);
    if (s.ppr.normalMap == NormalMap::Approx) flags |= gpu::kPprNormalApprox;
    if (s.ppr.normalMap == NormalMap::Raymarch) flags |= gpu::kPprNormalRaymarch;
    if (s.ppr.normalMap == NormalMap::Raymarch && s.ppr.normalRefine != NormalRefine::Off) flags |= gpu::kPprNormalRefine;
    if (s.ppr.normalMap == NormalMap::Raymarch && s.ppr.normalRefine == NormalRefine::Walk) flags |= gpu::kPprNormalWalk;
    if (s.ppr.contact && s.ppr.holes == HoleRule::Enclosed) flags |= gpu::kPprContactMarch;
    if (s.env.fallback) flags |= gpu::kPprEnvironment;
    if (s.tiles.indirect) flags |= gpu::kPprIndirect;
    return flags;
}

}  // namespace

PprTechnique::PprTechnique(FrameServices& s)
    : project_(s.ctx), reflect_(s.ctx), bounds_(s.ctx), reach_(s.ctx), fallback_(passes::makeSsrHizPass(s.ctx)),
      deviceWarning_(util::lavapipeWidthWarning(s.ctx.info().type, s.ctx.info().name, s.ctx.info().subgroupSize)) {}

std::string PprTechnique::warning(const FrameServices& services) const {
    std::string budget = services.reflectors.budgetWarning();
    if (deviceWarning_.empty()) return budget;
    return budget.empty() ? deviceWarning_ : budget + "; " + deviceWarning_;
}

std::string PprTechnique::unsupported(VkExtent2D extent) const {
    // The intermediate encoding holds offsets up to 4095 px; larger frames render without PPR.
    if (std::max(extent.width, extent.height) <= gpu::kPprMaxExtent) return {};
    return "PPR is limited to " + std::to_string(gpu::kPprMaxExtent) + " px per side (12-bit offsets); rendering without reflections";
}

void PprTechnique::queueGlass(TechniqueFrame& f, passes::TransferBatch& lists, passes::TransferBatch& clears, passes::PprProjectInputs& project,
                              passes::GlassRegionBuffers& regions, passes::GlassReflectInputs& resolve) const {
    const FrameConstantsBuffer& constants = f.services.constants;
    const uint32_t atlasSize = f.services.glass.pack(f.slot, f.settings.glass, f.services.reflectors, constants.main().viewProj,
                                                     f.camera.position, f.in.extent);
    f.services.glass.queueUpload(f.graph, lists, &regions);  // the projection binds the table even without glass
    project.glass = f.services.glass.stats(f.slot).has_value();
    passes::queuePprClear(f.graph, clears, "ppr.glass.atlas", {atlasSize, atlasSize}, "ppr.glass.clear", &project.glassAtlas);
    const std::optional<GlassStats>& glass = f.services.glass.stats(f.slot);
    if (!glass || glass->regions() == 0) return;
    resolve.regionCount = glass->regions();
    resolve.atlasSize = glass->atlasSize;
    resolve.blockCount = f.services.glass.resolveBlocks();
    resolve.flags = resolveFlags(f.settings.ppr);
    // The resolve writes every texel the glass pass reads; the atlas view shows them all.
    if (f.settings.view.debug == gpu::kDebugAtlas) passes::GlassReflectPass::queueClears(f.graph, clears, resolve);
}

std::optional<graph::ImageHandle> PprTechnique::addReflection(TechniqueFrame& f) {
    const PprSettings& s = f.settings.ppr;
    const passes::ReflectorBuffer& buffer = f.services.reflectors.buffer();
    const uint32_t projected = buffer.projected();
    const passes::ReflectorBinding binding{buffer.reflectors(f.slot), buffer.order(f.slot), buffer.planeLeaders(f.slot), projected,
                                           buffer.cullPlaneCount()};
    // The debug views PPR draws over the whole screen are left as they are: no fallback over them.
    const uint32_t debug = f.settings.view.debug;
    const bool pprDebugView = debug == gpu::kDebugIntermediate || debug == gpu::kDebugHoles || debug == gpu::kDebugTiles;
    const bool fallbackMarches = s.fallback != PprFallback::None && !pprDebugView;
    // With culling and indirect dispatch, the projection runs only on the tiles that can be reflected.
    const bool reaches = s.tiles && f.settings.tiles.indirect;

    // The frame's clears and uploads in two transfer passes (common/transfer_batch.hpp): "ppr.lists"
    // first, the buffers (empty lists, zero counters, the glass table), and "ppr.clear" just before
    // the projection, the images it and the glass resolve write (on a CPU device a cleared image
    // is still in the cache then). The inputs below name the cleared versions once each is added.
    passes::TransferBatch lists(f.in), clears(f.in);
    passes::TileClassifyTargets tileTargets;
    passes::TileClassifyPass::queueClears(f.graph, lists, f.services.stats.import(f.graph, f.slot), &tileTargets);
    passes::PprReachInputs reach;
    if (reaches) passes::PprReachPass::queueClears(f.graph, lists, reach);
    passes::PprReflectInputs reflect;
    reflect.debugView = f.settings.view.debug;
    reflect.flags = reflectFlags(f.settings);
    // The holes the fallback marches are normal-mapped pixels (none with normalmap=off): the
    // reflection pass lists their tiles for it.
    const bool marchHoles = s.fallback == PprFallback::SsrHoles && s.normalMap != NormalMap::Off && !pprDebugView;
    reflect.listMappedHoles = marchHoles;
    passes::PprReflectPass::queueClears(f.graph, lists, f.in.extent, reflect);
    passes::PprProjectInputs project;
    passes::queuePprClear(f.graph, clears, "ppr.intermediate", f.in.extent, "ppr.clear", &project.intermediate);
    passes::GlassRegionBuffers regions;
    passes::GlassReflectInputs resolve;
    queueGlass(f, lists, clears, project, regions, resolve);
    lists.add(f.graph, "ppr.lists");

    const passes::TileLists tiles = f.classifyTiles(projected, tileTargets);
    project.depth = f.gbuffer.depth;
    const passes::PprBoundsOutputs bounds = bounds_.add(f.graph, f.in, binding, tiles.stats);
    project.bounds = bounds.bounds;
    project.visible = bounds.visible;
    project.stats = bounds.stats;
    project.tilesX = tiles.tilesX;
    project.tilesY = tiles.tilesY;
    project.cullTiles = s.tiles;
    project.normal = f.gbuffer.normal;
    project.facingOnly = s.facing;
    project.splat = s.splat;
    project.threads = s.projectThreads;
    project.glassRegions = regions.table;
    if (reaches) {
        reach = passes::PprReachInputs{project.depth,  project.bounds, project.visible, project.stats, project.tilesX,
                                       project.tilesY, s.reachThreads,  {},              reach.clearedArgs};
        // It reads every depth texel of each tile for the tile's box; with one invocation per tile it
        // stores the tile's levels of the depth hierarchy the fallback marches from the same reads.
        if (fallbackMarches && reach_.writesHierarchy(s.reachThreads)) reach.hierarchy = passes::HizPass::createAtlas(f.graph, f.in);
        graph::ImageHandle hierarchyTiles;
        project.reach = reach_.add(f.graph, f.in, binding, reach, &hierarchyTiles);
        if (reach.hierarchy) f.board.put(DepthHierarchyTiles{hierarchyTiles});
    }
    clears.add(f.graph, "ppr.clear");
    const passes::PprProjectOutputs scatter = project_.add(f.graph, f.in, binding, project);
    f.services.stats.markWritten(f.slot);
    const std::optional<GlassStats>& glass = f.services.glass.stats(f.slot);
    if (glass && glass->regions() > 0) {
        resolve.atlas = scatter.glassAtlas;
        resolve.sceneColor = f.lit;
        resolve.regions = regions.table;
        resolve.regionList = regions.list;
        resolve.blockStarts = regions.blockStarts;
        f.board.put(passes::GlassReflection{f.services.glassReflect.add(f.graph, f.in, resolve), regions.table});
    }

    reflect.intermediate = scatter.intermediate;
    reflect.sceneColor = f.lit;
    reflect.reflectorIds = f.gbuffer.reflector;
    reflect.depth = f.gbuffer.depth;
    reflect.normal = f.gbuffer.normal;
    reflect.material = f.gbuffer.material;
    reflect.reflectors = binding.reflectors;
    reflect.tileSurvivors = scatter.tileSurvivors;
    reflect.tiles = &tiles;
    reflect.maxReflectorId = projected;
    reflect.environment = f.environment();
    reflect.stats = scatter.stats;
    // TAA's reflection history reprojects through the virtual point, which needs each pixel's path length.
    const bool taa = f.settings.taa.enabled && f.settings.view.debug == gpu::kDebugNone;
    if (taa) reflect.distance = f.graph.createImage("ppr.distance", {f.in.extent.width, f.in.extent.height, passes::kReflectedPathFormat, 1});
    graph::ImageHandle distance;
    std::optional<passes::TileLists> holeTiles;
    graph::ImageHandle reflection = reflect_.add(f.graph, f.in, reflect, &distance, &holeTiles);
    if (fallbackMarches) {
        passes::SsrInputs fallback = ssrInputs(f, tiles);
        const passes::HizAtlas hiz = f.depthHierarchy();
        fallback.hiz = hiz.image;
        fallback.hizLevels = hiz.levels;
        // The fallback's pixels get their path lengths from their SSR hits.
        reflection = fallback_->addFallback(f.graph, f.in, fallback, reflection, "ppr.fallback", marchHoles, taa ? &distance : nullptr,
                                            holeTiles ? &*holeTiles : nullptr);
    }
    if (taa) f.board.put(ReflectionDistance{distance});
    return reflection;
}

}  // namespace ppr::app
