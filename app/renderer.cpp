#include "renderer.hpp"

#include "common/frame.h"
#include "readback/readback_pass.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstring>

namespace ppr::app {
namespace {

uint32_t debugViewIndex(const std::string& name) {
    if (name == "albedo") return gpu::kDebugAlbedo;
    if (name == "normals") return gpu::kDebugNormals;
    if (name == "roughness") return gpu::kDebugRoughness;
    if (name == "reflectors") return gpu::kDebugReflectors;
    if (name == "depth") return gpu::kDebugDepth;
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

Renderer::Renderer(const vk::Context& ctx, const scene::Scene& scene) : ctx_(ctx), scene_(scene) {
    samplers_.create(ctx);
    gpuScene_ = std::make_unique<gpu::GpuScene>(ctx, scene, samplers_.linearRepeatAniso);
    shadow_ = std::make_unique<passes::ShadowPass>(ctx);
    gbuffer_ = std::make_unique<passes::GBufferPass>(ctx, *gpuScene_);
    lighting_ = std::make_unique<passes::LightingPass>(ctx);
    composite_ = std::make_unique<passes::CompositePass>(ctx);
    tonemap_ = std::make_unique<passes::TonemapPass>(ctx);
    tonemap_->prepare(kCaptureFormat);
    executor_ = std::make_unique<graph::GraphExecutor>(ctx, kFramesInFlight);
    const VkDeviceSize align = 256;  // ≥ minUniformBufferOffsetAlignment on every known device
    frameStride_ = (sizeof(gpu::FrameConstants) + align - 1) / align * align;
    frameConstants_ = vk::createBuffer(ctx, frameStride_ * kFramesInFlight, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload,
                                       "frame constants");
}

Renderer::~Renderer() {
    vkDeviceWaitIdle(ctx_.device());
    executor_.reset();
    vk::destroyBuffer(ctx_, frameConstants_);
    tonemap_.reset();
    composite_.reset();
    lighting_.reset();
    gbuffer_.reset();
    shadow_.reset();
    gpuScene_.reset();
    samplers_.destroy(ctx_);
}

void Renderer::writeFrameConstants(uint32_t slot, const FrameRequest& req) {
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
    f.frameIndex = frameIndex_++;
    f.debugView = debugViewIndex(settings_.get("debug"));
    std::memcpy(static_cast<char*>(frameConstants_.mapped) + slot * frameStride_, &f, sizeof(f));
    vmaFlushAllocation(ctx_.allocator(), frameConstants_.allocation, slot * frameStride_, frameStride_);
}

FrameRecord Renderer::record(VkCommandBuffer cmd, uint32_t slot, const FrameRequest& req) {
    writeFrameConstants(slot, req);
    passes::FrameInputs in;
    in.frameConstants = frameConstants_.buffer;
    in.frameConstantsOffset = slot * frameStride_;
    in.frameConstantsSize = sizeof(gpu::FrameConstants);
    in.samplers = &samplers_;
    in.scene = gpuScene_.get();
    in.extent = req.extent;

    graph::RenderGraph g;
    graph::ImageHandle shadowMap = shadow_->add(g, in, static_cast<uint32_t>(settings_.number("shadowres")));
    passes::GBuffer gb = gbuffer_->add(g, in);
    graph::ImageHandle lit = lighting_->add(g, in, gb, shadowMap);
    graph::ImageHandle hdr = composite_->add(g, in, gb, lit);
    graph::ImageHandle target = req.target ? g.importImage("target", req.target)
                                           : g.createImage("final", {req.extent.width, req.extent.height, kCaptureFormat, 1});
    graph::ImageHandle output = tonemap_->add(g, in, hdr, target);
    if (req.overlay) output = req.overlay(g, output);
    if (req.readback) passes::addReadbackPass(g, "readback", output, g.importBuffer("readback", req.readback));

    g.compile();
    executor_->execute(g, cmd, slot);
    FrameRecord rec;
    rec.cullLog = g.cullLog();
    if (req.dumpGraph) rec.dot = g.toDot();
    return rec;
}

}  // namespace ppr::app
