#include "renderer.hpp"

#include "common/frame.h"
#include "ppr_clear/ppr_clear_pass.hpp"
#include "ppr_common/encoding.h"
#include "ppr_reflect/ppr_reflect.h"
#include "readback/readback_pass.hpp"
#include "scene/mirror.hpp"
#include "ssr_brute/ssr_brute_pass.hpp"
#include "ssr_hiz/ssr_hiz_pass.hpp"
#include "ssr_linear/ssr_linear_pass.hpp"
#include "ssr_lowq/ssr_lowq_pass.hpp"
#include "techniques.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace ppr::app {
namespace {

uint32_t debugViewIndex(const std::string& name) {
    if (name == "albedo") return gpu::kDebugAlbedo;
    if (name == "normals") return gpu::kDebugNormals;
    if (name == "roughness") return gpu::kDebugRoughness;
    if (name == "reflectors") return gpu::kDebugReflectors;
    if (name == "depth") return gpu::kDebugDepth;
    if (name == "intermediate") return gpu::kDebugIntermediate;
    if (name == "holes") return gpu::kDebugHoles;
    if (name == "tiles") return gpu::kDebugTiles;
    if (name == "atlas") return gpu::kDebugAtlas;
    return gpu::kDebugNone;
}

// Orthographic light projection fitted around the scene's bounding sphere, reverse-Z (near = 1).
glm::mat4 lightViewProjection(const scene::Scene& s, const glm::vec3& lightDir) {
    glm::vec3 center = (s.boundsMin + s.boundsMax) * 0.5f;
    float radius = std::max(glm::length(s.boundsMax - s.boundsMin) * 0.5f, 1.0f);
    glm::vec3 up = std::abs(lightDir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::mat4 view = glm::lookAt(center - lightDir * radius * 2.0f, center, up);
    glm::mat4 ortho = glm::orthoRH_ZO(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f);
    glm::mat4 reverse(1.0f);
    reverse[2][2] = -1.0f;
    reverse[3][2] = 1.0f;
    return reverse * ortho * view;
}

}  // namespace

uint32_t GlassStats::usedHeight() const {
    uint32_t rows = 0;
    for (const scene::GlassRegion& r : layout) rows = std::max(rows, static_cast<uint32_t>(r.atlasOrigin.y + r.atlasSize.y));
    return rows;
}

std::string GlassStats::overflowMessage() const {
    if (!overflowed()) return {};
    char scaleText[32];
    std::snprintf(scaleText, sizeof scaleText, "%.3g", scale);
    const std::string side = std::to_string(atlasSize);
    return "glass atlas " + side + "x" + side + " overflowed: " + std::to_string(scaled) + " of " + std::to_string(visible) +
           " visible glass panels' reflections scaled to " + scaleText + ", " + std::to_string(dropped) +
           " dropped (the farthest first); raise --set glass_atlas";
}

Renderer::Renderer(const vk::Context& ctx, const scene::Scene& scene) : ctx_(ctx), scene_(scene) {
    samplers_.create(ctx);
    gpuScene_ = std::make_unique<gpu::GpuScene>(ctx, scene, samplers_.linearRepeatAniso);
    shadow_ = std::make_unique<passes::ShadowPass>(ctx);
    gbuffer_ = std::make_unique<passes::GBufferPass>(ctx, *gpuScene_);
    lighting_ = std::make_unique<passes::LightingPass>(ctx);
    composite_ = std::make_unique<passes::CompositePass>(ctx);
    tonemap_ = std::make_unique<passes::TonemapPass>(ctx);
    tonemap_->prepare(kCaptureFormat);
    pprProject_ = std::make_unique<passes::PprProjectPass>(ctx);
    pprReflect_ = std::make_unique<passes::PprReflectPass>(ctx);
    pprBounds_ = std::make_unique<passes::PprBoundsPass>(ctx);
    tileClassify_ = std::make_unique<passes::TileClassifyPass>(ctx);
    ssrBrute_ = passes::makeSsrBrutePass(ctx);
    ssrLowq_ = passes::makeSsrLowqPass(ctx);
    ssrHiz_ = passes::makeSsrHizPass(ctx);
    ssrLinear_ = passes::makeSsrLinearPass(ctx);
    hiz_ = std::make_unique<passes::HizPass>(ctx);
    floor_ = std::make_unique<passes::FloorPass>(ctx);
    glass_ = std::make_unique<passes::GlassForwardPass>(ctx, *gpuScene_);
    ab_ = std::make_unique<passes::AbComparePass>(ctx);
    pick_ = std::make_unique<passes::PickPass>(ctx);
    glassReflect_ = std::make_unique<passes::GlassReflectPass>(ctx);
    for (uint32_t slot = 0; slot < kFramesInFlight; ++slot) {
        stats_[slot] = vk::createBuffer(ctx, sizeof(gpu::PprFrameStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback,
                                        "ppr stats[" + std::to_string(slot) + "]");
        statsImport_[slot].buffer = stats_[slot].buffer;
        statsImport_[slot].desc = {sizeof(gpu::PprFrameStats)};
        statsImport_[slot].finalAccess = graph::Access::HostRead;
    }
    planar_ = std::make_unique<passes::PlanarPass>(ctx, *gbuffer_, *lighting_);
    reflectorBuffer_ = std::make_unique<passes::ReflectorBuffer>(ctx, kFramesInFlight);
    surfaces_ = std::make_unique<passes::SurfaceBindingBuffer>(ctx, kFramesInFlight, static_cast<uint32_t>(scene.draws.size()));
    executor_ = std::make_unique<graph::GraphExecutor>(ctx, kFramesInFlight);
    const VkDeviceSize align = 256;  // ≥ minUniformBufferOffsetAlignment on every known device
    frameStride_ = (sizeof(gpu::FrameConstants) + align - 1) / align * align;
    setReflectors(scene.reflectors);
}

Renderer::~Renderer() {
    vkDeviceWaitIdle(ctx_.device());
    executor_.reset();
    vk::destroyBuffer(ctx_, frameConstants_);
    for (vk::Buffer& b : stats_) vk::destroyBuffer(ctx_, b);
    tileClassify_.reset();
    ssrBrute_.reset();
    ssrLowq_.reset();
    ssrHiz_.reset();
    ssrLinear_.reset();
    hiz_.reset();
    floor_.reset();
    glass_.reset();
    ab_.reset();
    pick_.reset();
    glassReflect_.reset();
    pprBounds_.reset();
    reflectorBuffer_.reset();
    surfaces_.reset();
    planar_.reset();
    pprReflect_.reset();
    pprProject_.reset();
    tonemap_.reset();
    composite_.reset();
    lighting_.reset();
    gbuffer_.reset();
    shadow_.reset();
    gpuScene_.reset();
    samplers_.destroy(ctx_);
}

void Renderer::setTechnique(const std::string& technique) {
    if (!isTechnique(technique)) throw std::runtime_error("unknown technique '" + technique + "'");
    technique_ = technique;
}

void Renderer::setReflectors(std::vector<scene::Reflector> reflectors) {
    reflectorList_ = std::move(reflectors);
    ++reflectorVersion_;
    reflectorWarning_.clear();
    if (reflectorList_.size() > gpu::kPprMaxReflectors) {
        const size_t extra = reflectorList_.size() - gpu::kPprMaxReflectors;
        reflectorWarning_ = std::to_string(reflectorList_.size()) + " reflectors exceed PPR's budget of " +
                            std::to_string(gpu::kPprMaxReflectors) + ": the last " + std::to_string(extra) + " (from '" +
                            reflectorList_[gpu::kPprMaxReflectors].name + "' on) get no PPR reflection";
    }
    // Surfaces follow the list by name (and geometry); reflectors no mesh belongs to are found per pixel.
    const std::vector<int> binding = scene::bindDraws(scene_, reflectorList_);
    std::vector<bool> bound(reflectorList_.size(), false);
    for (int r : binding)
        if (r >= 0) bound[size_t(r)] = true;
    std::vector<uint32_t> loose;
    for (size_t i = 0; i < std::min<size_t>(reflectorList_.size(), gpu::kPprMaxReflectors); ++i)
        if (!bound[i] && reflectorList_[i].kind == scene::ReflectorKind::Opaque) loose.push_back(static_cast<uint32_t>(i));
    surfaces_->set(binding, loose, reflectorVersion_);
    glassIndices_.clear();
    const size_t projected = std::min<size_t>(reflectorList_.size(), gpu::kPprMaxReflectors);
    for (size_t i = 0; i < projected; ++i)
        if (reflectorList_[i].kind == scene::ReflectorKind::Glass) glassIndices_.push_back(static_cast<uint32_t>(i));
    glassRegions_.reserve(static_cast<uint32_t>(projected));
    // Worst case every reflector is its own visible plane: size the per-frame views once per change.
    ensureViewCapacity(1 + static_cast<uint32_t>(reflectorList_.size()));
}

void Renderer::ensureViewCapacity(uint32_t views) {
    if (views <= viewCapacity_) return;
    vkDeviceWaitIdle(ctx_.device());  // frames in flight read the old buffer; a reflector change is rare
    vk::destroyBuffer(ctx_, frameConstants_);
    frameConstants_ = vk::createBuffer(ctx_, frameStride_ * views * kFramesInFlight, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                       vk::MemoryUse::Upload, "frame constants");
    viewCapacity_ = views;
}

passes::FrameInputs Renderer::frameInputs(uint32_t slot, uint32_t view, VkExtent2D extent) const {
    passes::FrameInputs in;
    in.frameConstants = frameConstants_.buffer;
    in.frameConstantsOffset = (VkDeviceSize(slot) * viewCapacity_ + view) * frameStride_;
    in.frameConstantsSize = sizeof(gpu::FrameConstants);
    in.samplers = &samplers_;
    in.scene = gpuScene_.get();
    in.extent = extent;
    in.drawReflectors = surfaces_->drawReflectors(slot);
    in.reflectors = reflectorBuffer_->reflectors(slot);
    in.looseReflectors = surfaces_->loose(slot);
    in.looseCount = surfaces_->looseCount();
    return in;
}

gpu::FrameConstants Renderer::mainConstants(const FrameRequest& req) const {
    gpu::FrameConstants f{};
    const float aspect = static_cast<float>(req.extent.width) / static_cast<float>(req.extent.height);
    f.view = scene::viewMatrix(req.camera);
    f.proj = scene::projectionMatrix(req.camera.fovYDeg, aspect, scene::kNearPlane);
    f.viewProj = f.proj * f.view;
    f.invViewProj = glm::inverse(f.viewProj);
    const glm::vec3 lightDir = glm::normalize(glm::vec3(-0.45f, -0.8f, -0.4f));
    f.lightViewProj = lightViewProjection(scene_, lightDir);
    f.cameraPos = glm::vec4(req.camera.position, scene::kNearPlane);
    const float shadowRes = static_cast<float>(settings_.number("shadowres"));
    f.lightDir = glm::vec4(lightDir, 1.0f / shadowRes);
    f.lightColor = glm::vec4(3.2f, 3.0f, 2.7f, static_cast<float>(settings_.number("exposure")));
    f.skyColor = glm::vec4(0.50f, 0.62f, 0.85f, 0.9f);
    f.groundColor = glm::vec4(0.22f, 0.20f, 0.18f, 0.0f);
    f.screenSize = glm::vec2(req.extent.width, req.extent.height);
    f.invScreenSize = 1.0f / f.screenSize;
    f.frameIndex = frameIndex_;
    f.debugView = debugViewIndex(settings_.get("debug"));
    return f;
}

Renderer::Views Renderer::writeFrameConstants(uint32_t slot, const FrameRequest& req, bool mirroredViews) {
    Views views;
    const gpu::FrameConstants main = mainConstants(req);
    frameViewProj_ = main.viewProj;
    ++frameIndex_;
    auto write = [&](uint32_t view, const gpu::FrameConstants& f) {
        const VkDeviceSize offset = (VkDeviceSize(slot) * viewCapacity_ + view) * frameStride_;
        std::memcpy(static_cast<char*>(frameConstants_.mapped) + offset, &f, sizeof(f));
    };
    write(0, main);
    if (mirroredViews) {
        // One mirrored view per plane group with a visible reflector, in group order.
        const scene::ReflectorGroups& groups = reflectorBuffer_->groups();
        std::vector<int> representative(groups.planeGroupCount, -1);
        for (size_t i = 0; i < reflectorList_.size(); ++i)
            if (scene::reflectorMaybeVisible(reflectorList_[i], main.viewProj, req.camera.position) &&
                representative[groups.planeGroup[i]] < 0)
                representative[groups.planeGroup[i]] = static_cast<int>(i);
        for (uint32_t group = 0; group < groups.planeGroupCount; ++group) {
            if (representative[group] < 0) continue;
            const scene::MirrorView mv = scene::mirrorView(main.view, main.proj, req.camera.position, reflectorList_[representative[group]]);
            gpu::FrameConstants f = main;
            f.view = mv.view;
            f.proj = mv.proj;
            f.viewProj = mv.proj * mv.view;
            f.invViewProj = glm::inverse(f.viewProj);
            f.cameraPos = glm::vec4(mv.eye, main.cameraPos.w);
            f.debugView = gpu::kDebugNone;
            f.mirrored = 1;
            const uint32_t view = 1 + static_cast<uint32_t>(views.planar.size());
            write(view, f);
            views.planar.push_back({group, frameInputs(slot, view, req.extent)});
        }
    }
    vmaFlushAllocation(ctx_.allocator(), frameConstants_.allocation, VkDeviceSize(slot) * viewCapacity_ * frameStride_,
                       VkDeviceSize(viewCapacity_) * frameStride_);
    return views;
}

uint32_t Renderer::pprResolveFlags() const {
    uint32_t flags = 0;
    if (settings_.get("holes") == "1") flags |= gpu::kPprHoleFilling;
    if (settings_.get("filter") == "1") flags |= gpu::kPprFiltering;
    if (settings_.get("antibleed") == "1") flags |= gpu::kPprAntiBleeding;
    return flags;
}

uint32_t Renderer::prepareGlass(uint32_t slot, const FrameRequest& req) {
    glassStats_[slot].reset();
    scene::GlassAtlasLayout layout;
    const bool glass = settings_.get("glass") == "1" && !glassIndices_.empty();
    const uint32_t setting = static_cast<uint32_t>(settings_.number("glass_atlas"));
    if (glass)
        layout = scene::packGlassAtlas(reflectorList_, glassIndices_, frameViewProj_, req.camera.position, scene::kNearPlane,
                                       {req.extent.width, req.extent.height}, setting);
    glassRegions_.fill(layout);
    const uint32_t atlasSize = layout.regions.empty() ? 1u : setting;  // bound but unused without a region
    if (glass) {
        GlassStats stats;
        stats.atlasSize = setting;
        stats.visible = layout.visible;
        stats.scaled = layout.scaled;
        stats.dropped = layout.dropped;
        stats.scale = layout.scale;
        stats.layout = std::move(layout.regions);
        glassStats_[slot] = std::move(stats);
    }
    return atlasSize;
}

void Renderer::addGlassAtlas(graph::RenderGraph& g, uint32_t slot, const FrameRequest& req, passes::PprProjectInputs& project) {
    const uint32_t atlasSize = prepareGlass(slot, req);
    glassRegionBuffers_ = glassRegions_.add(g);  // the projection binds the table even without glass
    project.glass = glassStats_[slot].has_value();
    project.glassAtlas = passes::addPprClearPass(g, "ppr.glass.atlas", {atlasSize, atlasSize}, "ppr.glass.clear");
    project.glassRegions = glassRegionBuffers_.table;
}

passes::HizAtlas Renderer::addHiz(graph::RenderGraph& g, const passes::FrameInputs& in, const passes::GBuffer& gb, const FrameRequest& req,
                                  FrameRecord& rec) {
    const passes::HizAtlas hiz = hiz_->add(g, in, gb.depth);
    if (req.hizReadback) {
        passes::addReadbackPass(g, "readback.hiz", hiz.image, g.importBuffer("hiz readback", req.hizReadback));
        rec.hizCopied = true;
    }
    return hiz;
}

const passes::SsrTracePass* Renderer::ssrPass(const std::string& technique) const {
    if (technique == "ssr-brute") return ssrBrute_.get();
    if (technique == "ssr-lowq") return ssrLowq_.get();
    if (technique == "ssr-hiz") return ssrHiz_.get();
    if (technique == "ssr-linear") return ssrLinear_.get();
    return nullptr;
}

passes::SsrInputs Renderer::ssrInputs(const passes::GBuffer& gb, graph::ImageHandle lit, uint32_t slot, const passes::TileLists& tiles) const {
    passes::SsrInputs s;
    s.gbuffer = &gb;
    s.sceneColor = lit;
    s.reflectors = reflectorBuffer_->reflectors(slot);
    s.tiles = &tiles;
    s.params.maxDistance = static_cast<float>(settings_.number("ssr_distance"));
    s.params.thickness = static_cast<float>(settings_.number("ssr_thickness"));
    s.params.thicknessScale = static_cast<float>(settings_.number("ssr_thickness_scale"));
    s.params.maxSteps = static_cast<uint32_t>(settings_.number("ssr_steps"));
    s.indirect = settings_.get("indirect") == "1";
    return s;
}

std::optional<graph::ImageHandle> Renderer::addReflection(graph::RenderGraph& g, const std::string& technique, uint32_t slot,
                                                          const passes::FrameInputs& in, const passes::GBuffer& gb, graph::ImageHandle lit,
                                                          graph::ImageHandle shadowMap, const Views& views, const FrameRequest& req,
                                                          FrameRecord& rec) {
    auto stats = [&] { return g.importBuffer("ppr.stats", &statsImport_[slot]); };
    if (technique == "ppr") {
        const uint32_t projected = reflectorBuffer_->projected();
        const passes::ReflectorBinding binding{reflectorBuffer_->reflectors(slot), reflectorBuffer_->order(slot),
                                               reflectorBuffer_->planeLeaders(slot), projected, reflectorBuffer_->cullPlaneCount()};
        const passes::TileLists tiles = tileClassify_->add(g, in, gb, stats(), projected);
        passes::PprProjectInputs project;
        project.depth = gb.depth;
        project.intermediate = passes::addPprClearPass(g, "ppr.intermediate", in.extent);
        project.bounds = pprBounds_->add(g, in, binding.reflectors, projected);
        project.stats = tiles.stats;
        project.tilesX = tiles.tilesX;
        project.tilesY = tiles.tilesY;
        project.cullTiles = settings_.get("tiles") == "1";
        addGlassAtlas(g, slot, req, project);
        const passes::PprProjectOutputs scatter = pprProject_->add(g, in, binding, project);
        statsWritten_[slot] = true;
        if (glassStats_[slot] && glassStats_[slot]->regions() > 0) {
            passes::GlassReflectInputs glass;
            glass.atlas = scatter.glassAtlas;
            glass.sceneColor = lit;
            glass.regions = glassRegionBuffers_.table;
            glass.regionList = glassRegionBuffers_.list;
            glass.regionCount = glassStats_[slot]->regions();
            glass.atlasSize = glassStats_[slot]->atlasSize;
            glass.usedHeight = glassStats_[slot]->usedHeight();
            glass.flags = pprResolveFlags();
            glassReflection_ = passes::GlassReflection{glassReflect_->add(g, in, glass), glassRegionBuffers_.table};
        }

        passes::PprReflectInputs reflect;
        reflect.intermediate = scatter.intermediate;
        reflect.sceneColor = lit;
        reflect.reflectorIds = gb.reflector;
        reflect.tileSurvivors = scatter.tileSurvivors;
        reflect.tiles = &tiles;
        reflect.debugView = debugViewIndex(settings_.get("debug"));
        reflect.maxReflectorId = projected;
        reflect.flags = pprResolveFlags();
        if (settings_.get("indirect") == "1") reflect.flags |= gpu::kPprIndirect;
        graph::ImageHandle reflection = pprReflect_->add(g, in, reflect);
        // The debug views PPR draws over the whole screen are left as they are.
        const bool pprDebugView = reflect.debugView == gpu::kDebugIntermediate || reflect.debugView == gpu::kDebugHoles ||
                                  reflect.debugView == gpu::kDebugTiles;
        if (settings_.get("fallback") == "ssr" && !pprDebugView) {
            passes::SsrInputs fallback = ssrInputs(gb, lit, slot, tiles);
            const passes::HizAtlas hiz = addHiz(g, in, gb, req, rec);
            fallback.hiz = hiz.image;
            fallback.hizLevels = hiz.levels;
            reflection = ssrHiz_->addFallback(g, in, fallback, reflection, "ppr.fallback");
        }
        return reflection;
    }
    if (const passes::SsrTracePass* ssr = ssrPass(technique)) {
        // Every reflector id makes a tile planar here: SSR has no reflector budget.
        const passes::TileLists tiles = tileClassify_->add(g, in, gb, stats(), UINT32_MAX);
        passes::SsrInputs inputs = ssrInputs(gb, lit, slot, tiles);
        if (technique == "ssr-hiz") {
            const passes::HizAtlas hiz = addHiz(g, in, gb, req, rec);
            inputs.hiz = hiz.image;
            inputs.hizLevels = hiz.levels;
        }
        return ssr->addTechnique(g, in, inputs);
    }
    if (technique == "floor") return floor_->add(g, in, gb.depth, lit);
    if (technique == "planar") {
        prepareGlass(slot, req);
        if (!glassStats_[slot] || glassStats_[slot]->regions() == 0)
            return planar_->add(g, in, gb, shadowMap, views.planar, reflectorBuffer_->reflectors(slot));
        glassRegionBuffers_ = glassRegions_.add(g);
        passes::PlanarGlass glass;
        glass.regions = glassRegionBuffers_.table;
        glass.regionList = glassRegionBuffers_.list;
        glass.regionCount = glassStats_[slot]->regions();
        glass.atlasSize = glassStats_[slot]->atlasSize;
        glass.usedHeight = glassStats_[slot]->usedHeight();
        glassPlaneGroups_.assign(reflectorBuffer_->groups().planeGroupCount, false);
        for (const scene::GlassRegion& r : glassStats_[slot]->layout) glassPlaneGroups_[reflectorBuffer_->groups().planeGroup[r.reflectorIndex]] = true;
        glass.planeGroups = &glassPlaneGroups_;
        graph::ImageHandle glassAtlas;
        graph::ImageHandle reflection = planar_->add(g, in, gb, shadowMap, views.planar, reflectorBuffer_->reflectors(slot), &glass, &glassAtlas);
        glassReflection_ = passes::GlassReflection{glassAtlas, glassRegionBuffers_.table};
        return reflection;
    }
    return std::nullopt;
}

std::optional<gpu::PprFrameStats> Renderer::frameStats(uint32_t slot) const {
    if (!statsWritten_[slot]) return std::nullopt;
    vmaInvalidateAllocation(ctx_.allocator(), stats_[slot].allocation, 0, VK_WHOLE_SIZE);
    gpu::PprFrameStats s;
    std::memcpy(&s, stats_[slot].mapped, sizeof(s));
    return s;
}

FrameRecord Renderer::record(VkCommandBuffer cmd, uint32_t slot, const FrameRequest& req) {
    FrameRecord rec;
    statsWritten_[slot] = false;
    glassStats_[slot].reset();
    glassReflection_.reset();
    std::string technique = technique_;
    if (technique == "ppr" && std::max(req.extent.width, req.extent.height) > gpu::kPprMaxExtent) {
        // The intermediate encoding holds offsets up to 4095 px; larger frames render without PPR.
        rec.warning = "PPR is limited to " + std::to_string(gpu::kPprMaxExtent) + " px per side (12-bit offsets); rendering without reflections";
        technique = "none";
    } else if (technique == "ppr" && !reflectorWarning_.empty()) {
        rec.warning = reflectorWarning_;
    }
    reflectorBuffer_->update(slot, reflectorList_, reflectorVersion_);
    surfaces_->update(slot);
    const bool ab = req.ab != AbView::Off && technique != "planar" && technique != "none";
    const Views views = writeFrameConstants(slot, req, technique == "planar" || ab);
    const passes::FrameInputs in = frameInputs(slot, 0, req.extent);

    graph::RenderGraph g;
    graph::ImageHandle shadowMap = shadow_->add(g, in, static_cast<uint32_t>(settings_.number("shadowres")));
    passes::GBuffer gb = gbuffer_->add(g, in);
    graph::ImageHandle lit = lighting_->add(g, in, gb, shadowMap);
    if (req.pickPixel && req.pickResult) pick_->add(g, in, gb, *req.pickPixel, g.importBuffer("pick", req.pickResult));
    std::optional<graph::ImageHandle> reflection = addReflection(g, technique, slot, in, gb, lit, shadowMap, views, req, rec);
    std::optional<graph::ImageHandle> reference;  // A/B: the planar ground truth beside the technique
    if (ab && reflection) reference = planar_->add(g, in, gb, shadowMap, views.planar, reflectorBuffer_->reflectors(slot));
    std::optional<passes::CompositeReflection> blend;
    if (reflection) {
        graph::ImageHandle shown = *reflection;
        if (reference && req.ab == AbView::Split)
            shown = ab_->split(g, in, *reflection, *reference, std::clamp(req.abSplit, 0.0f, 1.0f) * float(req.extent.width));
        blend = passes::CompositeReflection{shown, reflectorBuffer_->reflectors(slot)};
    }
    graph::ImageHandle hdr = composite_->add(g, in, gb, lit, blend);
    if (!gpuScene_->transparentDraws().empty()) {
        passes::GlassForwardPass::sortBackToFront(*gpuScene_, req.camera.position, glassOrder_);
        hdr = glass_->add(g, in, hdr, gb.depth, reflectorBuffer_->reflectors(slot), glassReflection_, &glassOrder_);
        if (glassReflection_ && debugViewIndex(settings_.get("debug")) == gpu::kDebugAtlas)
            hdr = glassReflect_->addAtlasView(g, in, glassReflection_->atlas, hdr);
    }
    if (reference && req.ab == AbView::ErrorHeat) hdr = ab_->heat(g, in, *reflection, *reference, hdr);
    if (req.glassReadback && glassReflection_) {
        passes::addReadbackPass(g, "readback.glass", glassReflection_->atlas, g.importBuffer("glass readback", req.glassReadback));
        rec.glassCopied = true;
    }
    graph::ImageHandle target = req.target ? g.importImage("target", req.target)
                                           : g.createImage("final", {req.extent.width, req.extent.height, kCaptureFormat, 1});
    graph::ImageHandle output = tonemap_->add(g, in, hdr, target);
    if (req.overlay) output = req.overlay(g, output);
    if (req.readback) passes::addReadbackPass(g, "readback", output, g.importBuffer("readback", req.readback));
    if (req.depthReadback) passes::addReadbackPass(g, "readback.depth", gb.depth, g.importBuffer("depth readback", req.depthReadback));
    if (req.reflectionReadback && reflection) {
        passes::addReadbackPass(g, "readback.reflection", *reflection, g.importBuffer("reflection readback", req.reflectionReadback));
        rec.reflectionCopied = true;
    }

    g.compile();
    executor_->execute(g, cmd, slot);
    rec.cullLog = g.cullLog();
    if (req.dumpGraph) rec.dot = g.toDot();
    return rec;
}

}  // namespace ppr::app
