#include "render/renderer.hpp"

#include "taa/taa.h"
#include "techniques/technique_table.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace ppr::app {
namespace {

passes::TaaReflectionInputs taaReflectionInputs(const graph::Blackboard& board, graph::ImageHandle reflection, const passes::GBuffer& gb,
                                                const FrameSettings& settings) {
    passes::TaaReflectionInputs r;
    r.reflection = reflection;
    if (const ReflectionDistance* d = board.find<ReflectionDistance>()) r.distance = d->image;
    r.depth = gb.depth;
    r.normal = gb.normal;
    static_assert(uint32_t(Reproject::Surface) == gpu::kReprojectSurface && uint32_t(Reproject::Candidates) == gpu::kReprojectCandidates &&
                  uint32_t(Reproject::Virtual) == gpu::kReprojectVirtual);
    r.mode = static_cast<uint32_t>(settings.taa.reproject);
    r.average = settings.taa.average;
    r.stillSpread = settings.taa.stillSpread;
    r.motionCap = settings.taa.reflectionCap;
    r.rimKeep = settings.taa.rimKeep;
    r.stillRange = settings.taa.stillRange;
    r.stillKeep = settings.taa.stillKeep;
    r.movingEdge = settings.taa.movingEdge;
    r.threads = settings.taa.threads;
    return r;
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

Renderer::Renderer(const vk::Context& ctx, const scene::Scene& scene) : ctx_(ctx), scene_(scene) {
    samplers_.create(ctx);
    gpuScene_ = std::make_unique<gpu::GpuScene>(ctx, scene, samplers_.linearRepeatAniso, kFramesInFlight);
    shadow_ = std::make_unique<passes::ShadowPass>(ctx, *gpuScene_);
    shadowCache_ = std::make_unique<ShadowMapCache>(ctx, *shadow_, gpuScene_->animated());
    gbuffer_ = std::make_unique<passes::GBufferPass>(ctx, *gpuScene_);
    lighting_ = std::make_unique<passes::LightingPass>(ctx);
    composite_ = std::make_unique<passes::CompositePass>(ctx);
    glassForward_ = std::make_unique<passes::GlassForwardPass>(ctx, *gpuScene_);
    tonemap_ = std::make_unique<passes::TonemapPass>(ctx);
    tonemap_->prepare(kCaptureFormat);
    taa_ = std::make_unique<passes::TaaPass>(ctx);
    tileClassify_ = std::make_unique<passes::TileClassifyPass>(ctx);
    hiz_ = std::make_unique<passes::HizPass>(ctx);
    glassReflect_ = std::make_unique<passes::GlassReflectPass>(ctx);
    reflectors_ = std::make_unique<ReflectorSet>(ctx, scene, kFramesInFlight);
    imageClear_ = std::make_unique<passes::ImageClear>(ctx);
    constants_ = std::make_unique<FrameConstantsBuffer>(ctx, samplers_, *imageClear_, *gpuScene_, kFramesInFlight);
    glass_ = std::make_unique<GlassAtlasFrame>(kFramesInFlight);
    stats_ = std::make_unique<FrameStatsBuffers>(ctx, kFramesInFlight);
    environment_ = std::make_unique<EnvironmentProbe>(ctx, *gpuScene_, *shadow_, *gbuffer_, *lighting_);
    services_.reset(new FrameServices{ctx, *gpuScene_, *gbuffer_, *lighting_, *reflectors_, *constants_, *glass_, *stats_, *tileClassify_,
                                      *hiz_, *glassReflect_, *environment_, kFramesInFlight});
    for (const TechniqueDesc& t : techniqueTable()) modules_.push_back(t.make ? t.make(*services_) : nullptr);
    executor_ = std::make_unique<graph::GraphExecutor>(ctx, kFramesInFlight);
    setReflectors(scene.reflectors);
}

Renderer::~Renderer() {
    vkDeviceWaitIdle(ctx_.device());
    executor_.reset();
    shadowCache_.reset();
    modules_.clear();
    services_.reset();
    environment_.reset();
    stats_.reset();
    glass_.reset();
    constants_.reset();
    imageClear_.reset();
    reflectors_.reset();
    glassReflect_.reset();
    hiz_.reset();
    tileClassify_.reset();
    taa_.reset();
    tonemap_.reset();
    glassForward_.reset();
    composite_.reset();
    lighting_.reset();
    gbuffer_.reset();
    shadow_.reset();
    gpuScene_.reset();
    samplers_.destroy(ctx_);
}

void Renderer::setReflectors(std::vector<scene::Reflector> reflectors) {
    reflectors_->set(std::move(reflectors));
    glass_->reserve(static_cast<uint32_t>(std::min<size_t>(reflectors_->list().size(), gpu::kPprMaxReflectors)));
    // Worst case every reflector is its own visible plane: size the per-frame views once per change.
    constants_->reserveViews(1 + static_cast<uint32_t>(reflectors_->list().size()));
}

Technique* Renderer::module(const std::string& technique) const {
    const TechniqueDesc& desc = techniqueDesc(technique);
    return modules_[static_cast<size_t>(&desc - techniqueTable().data())].get();
}

std::string Renderer::unsupported(const std::string& technique, VkExtent2D extent) const {
    const Technique* t = module(technique);
    return t ? t->unsupported(extent) : std::string();
}

void Renderer::resetTaaHistory(const FrameRequest& req) {
    graph::HistoryStore& history = executor_->history();
    const bool changed = !lastTechnique_.empty() && lastTechnique_ != req.technique;
    lastTechnique_ = req.technique;
    const bool splitChanged = lastTaaSplit_ != req.settings.taa.split;
    lastTaaSplit_ = req.settings.taa.split;
    const bool rangeChanged = lastTaaStillRange_ != req.settings.taa.stillRange;
    lastTaaStillRange_ = req.settings.taa.stillRange;
    // A new shot starts the jitter sequence again: the same shot renders the same frames, whichever
    // shots came before (compare's rows stay comparable frame by frame).
    if (req.cameraCut) taaFrames_ = 0;
    // A resize needs nothing here: the store reallocates and resets a pair whose size changed.
    for (const char* name : passes::TaaPass::kHistoryNames) {
        if (!history.contains(name)) continue;
        if (changed) history.reset(name, "technique change");
        if (splitChanged) history.reset(name, "taa_split change");
        if (rangeChanged) history.reset(name, "taa_still_range change");
        if (req.cameraCut) history.reset(name, "camera cut");
    }
}

void Renderer::runTaps(const FrameRequest& req, TapPoint point, TapContext& ctx) {
    for (const FrameTap& tap : req.taps)
        if (tap.point == point) tap.add(ctx);
}

FrameRecord Renderer::record(VkCommandBuffer cmd, uint32_t slot, const FrameRequest& req) {
    FrameRecord rec;
    Technique* technique = module(req.technique);
    if (technique) {
        rec.warning = technique->unsupported(req.extent);
        if (!rec.warning.empty()) technique = nullptr;
        else rec.warning = technique->warning(*services_);
    }
    const FrameSettings& settings = req.settings;
    // TAA resolves the frame as shown; a debug view is data, not an image to accumulate.
    const bool taa = settings.taa.enabled && settings.view.debug == gpu::kDebugNone;
    resetTaaHistory(req);
    const glm::vec2 jitter = req.jitter ? *req.jitter : taa ? scene::haltonJitter(taaFrames_++) : glm::vec2(0.0f);
    stats_->beginFrame(slot);
    glass_->beginFrame(slot);
    reflectors_->update(slot);
    gpuScene_->pose(slot, req.sceneTime, req.cameraCut);
    constants_->beginFrame(slot, req.camera, req.extent, settings.view, lightViewProjection(scene_, glm::normalize(glm::vec3(-0.45f, -0.8f, -0.4f))),
                           jitter);
    const passes::FrameInputs in = constants_->inputs(*reflectors_);

    graph::RenderGraph g;
    graph::Blackboard board;
    // A still scene's pose never changes; an animated one's is its clock (none: the pose as loaded).
    const ShadowMapKey shadowKey{settings.view.shadowRes, gpuScene_->animated() ? req.sceneTime : std::nullopt};
    const graph::ImageHandle shadowMap = shadowCache_->add(g, in, shadowKey, settings.view.shadowCache);
    const passes::GBuffer gb = gbuffer_->add(g, in);
    const graph::ImageHandle lit = lighting_->add(g, in, gb, shadowMap);
    board.put(gb);
    board.put(LitColor{lit});
    board.put(ShadowMap{shadowMap});
    TechniqueFrame frame{g, board, *services_, settings, in, gb, lit, shadowMap, slot, req.camera};
    std::optional<graph::ImageHandle> taaShown, reflectionHistory;  // taa.reflection's outputs
    if (technique) {
        if (std::optional<graph::ImageHandle> reflection = technique->addReflection(frame)) {
            board.put(TechniqueReflection{*reflection});
            board.put(ShownReflection{*reflection});
            if (taa) {
                const passes::TaaReflectionOutput out = taa_->addReflection(g, in, executor_->history(), taaReflectionInputs(board, *reflection, gb, settings));
                board.put(ShownReflection{out.shown});
                taaShown = out.shown;
                reflectionHistory = out.history;
            }
        }
    }
    std::optional<graph::ImageHandle> reference;
    TapContext taps{g, board, in, req.technique, req.reference, [&]() -> std::optional<graph::ImageHandle> {
                        Technique* truth = module(req.reference);
                        if (!reference && truth) reference = truth->addReference(frame);
                        return reference;
                    }};
    runTaps(req, TapPoint::AfterReflection, taps);

    std::optional<passes::CompositeReflection> blend;
    if (const ShownReflection* shown = board.find<ShownReflection>()) blend = passes::CompositeReflection{shown->image, frame.reflectorData()};
    graph::ImageHandle hdr = composite_->add(g, in, gb, lit, blend);
    if (!gpuScene_->transparentDraws().empty()) {
        const passes::GlassReflection* glass = board.find<passes::GlassReflection>();
        const std::optional<passes::GlassReflection> glassReflection = glass ? std::optional(*glass) : std::nullopt;
        passes::GlassForwardPass::sortBackToFront(*gpuScene_, req.camera.position, glassOrder_);
        hdr = glassForward_->add(g, in, hdr, gb.depth, frame.reflectorData(), glassReflection, &glassOrder_);
        if (glass && settings.view.debug == gpu::kDebugAtlas) hdr = glassReflect_->addAtlasView(g, in, glass->atlas, hdr);
    }
    if (taa) {
        passes::TaaInputs t{hdr, gb.depth, gb.material, std::nullopt};
        t.average = settings.taa.average;
        t.motionCap = settings.taa.motionCap;
        t.stillSpread = settings.taa.stillSpread;
        t.stillRange = settings.taa.stillRange;
        t.movingFilter = settings.taa.movingFilter;
        t.threads = settings.taa.threads;
        const ReflectionDistance* path = board.find<ReflectionDistance>();
        if (path && settings.taa.reproject == Reproject::Virtual) t.reflectedPath = path->image;
        const ShownReflection* shown = board.find<ShownReflection>();
        if (shown && settings.taa.split) {
            t.shownReflection = shown->image;
            if (shown->image == taaShown) t.reflectionHistory = reflectionHistory;  // not A/B's split of it
        }
        hdr = taa_->add(g, in, executor_->history(), t);
    }
    board.put(HdrColor{hdr});
    runTaps(req, TapPoint::AfterGlass, taps);

    const graph::ImageHandle target = req.target ? g.importImage("target", req.target)
                                                 : g.createImage("final", {req.extent.width, req.extent.height, kCaptureFormat, 1});
    board.put(FinalColor{tonemap_->add(g, in, board.get<HdrColor>().image, target)});
    runTaps(req, TapPoint::AfterOutput, taps);

    g.compile();
    executor_->execute(g, cmd, slot);
    rec.cullLog = g.cullLog();
    if (req.dumpGraph) rec.dot = g.toDot();
    return rec;
}

}  // namespace ppr::app
